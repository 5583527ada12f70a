"""PASM probe programs against what spinsim 0.99 ``-p`` did with them.

Each ``tests/data/chip/pasm/NAME.spin`` (spinemu's own probes: the pipeline,
jumps, hub windows in every cog, WAITCNT, pins and WAITPEQ across cogs,
COGINIT/COGSTOP, locks, special registers, Spin and PASM together, a PASM
cog starting a Spin cog, odd corners) comes with OpenSpin's image and
``NAME.expected.json``, recorded by tests/chip/tools/make_pasm_probes.py: every instruction of every PASM cog
(first cycle, address, long, condition, value written, flags), the pin
changes, the cycle the last cog stopped and the hub RAM's SHA-256 then.
"""
from __future__ import annotations

import glob
import hashlib
import json
import os

import pytest

from spinemu.chip import Chip

from chip_helpers import ROOT, pasm_mismatches, read_bytes

PROBES = os.path.join(ROOT, "tests", "data", "chip", "pasm")
NAMES = sorted(os.path.basename(p)[:-len(".expected.json")]
               for p in glob.glob(os.path.join(PROBES, "*.expected.json")))


def run_probe(name):
    image = read_bytes(os.path.join(PROBES, name + ".binary"))
    with open(os.path.join(PROBES, name + ".expected.json")) as f:
        expected = json.load(f)
    chip = Chip(image)
    steps = {int(k): [] for k in expected["steps"]}
    for cog, log in steps.items():
        chip.trace_cog(cog, log.append)
    result = chip.run(max_cycles=10 * expected["end_cycle"])
    return expected, steps, result


@pytest.mark.parametrize("name", NAMES)
def test_probe_runs_every_pasm_instruction_as_spinsim(name):
    expected, steps, _ = run_probe(name)
    for cog, recorded in expected["steps"].items():
        bad = pasm_mismatches(recorded, steps[int(cog)])
        assert not bad, f"cog {cog}: {len(bad)} differences, first: " + "; ".join(bad[:3])


@pytest.mark.parametrize("name", NAMES)
def test_probe_pins_end_and_hub_as_spinsim(name):
    expected, _, result = run_probe(name)
    assert result.reason == "all cogs stopped"
    assert result.end_cycle == expected["end_cycle"]
    assert [list(c) for c in result.trace.changes] == expected["pins"]
    assert hashlib.sha256(result.hub).hexdigest() == expected["hub_sha256"]


@pytest.mark.parametrize("name", NAMES)
def test_probe_results_do_not_depend_on_fast_forward_or_compiled_blocks(name):
    image = read_bytes(os.path.join(PROBES, name + ".binary"))
    runs = [Chip(image, fast_forward=ff, compile_blocks=cb).run(max_cycles=5_000_000)
            for ff, cb in ((True, True), (False, False))]
    a, b = runs
    assert (a.trace.changes, a.hub, a.end_cycle, a.stats["pasm_instructions_per_cog"]) == \
        (b.trace.changes, b.hub, b.end_cycle, b.stats["pasm_instructions_per_cog"])
