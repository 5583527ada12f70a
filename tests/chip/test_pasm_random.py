"""Random PASM programs against spinsim 0.99 ``-p``: every instruction's cycle, value and flags.

``tests/data/chip/pasm_random/sample.json.gz`` holds 40 programs made by
tests/chip/tools/pasm_random.py (random ALU instructions with conditions,
effects and special registers; forward jumps, loops, calls; hub reads and
writes; WAITCNT, WAITPEQ/WAITPNE, WAITVID; locks; self-modifying operands),
OpenSpin's images of them and what spinsim did: each instruction of the PASM
cog, the pins, the end cycle and the hub RAM.  The tool compares hundreds
more on demand.
"""
from __future__ import annotations

import gzip
import hashlib
import json
import os

import pytest

from spinemu.chip import Chip

from chip_helpers import ROOT, pasm_mismatches

SAMPLE = os.path.join(ROOT, "tests", "data", "chip", "pasm_random", "sample.json.gz")


def _programs():
    with gzip.open(SAMPLE, "rt") as f:
        return json.load(f)["programs"]


PROGRAMS = _programs()


@pytest.mark.parametrize("program", PROGRAMS, ids=[f"seed{p['seed']}" for p in PROGRAMS])
def test_random_program_runs_as_on_spinsim(program):
    expected = program["expected"]
    chip = Chip(bytes.fromhex(program["binary"]))
    steps: list = []
    chip.trace_cog(1, steps.append)
    result = chip.run(max_cycles=10 * expected["end_cycle"])
    bad = pasm_mismatches(expected["steps"], steps)
    assert not bad, f"{len(bad)} differences, first: " + "; ".join(bad[:3]) + "\n" + program["source"]
    assert len(steps) == len(expected["steps"])
    assert [list(c) for c in result.trace.changes] == expected["pins"]
    assert (result.reason, result.end_cycle) == ("all cogs stopped", expected["end_cycle"])
    assert hashlib.sha256(result.hub).hexdigest() == expected["hub_sha256"]


def test_the_sample_covers_every_instruction_family():
    from spinemu.chip.pasm_ops import FAMILIES
    seen = set()
    for program in PROGRAMS:
        for step in program["expected"]["steps"]:
            family, detail = FAMILIES[step[2] >> 26]
            seen.add(family if family != "alu" else detail)
    assert {"jump", "mem", "hubop", "wait"} <= seen
    alu = {d for f, d in FAMILIES if f == "alu"}
    assert len(alu & seen) >= len(alu) - 3
