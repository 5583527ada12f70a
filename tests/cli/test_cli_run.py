"""End-to-end command-line runs, in-process (STYLE.md section 7)."""
import io
from pathlib import Path

import pytest

from spinemu.cli import main
from spinemu.trace import read_log

ROOT = Path(__file__).parent.parent.parent
DATA = ROOT / "tests" / "data" / "article"
SRC = ROOT / "spin_src"


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


def test_compile_writes_the_openspin_image(tmp_path):
    target = tmp_path / "demo.binary"
    code, out, err = run("compile", SRC / "stepper_demo.spin", "-o", target)
    assert code == 0, err
    assert target.read_bytes() == (DATA / "as_printed_stepper_demo.binary").read_bytes()


def test_compile_writes_an_eeprom_image(tmp_path):
    target = tmp_path / "demo.eeprom"
    code, _, err = run("compile", SRC / "simple_stepper.spin", "-e", target)
    assert code == 0, err
    data = target.read_bytes()
    assert len(data) == 32768
    assert data[:168] == (DATA / "as_printed_simple_stepper.binary").read_bytes()


def test_a_syntax_error_names_file_line_column_and_writes_nothing(tmp_path):
    src = tmp_path / "bad.spin"
    src.write_text("PUB main\n  outa[0] := := 1\n")
    target = tmp_path / "bad.binary"
    code, _, err = run("compile", src, "-o", target)
    assert code == 1
    first = err.splitlines()[0]
    assert first.startswith(f"{src}:2:") and ": error: " in first
    assert "Traceback" not in err and "^" in err
    assert not target.exists()


def test_a_missing_object_file_is_reported_at_the_obj_line(tmp_path):
    src = tmp_path / "top.spin"
    src.write_text("OBJ\n  m : \"nowhere\"\nPUB main\n  m.go\n")
    code, _, err = run("compile", src)
    assert code == 1 and err.startswith(f"{src}:2:") and "nowhere" in err


def test_run_of_the_column_demo_matches_the_reference_by_default(tmp_path):
    log = tmp_path / "demo.log"
    code, out, err = run("run", SRC / "corrected" / "stepper_demo.spin", "--trace", log, "--no-progress")
    assert code == 0, err
    assert "all cogs stopped" in out and "2 started, 2 stopped" in out
    code, out, _ = run("trace", "compare", DATA / "corrected_stepper_demo.trace", log)
    assert code == 0 and "largest offset 0 cycles" in out


def test_run_in_chip_mode_loads_the_new_cog_first(tmp_path):
    # the silicon spends 7,952 cycles loading the stepper cog: P0 is driven before P1..P4
    log = tmp_path / "demo.log"
    code, _, err = run("run", SRC / "corrected" / "stepper_demo.spin", "--compat", "chip", "--seconds", "0.01",
                       "--trace", log, "--no-progress")
    assert code == 0, err
    changes = read_log(log.read_text()).changes
    assert [(d, o) for _, d, o in changes[1:3]] == [(0x01, 0), (0x1F, 0)]


def test_compat_and_inputs_are_refused_for_a_basic_stamp_program():
    code, _, err = run("run", SRC / "bs2" / "stepper_bs2.bs2", "--inputs", "pullup")
    assert code == 2 and "Spin programs only" in err


def test_run_of_a_binary_image_with_a_cycle_limit(tmp_path):
    log = tmp_path / "s.log"
    code, out, err = run("run", DATA / "as_printed_simple_stepper.binary", "--cycles", "20_000_000",
                         "--trace", log, "--trace-format", "log")
    assert code == 0, err
    trace = read_log(log.read_text())
    assert trace.changes[-1][0] <= 20_000_000
    assert "cycle limit" in out


def test_run_writes_vcd_and_hub_dump(tmp_path):
    vcd, hub = tmp_path / "s.vcd", tmp_path / "s.hub"
    code, _, err = run("run", SRC / "simple_stepper.spin", "--seconds", "0.05", "--trace", vcd, "--dump-hub", hub)
    assert code == 0, err
    assert "$var wire 1" in vcd.read_text() and len(hub.read_bytes()) == 32768


def test_run_of_the_basic_stamp_program_steps_every_15_ms(tmp_path):
    log = tmp_path / "b.log"
    code, out, err = run("run", SRC / "bs2" / "stepper_bs2.bs2", "--seconds", "0.1", "--trace", log)
    assert code == 0, err
    assert "time limit" in out
    code, out, _ = run("trace", "steps", log, "--clock", "1000000", "--pins", "4..7")
    assert code == 0 and "15.000 ms/step" in out


