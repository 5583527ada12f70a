"""Conformance suite: Spin programs whose results on Parallax's ROM interpreter are known.

Each ``tests/data/chip/programs/NAME.spin`` comes with the image OpenSpin
made of it and ``NAME.expected.json``, recorded from spinsim 0.99 ``-p`` by
tests/chip/tools/make_conformance.py: the final VAR values, the SHA-256 of
all of hub RAM, the cycle the last cog stopped and, for single-cog programs,
every pin change.

:func:`run_engine` is the one place that knows how to run a program; the
Spin->Python translation can be added there as another engine (it checks the
VAR values, which every engine must reproduce; hub RAM, cycles and pins are
chip-only).
"""
from __future__ import annotations

import glob
import hashlib
import json
import os
import struct

import pytest

from spinemu.chip import Chip

from chip_helpers import PROGRAMS, read_bytes, trace_states

NAMES = sorted(os.path.splitext(os.path.basename(p))[0].replace(".expected", "")
               for p in glob.glob(os.path.join(PROGRAMS, "*.expected.json")))
ENGINES = ["chip"]

#: programs whose results spinemu does not reproduce yet, and why (docs/chip.md)
KNOWN_DIFFERENCES: dict = {}


def _marked(names):
    return [pytest.param(n, marks=pytest.mark.xfail(reason=KNOWN_DIFFERENCES[n], strict=True))
            if n in KNOWN_DIFFERENCES else n for n in names]


def load(name):
    with open(os.path.join(PROGRAMS, name + ".expected.json")) as f:
        return read_bytes(os.path.join(PROGRAMS, name + ".binary")), json.load(f)


def run_engine(engine: str, image: bytes):
    """Run ``image`` to its end; returns ``(var_longs: dict, chip result or None)``."""
    if engine == "chip":
        result = Chip(image, compat="spinsim").run(max_cycles=100_000_000)
        vbase, dbase = struct.unpack_from("<HH", image, 8)
        var = {f"{a:04x}": struct.unpack_from("<I", result.hub, a)[0]
               for a in range(vbase, dbase - 8, 4) if struct.unpack_from("<I", result.hub, a)[0]}
        return var, result
    raise ValueError(engine)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("name", _marked(NAMES))
def test_program_leaves_the_same_variables(name, engine):
    image, expected = load(name)
    var, _ = run_engine(engine, image)
    assert var == expected["var"]


@pytest.mark.parametrize("name", _marked(NAMES))
def test_program_ends_with_identical_hub_ram_at_the_same_cycle(name):
    image, expected = load(name)
    _, result = run_engine("chip", image)
    assert result.reason == "all cogs stopped"
    assert hashlib.sha256(result.hub).hexdigest() == expected["hub_sha256"]
    assert result.end_cycle == expected["end_cycle"]


@pytest.mark.parametrize("name", [n for n in NAMES if "trace" in load(n)[1]])
def test_program_changes_pins_at_the_same_cycles(name):
    image, expected = load(name)
    _, result = run_engine("chip", image)
    want = trace_states([tuple(x) for x in expected["trace"]])
    assert trace_states(result.trace.changes) == want
