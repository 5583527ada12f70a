"""Compiler hints (spinemu.compiler.hints, spinemu.frontend.obj_shadow): things that compile but
are rarely meant, reported at file:line:col, with the image unchanged (OpenSpin's, byte for byte)."""
import io
from pathlib import Path

from spinemu.cli import main
from spinemu.compiler import compile_file, compile_source

ROOT = Path(__file__).parent.parent.parent
PROBE = ROOT / "tests" / "data" / "compiler" / "probes" / "hints.spin"


def hints(src: str):
    return [(d.line, d.column, d.message) for d in compile_source(src).warnings]


def test_the_hinted_probe_compiles_to_openspins_image():
    prog = compile_file(str(PROBE))
    assert prog.binary == PROBE.with_suffix(".binary").read_bytes()
    assert [(d.line, d.column) for d in prog.warnings] == [(4, 7), (6, 8), (8, 18), (13, 17)]
    assert all(d.severity == "warning" for d in prog.warnings)


def test_greater_equal_in_a_condition_is_an_assignment():
    ((line, col, text),) = hints("PUB main | x\n  if x >= 10\n    outa := 1\n")
    assert (line, col) == (2, 8)
    assert text.startswith("'>=' assigns in Spin: 'x >= ...' sets x to (x > ...)") and "write '=>'" in text


def test_less_equal_in_a_loop_test_is_an_assignment():
    ((line, col, text),) = hints("PUB main | i\n  repeat while i <= 10\n    i++\n")
    assert (line, col) == (2, 18) and "write '=<'" in text


def test_the_assignment_on_its_own_and_the_real_comparisons_are_not_hinted():
    assert hints("PUB main | x\n  x >= 10\n  if x => 10 or x =< 2\n    outa := 1\n") == []


def test_rotate_left_written_against_a_number_is_hinted():
    ((line, col, text),) = hints("PUB main | z\n  if z<-1\n    outa := 1\n")
    assert (line, col) == (2, 7) and "'z<-1' rotates z left by 1" in text and "'z < -1'" in text
    assert len(hints("PUB main | z\n  if z <-1\n    outa := 1\n")) == 1


def test_a_spaced_rotate_and_the_rotate_assignment_are_not_hinted():
    assert hints("PUB main | z\n  z := z <- 1\n  z <-= 2\n  z := z <- (1)\n") == []


def test_the_column_programs_and_examples_get_no_hints():
    for path in list((ROOT / "spin_src").rglob("*.spin")):
        assert compile_file(str(path)).warnings == [], path


def _library(tmp_path, same: bool):
    for lib, body in (("lib1", "PUB go\n  outa := 1\n"), ("lib2", "PUB go\n  outa := 1\n" if same else "PUB go\n  outa := 2\n")):
        (tmp_path / lib).mkdir()
        (tmp_path / lib / "led.spin").write_text(body)
    top = tmp_path / "app" / "top.spin"
    top.parent.mkdir()
    top.write_text('OBJ\n  led : "led"\nPUB main\n  led.go\n')
    return top, [str(tmp_path / "lib1"), str(tmp_path / "lib2")]


def test_an_obj_file_from_a_library_folder_that_hides_another_is_hinted(tmp_path):
    top, libs = _library(tmp_path, same=False)
    prog = compile_file(str(top), include_dirs=libs)
    (d,) = prog.warnings
    assert (d.path, d.line, d.column) == (str(top), 2, 3)
    assert "'led' is taken from" in d.message and "lib1" in d.message and "lib2" in d.message


def test_identical_copies_and_files_next_to_the_source_are_not_hinted(tmp_path):
    top, libs = _library(tmp_path, same=True)
    assert compile_file(str(top), include_dirs=libs).warnings == []
    (top.parent / "led.spin").write_text("PUB go\n  outa := 3\n")
    assert compile_file(str(top), include_dirs=libs).warnings == []


def test_compile_and_run_print_the_hints_on_stderr():
    for argv in (["compile", str(PROBE), "-o", "/dev/null"], ["run", str(PROBE), "--cycles", "100000", "--no-progress"]):
        out, err = io.StringIO(), io.StringIO()
        assert main(argv, out, err) == 0
        assert "hints.spin:6:8: warning: '>=' assigns in Spin" in err.getvalue() and "^~" in err.getvalue()


def test_a_jump_openspins_sizing_writes_past_its_target_is_hinted_at_its_line():
    regressions = ROOT / "tests" / "data" / "compiler" / "regressions"
    prog = compile_file(str(regressions / "stale_branch_jumps.spin"))
    stale = [d for d in prog.warnings if d.message.startswith("OpenSpin's jump sizing")]
    assert stale, "the regression program has jumps OpenSpin writes one byte past their targets"
    assert all("1 byte past its target" in d.message and d.line for d in stale)
    # a program whose jumps all land where they should gets no such hint
    far = compile_file(str(regressions / "next_in_post_loop_far.spin"))
    assert not [d for d in far.warnings if d.message.startswith("OpenSpin's jump sizing")]