def test_basic_stamp_input_stimulus_reaches_the_program(tmp_path):
    prog = tmp_path / "in.bs2"
    prog.write_text("' {$STAMP BS2}\n' {$PBASIC 2.5}\nDO\n  OUT0 = IN3\nLOOP UNTIL IN3 = 1\nHIGH 1\n")
    log = tmp_path / "in.log"
    code, out, err = run("run", prog, "--seconds", "1", "--timing", "realistic", "--input", "P3=0@0,1@0.5", "--trace", log)
    assert code == 0, err
    assert "END statement" in out
    assert read_log(log.read_text()).changes[-1][2] & 0b10


def test_spin_input_stimulus_drives_ina(tmp_path):
    prog = tmp_path / "echo.spin"
    prog.write_text("CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"
                    "PUB main\n  dira[0]~~\n  repeat\n    outa[0] := ina[5]\n")
    log = tmp_path / "e.log"
    code, _, err = run("run", prog, "--seconds", "0.01", "--input", "P5=0@0,1@0.004", "--trace", log)
    assert code == 0, err
    highs = [c for c, d, o in read_log(log.read_text()).changes if o & 1]
    assert highs and 4 * 80_000 <= highs[0] <= 4 * 80_000 + 5_000


@pytest.mark.parametrize("argv,msg", [
    (["run", "x.bs2", "--cycles", "100"], "limited with --seconds"),
    (["run", "x.spin", "--timing", "exact"], "BASIC Stamp programs"),
    (["run", "x.spin", "--input", "P40=1"], "pin 40 does not exist"),
    (["run", "x.spin", "--cycles", "10", "--seconds", "1"], "not allowed with argument"),
])
def test_usage_errors_exit_2(tmp_path, argv, msg):
    (tmp_path / "x.spin").write_text("PUB main\n")
    (tmp_path / "x.bs2").write_text("' {$STAMP BS2}\nEND\n")
    argv = [str(tmp_path / a) if a.startswith("x.") else a for a in argv]
    code, _, err = run(*argv)
    assert code == 2 and msg in err, err


def test_an_unreadable_image_is_an_error(tmp_path):
    bad = tmp_path / "junk.binary"
    bad.write_bytes(b"not an image at all, really")
    code, _, err = run("run", bad)
    assert code == 1 and str(bad) in err and "Traceback" not in err


def test_sidebyside_of_bs2_and_spin_forward_revolution(tmp_path):
    b, s = tmp_path / "b.log", tmp_path / "s.log"
    assert run("run", SRC / "bs2" / "stepper_bs2.bs2", "--seconds", "1", "--trace", b)[0] == 0
    assert run("run", SRC / "simple_stepper.spin", "--seconds", "0.5", "--trace", s)[0] == 0
    code, out, _ = run("sidebyside", b, s, "--left-pins", "4..7", "--right-pins", "1..4",
                       "--left-clock", "1000000", "--steps", "48")
    assert code == 0 and "coil patterns agree for all 48 compared steps" in out


@pytest.mark.parametrize("defines,image", [([], "ifdef_fast.binary"), (["-D", "FAST"], "ifdef_fast_D_FAST.binary")])
def test_compile_with_defines_matches_openspin(tmp_path, defines, image):
    data = ROOT / "tests" / "data" / "compiler" / "defines"
    target = tmp_path / "out.binary"
    code, _, err = run("compile", data / "ifdef_fast.spin", *defines, "-o", target)
    assert code == 0, err
    assert target.read_bytes() == (data / image).read_bytes()


def test_progress_is_reported_on_a_terminal(monkeypatch):
    """A long run shows progress on a terminal; the callback must reach the display."""
    import spinemu.cli as cli

    class TTY(io.StringIO):
        def isatty(self):
            return True

    out = cli._Out(io.StringIO(), TTY())
    progress, update = cli._progress_callback(out, None, 80_000_000, True)
    assert progress is not None
    with progress:
        monkeypatch.setattr(cli.time, "monotonic", lambda: 1e9)
        update(40_000_000)
    assert progress.tasks[0].fields["sim"] == "0.500 s simulated"
    assert cli._progress_callback(cli._Out(io.StringIO(), io.StringIO()), None, 1, True) == (None, None)


def test_an_unknown_symbol_in_a_child_object_is_shown_as_in_the_house_style(tmp_path, monkeypatch):
    for name in ("stepper.spin", "stepper_demo.spin"):
        (tmp_path / name).write_text((SRC / name).read_text())
    child = tmp_path / "stepper.spin"
    child.write_text(child.read_text().replace("if (numSteps-- > 0)", "if (numStep-- > 0)"))
    monkeypatch.chdir(tmp_path)
    code, _, err = run("compile", "stepper_demo.spin")
    assert code == 1
    assert err.splitlines() == [
        "stepper.spin:146:15: error: unknown symbol 'numStep'",
        "          if (numStep-- > 0)                           ' any steps left?",
        "              ^",
    ]
    assert not (tmp_path / "stepper_demo.binary").exists()


