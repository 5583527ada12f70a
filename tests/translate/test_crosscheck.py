"""Every Spin program in the tests runs on both engines with the same pins, timing and hub RAM (issue 5, item 4).

The list is built from the folders, so each new Spin test program is
checked on both engines.  Objects that are only children of other programs
(``*_child.spin``, ``sub_obj.spin``) run too: their first method starts with
zero parameters, as the boot loader would start it.  Known gaps are listed
in ``KNOWN_GAPS`` with their reason (docs/translate.md, "Not yet
translated").
"""
from __future__ import annotations

import glob
import os

import pytest

from spinemu import translate
from spinemu.diagnostics import EmulationError
from spinemu.translate import TranslateError
from tests.translate.crosscheck import crosscheck, run_bytecode

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

#: cycle budget per program: the column's demos run for seconds of chip time,
#: the semantics programs finish in well under this
BUDGETS = {"stepper_demo.spin": 120_000_000, "simple_stepper.spin": 60_000_000, "stepper.spin": 20_000_000,
           "cpu_bench.spin": 120_000_000}
DEFAULT_BUDGET = 3_000_000

#: programs the translator does not handle yet, and why
KNOWN_GAPS: dict = {
    "loop_count_leftover.spin": "reads an uninitialised local where a finished repeat left its count; "
                                "the Python engine starts such a local at 0 (docs/translate.md)",
    # spin_src/warnings: programs that make the mistakes the runtime warnings catch; what they do
    # then depends on the bytes of stacks and code, which the Python engine does not share
    "uninitialized.spin": "reads a local before assigning it: the value is the bytecode engine's leftover "
                          "stack, and the Python engine keeps its frames in Python",
    "stack_overflow.spin": "a cog's stack overruns into the next cog's frame in hub RAM; the Python "
                           "engine keeps its frames in Python",
    "write_into_code.spin": "overwrites its own bytecode, which the Python translation does not run",
}


def spin_programs() -> list:
    found = sorted(glob.glob(os.path.join(ROOT, "spin_src", "**", "*.spin"), recursive=True))
    for folder in ("tests/data/chip", "tests/data/translate"):
        found += sorted(glob.glob(os.path.join(ROOT, folder, "**", "*.spin"), recursive=True))
    return found


def _param(path):
    name = os.path.basename(path)
    rel = os.path.relpath(path, ROOT)
    marks = [pytest.mark.xfail(reason=KNOWN_GAPS[name], strict=True)] if name in KNOWN_GAPS else []
    return pytest.param(path, id=rel, marks=marks)


@pytest.mark.parametrize("compat", ["spinsim", "chip"])
@pytest.mark.parametrize("path", [_param(p) for p in spin_programs()])
def test_python_engine_matches_the_bytecode_engine(path, compat):
    budget = BUDGETS.get(os.path.basename(path), DEFAULT_BUDGET)
    try:
        bytecode_run = run_bytecode(path, budget, compat)
    except EmulationError as bytecode_fault:  # a program that faults must fault on both engines
        with pytest.raises(EmulationError) as err:
            translate.run_translated(path, max_cycles=budget, compat=compat)
        assert bytecode_fault.message.split(":")[0] == err.value.message.split(":")[0]
        return
    try:
        result = crosscheck(path, budget, compat, bytecode_run)
    except TranslateError as exc:
        pytest.fail(f"not translated: {exc}")
    assert result.ok, result.describe()
    assert result.bytecode.end_cycle == result.python.end_cycle


def test_the_program_list_covers_the_column_and_the_chip_programs():
    names = {os.path.relpath(p, ROOT) for p in spin_programs()}
    assert "spin_src/stepper_demo.spin" in names
    assert "spin_src/corrected/stepper_demo.spin" in names
    assert any(n.startswith("tests/data/chip/") for n in names)
    assert any(n.startswith("tests/data/translate/") for n in names)
