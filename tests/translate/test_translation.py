"""What the generated Python looks like, what it does, and how it fails (issue 5, items 1, 3, 5)."""
from __future__ import annotations

import ast
import os

import pytest
from rich.console import Console

from spinemu import translate
from spinemu.diagnostics import SpinError
from spinemu.translate import spin
from spinemu.translate.program import translate_program
from spinemu.translate.view import aligned_rows

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STEPPER = os.path.join(ROOT, "spin_src", "stepper.spin")
DEMO = os.path.join(ROOT, "spin_src", "stepper_demo.spin")


@pytest.fixture(scope="module")
def stepper_py():
    modules, _ = translate_program(STEPPER)
    return modules[0].text


def test_translate_file_writes_one_module_per_object_and_a_package(tmp_path):
    files = translate.translate_file(DEMO, tmp_path)
    assert [os.path.basename(f) for f in files] == ["stepper_demo.py", "stepper.py"]
    assert (tmp_path / "__init__.py").exists()
    for f in files:
        ast.parse(open(f).read())          # valid Python
    top = open(files[0]).read()
    assert "from .stepper import Stepper" in top
    assert "motor = spin.Child(Stepper)" in top
    assert "self.motor.setDir(self.motor.RUN_FWD)" in top      # obj#CONST as attribute access


def test_stepper_reads_as_python_with_spin_names_constants_and_comments(stepper_py):
    assert "class Stepper(spin.Object):" in stepper_py
    assert "M_ENABLED = 0b0001" in stepper_py                   # CON as class constants
    assert "def start(self, ePin, mnTime):" in stepper_py       # parameter names kept
    assert "okay = self.cogon" in stepper_py                    # named result kept
    assert "return okay" in stepper_py
    assert "def runStepper(self, m1):" in stepper_py
    assert '"""Load background stepper controller if cog available"""' in stepper_py   # '' comment -> docstring
    assert "# L54: update mode" in stepper_py                   # Spin line and comment carried over
    assert "cog.OUTA[m4:m1] = self.Steps[self.stpIdx]" in stepper_py
    assert "spin.waitcnt(c)" in stepper_py
    assert "self.cog = spin.cognew(self.runStepper, wrap(ePin + 1), stack=self.addr(\"stack\"))" in stepper_py
    assert "while True:" in stepper_py
    assert "exec(" not in stepper_py and "eval(" not in stepper_py


def test_every_statement_line_names_its_spin_line(stepper_py):
    lines = stepper_py.splitlines()
    tree = ast.parse(stepper_py)
    checked = 0
    for node in ast.walk(tree):
        if not isinstance(node, ast.FunctionDef):
            continue
        for stmt in ast.walk(node):
            if not isinstance(stmt, ast.stmt) or isinstance(stmt, ast.FunctionDef):
                continue
            text = lines[stmt.lineno - 1]
            if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
                continue                                       # docstring
            if text.strip().endswith("= 0") or text.strip().startswith(("return okay", "pass")):
                continue                                       # local set-up and the method's end
            assert "# L" in text, text
            checked += 1
    assert checked > 60


def test_spin_operators_keep_their_meaning():
    assert spin.div(-17, 5) == -3 and spin.mod(-17, 5) == -2
    assert spin.div(7, 0) == 0
    assert spin.shr(-0x80000000, 4) == 0x08000000
    assert spin.wrap(0x7FFFFFFF + 1) == -0x80000000
    assert spin.rev(0b0011, 4) == 0b1100
    assert spin.encode(0x100) == 9 and spin.decode(31) == -0x80000000
    assert spin.lookupz(1, [7, 8]) == 8 and spin.lookdown(11, [6, spin.span(10, 12)]) == 3
    assert spin.within(5, 7, 3) and not spin.within(8, 7, 3)
    assert spin.repeat_step(4, 0, 4) == (5, False)


def test_translated_program_runs_from_the_written_package(tmp_path):
    from spinemu.translate.weave import load_package
    translate.translate_file(os.path.join(ROOT, "spin_src", "simple_stepper.spin"), tmp_path)
    package = load_package(str(tmp_path))
    result = translate.run_package(package, max_cycles=2_000_000)
    states = [(d, o) for _c, d, o in result.trace.changes]
    assert (31, 1) in states and result.reason == "cycle limit"


def test_an_object_index_past_the_obj_line_is_named_with_its_place_and_nothing_is_written(tmp_path):
    (tmp_path / "kid.spin").write_text("PUB f\n  return 1\n")
    src = tmp_path / "far.spin"
    src.write_text('OBJ\n  one : "kid"\n  two[2] : "kid"\nVAR\n  long r\n'
                   "PUB main\n  r := one[0].f + two[1].f\n  r := two[2].f\n")
    with pytest.raises(SpinError) as err:
        translate.translate_file(src, tmp_path / "out")
    assert "far.spin:8:8: error: cannot translate an index on object 'two' past its 2 instances" in str(err.value)
    assert not (tmp_path / "out").exists()


def test_spin_errors_come_from_the_front_end(tmp_path):
    src = tmp_path / "bad.spin"
    src.write_text("PUB main\n  x := 1\n")
    with pytest.raises(SpinError) as err:
        translate.translate_file(src, tmp_path / "out")
    assert "bad.spin:2:" in str(err.value)


def test_side_by_side_aligns_python_lines_with_their_spin_lines():
    modules, _ = translate_program(STEPPER)
    spin_text = open(STEPPER).read()
    rows = aligned_rows(spin_text, modules[0])
    by_spin = {n: py for n, _s, py in rows if n is not None and py}
    assert "self.mode = m & 0b1111" in by_spin[54]
    assert "SPIN_CYCLES" not in "".join(py for _n, _s, py in rows)
    numbered = [n for n, _s, _p in rows if n is not None]
    assert numbered == sorted(numbered) and numbered[-1] == len(spin_text.splitlines())
    console = Console(width=200, record=True, color_system=None)
    console.print(translate.side_by_side(STEPPER))
    out = console.export_text()
    assert "mode := m & %1111" in out and "self.mode = m & 0b1111" in out


@pytest.mark.parametrize("name, src, cycles", [
    ("as_printed_simple_stepper", "spin_src/simple_stepper.spin", 1_000_000_000),
    ("as_printed_stepper_demo", "spin_src/stepper_demo.spin", None),
    ("corrected_stepper_demo", "spin_src/corrected/stepper_demo.spin", None),
])
def test_translated_column_programs_reproduce_parallaxs_interpreter(name, src, cycles):
    # tests/data/article: the ROM interpreter on spinsim 0.99 (compat="spinsim" models that simulator)
    from spinemu.analysis.compare import compare_traces
    from spinemu.trace import read_log
    ref = read_log(open(os.path.join(ROOT, "tests", "data", "article", name + ".trace")).read())
    result = translate.run_translated(os.path.join(ROOT, src), max_cycles=cycles, compat="spinsim")
    comparison = compare_traces(ref, result.trace, slack=0)
    assert comparison.identical and comparison.largest_offset == 0, comparison.render()
    hub_path = os.path.join(ROOT, "tests", "data", "article", name + ".hub")
    if os.path.exists(hub_path):
        hub = open(hub_path, "rb").read()
        stacks = [first for _cog, first, _end in result.stats["stacks"]]
        differ = [a for a in range(len(hub)) if hub[a] != result.hub[a]]
        # only on the cogs' stacks (the demo's calls are shallow: 256 bytes each)
        assert all(any(s <= a < s + 256 for s in stacks) for a in differ), [hex(a) for a in differ[:8]]