def test_translate_writes_one_module_per_object(tmp_path):
    code, out, err = run("translate", SRC / "stepper_demo.spin", "-o", tmp_path / "py")
    assert code == 0, err
    names = sorted(p.name for p in (tmp_path / "py").glob("*.py"))
    assert names == ["__init__.py", "stepper.py", "stepper_demo.py"]
    text = (tmp_path / "py" / "stepper.py").read_text()
    assert "class Stepper(" in text and "def runStepper(self, m1):" in text and "# L146" in text


def test_translate_side_by_side_shows_both_languages():
    code, out, err = run("translate", "--side-by-side", SRC / "simple_stepper.spin")
    assert code == 0, err
    assert "stpDelay" in out and "def " in out


def test_translate_needs_an_output_folder():
    code, _, err = run("translate", SRC / "simple_stepper.spin")
    assert code == 2 and "-o OUT_DIR" in err


def test_python_engine_gives_the_bytecode_engines_trace(tmp_path):
    a, b = tmp_path / "bytecode.log", tmp_path / "python.log"
    src = SRC / "simple_stepper.spin"
    assert run("run", src, "--seconds", "0.3", "--trace", a)[0] == 0
    code, _, err = run("run", src, "--seconds", "0.3", "--engine", "python", "--trace", b)
    assert code == 0, err
    code, out, _ = run("trace", "compare", a, b)
    assert code == 0 and "largest offset 0 cycles" in out


def test_run_summary_lists_pll_outputs_and_warns_about_the_untraced_ones():
    code, out, err = run("run", ROOT / "tests" / "data" / "chip" / "counters" / "pll.spin", "--cycles", "200000",
                         "--compat", "chip", "--no-progress")
    assert code == 0, err
    assert "P5, P6: 625 kHz (cog 0 CTRA, PLL differential)" in out
    assert "P4: 80 MHz (cog 0 CTRB, PLL single-ended, not in the trace)" in out
    assert "warning:" in err and "80.000000 MHz" in err


def test_every_file_the_help_examples_name_exists():
    from spinemu.cli import EPILOG

    named = [word for line in EPILOG.splitlines() if line.lstrip().startswith("spinemu ")
             for word in line.split() if word.startswith("spin_src/")]
    assert named, "the examples name programs from spin_src"
    missing = [p for p in named if not (ROOT / p).exists()]
    assert not missing, f"--help names files that do not exist: {missing}"


def test_run_skips_a_steady_state_writes_the_same_trace_and_says_what_it_skipped(tmp_path):
    src = tmp_path / "blink.spin"
    src.write_text("CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"
                   "VAR\n  long stack[32], count\n"
                   "PUB main | t\n  cognew(follow, @stack)\n  dira[0]~~\n  t := cnt\n  repeat\n"
                   "    !outa[0]\n    count++\n    waitcnt(t += clkfreq / 1000)\n"
                   "PRI follow | t\n  dira[1]~~\n  t := cnt\n  repeat\n"
                   "    outa[1] := count & 1\n    waitcnt(t += 40_000)\n")
    plain, skipped = tmp_path / "plain.log", tmp_path / "skipped.log"
    code, out, err = run("run", src, "--seconds", "3", "--trace", plain, "--no-progress", "--no-steady-skip")
    assert code == 0, err
    assert "periods of a steady state skipped" not in out
    code, out, err = run("run", src, "--seconds", "3", "--trace", skipped, "--no-progress")
    assert code == 0, err
    assert "periods of a steady state skipped" in out
    assert skipped.read_text() == plain.read_text()
    assert len(read_log(plain.read_text()).changes) > 5000


def test_the_console_command_flushes_its_output_and_keeps_its_exit_status(tmp_path):
    # the entry point leaves with os._exit: the summary must still be written, the status kept
    import os
    import subprocess
    import sys
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    ok = subprocess.run([sys.executable, "-m", "spinemu", "run", str(SRC / "simple_stepper.spin"),
                         "--cycles", "8000000", "--no-progress"], capture_output=True, text=True, env=env)
    assert ok.returncode == 0, ok.stderr
    assert ok.stdout.splitlines()[0].startswith("simulated ") and "pins" in ok.stdout
    bad = subprocess.run([sys.executable, "-m", "spinemu", "run", str(tmp_path / "missing.spin")],
                         capture_output=True, text=True, env=env)
    assert bad.returncode == 1 and "no such file" in bad.stderr
