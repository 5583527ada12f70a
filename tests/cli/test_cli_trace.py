"""The trace tools of the command line, called in-process."""
import io
from pathlib import Path

from spinemu.cli import main

DATA = Path(__file__).parent.parent / "data" / "article"


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main(list(argv), out, err)
    return code, out.getvalue(), err.getvalue()


def test_compare_passes_a_trace_against_itself():
    ref = str(DATA / "as_printed_simple_stepper.trace")
    code, out, _ = run("trace", "compare", ref, ref)
    assert code == 0 and "state sequence: identical" in out and out.splitlines()[-1].startswith("PASS")


def test_compare_fails_two_different_programs():
    code, out, _ = run("trace", "compare", str(DATA / "as_printed_stepper_demo.trace"),
                       str(DATA / "corrected_stepper_demo.trace"))
    assert code == 1 and "first difference" in out


def test_show_prints_a_timeline(tmp_path):
    code, out, _ = run("trace", "show", str(DATA / "corrected_stepper_demo.trace"), "--pins", "0..4", "--width", "30")
    assert code == 0 and "P4" in out and "edges" in out


def test_convert_writes_vcd(tmp_path):
    target = tmp_path / "demo.vcd"
    code, _, _ = run("trace", "convert", str(DATA / "corrected_stepper_demo.trace"), "-o", str(target))
    assert code == 0 and "$enddefinitions" in target.read_text()


def test_a_bad_trace_file_gets_file_line_and_caret(tmp_path):
    bad = tmp_path / "bad.log"
    bad.write_text("4 00000000 00000000\noops\n")
    code, _, err = run("trace", "show", str(bad))
    assert code == 1
    assert err.splitlines()[0] == f"{bad}:2:1: error: expected '<cycle> <dir> <out>' (decimal cycle, hex masks)"
    assert err.splitlines()[1:3] == ["oops", "^"]


def test_usage_errors_exit_2_without_traceback():
    code, _, err = run("run", "program.txt")
    assert code == 2 and "cannot tell what 'program.txt' is" in err and "Traceback" not in err
    code, _, err = run("run", "x.spin", "--cycles", "-5")
    assert code == 2 and "expected a number above 0" in err
    code, _, err = run("trace", "show", str(DATA / "corrected_stepper_demo.trace"), "--pins", "0..99")
    assert code == 2 and "pins must be 0..31" in err


def test_missing_file_is_an_error_not_a_traceback(tmp_path):
    code, _, err = run("trace", "show", str(tmp_path / "nope.log"))
    assert code == 1 and "cannot read file" in err and "Traceback" not in err


def test_help_lists_the_subcommands():
    code, out, _ = run("--help")
    assert code == 0
    for cmd in ("compile", "run", "disasm", "translate", "trace", "sidebyside"):
        assert cmd in out


def test_disasm_lists_an_openspin_image(tmp_path):
    code, out, _ = run("disasm", str(DATA / "as_printed_simple_stepper.binary"))
    assert code == 0
    assert "clkmode $6F (XTAL1 + PLL16X)" in out
    assert "REG_RANGE_USING      DIRA POST_SET" in out


def test_disasm_of_a_corrupt_image_is_an_error(tmp_path):
    bad = tmp_path / "bad.binary"
    bad.write_bytes(b"\x00" * 8)
    code, _, err = run("disasm", str(bad))
    assert code == 1 and "bad.binary" in err and "Traceback" not in err


def _step_dir_log(tmp_path, gaps):
    lines, now = ["0 00000003 00000002"], 1000
    for g in gaps:
        now += g
        lines += [f"{now} 00000003 00000003", f"{now + 400} 00000003 00000002"]
    path = tmp_path / "sd.log"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def test_steps_decodes_a_step_dir_trace_and_runs_it_through_the_motor(tmp_path):
    log = _step_dir_log(tmp_path, [80_000] * 5 + [8_000] * 5)     # 1,000 then 10,000 steps/s at 80 MHz
    code, out, _ = run("trace", "steps", log, "--step-dir", "0,1")
    assert code == 0 and "10 steps on P0 (step), P1 (dir) (step/dir), net +10 steps" in out
    assert "motor:" not in out
    code, out, _ = run("trace", "steps", log, "--step-dir", "0,1", "--pull-in", "2000")
    assert code == 0 and "motor: 10 steps asked for, 5 missed" in out


def test_steps_plots_the_motion(tmp_path):
    import pytest
    pytest.importorskip("matplotlib")
    log = _step_dir_log(tmp_path, [80_000] * 5)
    png = tmp_path / "m.png"
    code, out, _ = run("trace", "steps", log, "--step-dir", "0,1", "--plot", str(png))
    assert code == 0 and png.read_bytes()[:4] == b"\x89PNG" and "top speed 1000.00 steps/s" in out


def test_steps_needs_one_drive_with_the_right_number_of_pins(tmp_path):
    log = _step_dir_log(tmp_path, [80_000])
    for argv, message in ((["--pins", "1..4", "--step-dir", "0,1"], "either --pins"), ([], "either --pins"),
                          (["--step-dir", "0"], "--step-dir needs two pins"),
                          (["--pins", "1..3"], "a stepper has four coil pins")):
        code, _, err = run("trace", "steps", log, *argv)
        assert code == 2 and message in err, argv
