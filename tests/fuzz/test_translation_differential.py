"""A seeded sample of the translation differential (tests/fuzz/translation.py) in the default run.

Generated programs run on the bytecode engine and on the Python engine: the
same pin changes at the same cycles, the same end cycle, the same hub RAM
outside the stacks.  The campaigns behind docs/translate.md ran thousands of
seeds; this sample keeps a few of each generator in every test run.
"""
from __future__ import annotations

import pytest

from tests.fuzz.translation import _generators, check_translate

#: seeds run by every test run (each program takes a fraction of a second on both engines)
FULL_SEEDS = range(1000, 1006)
ORDER_SEEDS = range(2000, 2012)


@pytest.mark.parametrize("seed", FULL_SEEDS)
def test_generated_programs_run_alike_on_both_engines(seed):
    verdict = check_translate(_generators()["full"](seed))
    assert verdict is None, f"seed {seed}: {verdict} (python -m tests.fuzz.translation --seed {seed})"


@pytest.mark.parametrize("seed", ORDER_SEEDS)
def test_expressions_with_side_effects_run_alike_on_both_engines(seed):
    verdict = check_translate(_generators()["order"](seed))
    assert verdict is None, f"seed {seed}: {verdict} (python -m tests.fuzz.translation --generator order --seed {seed})"


def test_the_check_reports_a_python_engine_that_computes_a_value_wrong(monkeypatch):
    from spinemu.translate import spin
    program = _generators()["order"](ORDER_SEEDS[0])
    monkeypatch.setattr(spin, "random_forward", lambda v: 12345)
    monkeypatch.setattr(spin, "random_reverse", lambda v: 12345)
    program.files["main.spin"] += "PRI extra\n  r[0] := ?r[1]\n"
    program.files["main.spin"] = program.files["main.spin"].replace("  framed(a)\n", "  framed(a)\n  extra\n")
    verdict = check_translate(program)
    assert verdict is not None and verdict.startswith("hub RAM differs")
