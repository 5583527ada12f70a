"""A seeded sample of generated programs, checked against what OpenSpin and spinsim said (no oracle needed).

``tests/data/fuzz/compile_sample.json``: spinemu's image of each program is
OpenSpin's (SHA-256).  ``reference_sample.json``: the bytecode engine leaves
the results spinsim ``-p`` left, and the same hub RAM.  Both were recorded by
``python -m tests.fuzz.record``; the full campaigns are ``python -m tests.fuzz``.
"""
from __future__ import annotations

import hashlib
import json
import os

import pytest

from spinemu.chip import Chip

from tests.fuzz import generate
from tests.fuzz.oracles import spinemu_compile

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data", "fuzz")


def _load(name: str) -> dict:
    with open(os.path.join(DATA, name)) as fh:
        return json.load(fh)["seeds"]


COMPILE = _load("compile_sample.json")
REFERENCE = _load("reference_sample.json")
STALE = "the generator makes another program for this seed now: re-record with python -m tests.fuzz.record"


def _sha(data) -> str:
    return hashlib.sha256(data if isinstance(data, bytes) else data.encode()).hexdigest()


@pytest.mark.parametrize("seed", sorted(COMPILE, key=int))
def test_generated_program_compiles_to_openspins_image(seed):
    program = generate(int(seed))
    want = COMPILE[seed]
    assert _sha(program.text()) == want["program"], STALE
    image, err = spinemu_compile(program)
    if want["openspin"] == "rejected":
        assert image is None, "OpenSpin rejects this program; spinemu compiles it"
    else:
        assert image is not None, err
        assert _sha(image) == want["openspin"]


@pytest.mark.parametrize("seed", sorted(REFERENCE, key=int))
def test_generated_program_leaves_spinsims_results_and_hub_ram(seed):
    program = generate(int(seed))
    want = REFERENCE[seed]
    assert _sha(program.text()) == want["program"], STALE
    image, err = spinemu_compile(program)
    assert image is not None and _sha(image) == want["image"], err
    result = Chip(image, compat="spinsim").run(max_cycles=50_000_000)
    assert result.reason == "all cogs stopped"
    assert [f"${v:08X}" for v in program.results.read(image, result.hub)] == want["results"]
    assert _sha(result.hub) == want["hub"]


def test_a_seed_always_gives_the_same_program():
    assert generate(7).files == generate(7).files
    assert generate(7).files != generate(8).files


def test_a_program_says_where_its_results_are():
    program = generate(3)
    assert program.top in program.files
    assert f"long {program.results.name}[{program.results.count}]" in program.files[program.top]
    assert program.results.var_offset == 0
