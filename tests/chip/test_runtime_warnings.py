"""Runtime warnings (spinemu.runtime_warnings, spinemu.chip.checks): each one fires on its
example program in spin_src/warnings and stays quiet on the corrected twin, with and
without compiled blocks, and never changes what the chip does."""
import io
from pathlib import Path

import pytest

from spinemu.chip import Chip
from spinemu.cli import main
from spinemu.compiler import compile_file, compile_source
from spinemu.runtime_warnings import KINDS, RuntimeWarningError, WarningLog

ROOT = Path(__file__).parent.parent.parent
EXAMPLES = ROOT / "spin_src" / "warnings"

#: example file -> (kind, line of the mistake)
CASES = {
    "waitcnt_passed": ("waitcnt-passed", 11),
    "stack_overflow": ("stack-overflow", 17),
    "no_free_cog": ("no-free-cog", 8),
    "pin_conflict": ("pin-conflict", 14),
    "write_outside_hub": ("write-outside-hub", 8),
    "write_into_code": ("write-into-code", 8),
    "uninitialized": ("uninitialized", 9),
}


def run(path, cycles=20_000_000, **kw):
    prog = compile_file(str(path))
    chip = Chip(prog.binary, debug_info=prog.debug_info(), **kw)
    return chip.run(max_cycles=cycles)


def test_every_kind_has_an_example_pair():
    assert sorted(k for k, _ in CASES.values()) == sorted(KINDS)
    for name in CASES:
        assert (EXAMPLES / f"{name}.spin").exists() and (EXAMPLES / f"{name}_fixed.spin").exists()


@pytest.mark.parametrize("blocks", [True, False], ids=["blocks", "interpreter"])
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_mistake_warns_once_at_its_line(name, blocks):
    kind, line = CASES[name]
    r = run(EXAMPLES / f"{name}.spin", compile_blocks=blocks)
    assert [(w.kind, w.line) for w in r.runtime_warnings] == [(kind, line)]
    w = r.runtime_warnings[0]
    assert w.path.endswith(f"{name}.spin") and w.column >= 1 and w.source_line


@pytest.mark.parametrize("blocks", [True, False], ids=["blocks", "interpreter"])
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_corrected_program_does_not_warn(name, blocks):
    r = run(EXAMPLES / f"{name}_fixed.spin", compile_blocks=blocks)
    assert r.runtime_warnings == []


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_checks_change_nothing_the_chip_does(name):
    prog = compile_file(str(EXAMPLES / f"{name}.spin"))
    on = Chip(prog.binary, debug_info=prog.debug_info()).run(max_cycles=20_000_000)
    off = Chip(prog.binary, warn=False).run(max_cycles=20_000_000)
    assert on.trace.changes == off.trace.changes and on.hub == off.hub and on.end_cycle == off.end_cycle
    assert off.runtime_warnings == []


def message(name):
    return run(EXAMPLES / f"{name}.spin").runtime_warnings[0].message


def test_a_passed_waitcnt_says_how_long_the_cog_stalls_and_that_cnt_may_be_missing():
    text = message("waitcnt_passed")
    assert "stalls 53." in text and "80 MHz" in text and "'+ cnt' missing" in text


def test_a_waitcnt_that_lags_behind_its_own_loop_is_not_blamed_on_a_missing_cnt():
    prog = compile_source("PUB main | c\n  waitcnt(cnt + 100_000)\n  c := cnt\n  repeat 3\n    waitcnt(c += 200)\n")
    r = Chip(prog.binary, debug_info=prog.debug_info()).run(max_cycles=1_000_000)
    (w,) = r.runtime_warnings
    assert w.kind == "waitcnt-passed" and "'+ cnt' missing" not in w.message and "loop" in w.message


def test_a_stack_overflow_names_the_array_and_the_methods():
    text = message("stack_overflow")
    assert "long stack[8]" in text and "cognew gave to worker" in text and "calling sum" in text


def test_no_free_cog_names_the_method_that_does_not_start():
    assert "blink (a Spin method) does not start" in message("no_free_cog")


def test_a_pin_conflict_names_the_pin_and_both_cogs():
    assert message("pin_conflict").startswith("P5: cog 1 drives it low while cog 0 drives it high")


def test_a_write_into_code_names_the_method_it_hits():
    assert "method main of write_into_code.spin" in message("write_into_code")


def test_a_pasm_hub_write_into_code_warns_with_its_size_at_its_dat_line():
    prog = compile_source("PUB main\n  cognew(@entry, 0)\n  waitcnt(cnt + 5_000)\nDAT\n        org 0\n"
                          "entry   mov a, #$12\n        wrword a, #$14\n        cogid a\n        cogstop a\n"
                          "a       long 0\n")
    r = Chip(prog.binary, debug_info=prog.debug_info()).run(max_cycles=100_000)
    assert [(w.kind, w.line, w.cog) for w in r.runtime_warnings] == [("write-into-code", 7, 1)]
    assert r.runtime_warnings[0].message.startswith("word write to $0014 changes the program's own code")


def test_a_local_read_first_names_it_and_its_method():
    assert message("uninitialized").startswith("local 'sum' of average is read before it is assigned")


def test_a_place_warns_once_and_counts_the_rest():
    (w,) = run(EXAMPLES / "write_into_code.spin").runtime_warnings
    assert w.count == 4                     # buf[4..7]: four bytes of main's code


def test_an_uninitialized_read_only_warns_when_the_path_taken_skips_the_assignment():
    src = "PUB main | x, flag\n  flag := {f}\n  if flag\n    x := 5\n  if flag\n    outa := x\n  ifnot flag\n    outa := x\n"
    quiet = compile_source(src.format(f=1))
    assert Chip(quiet.binary, debug_info=quiet.debug_info()).run().runtime_warnings == []
    loud = compile_source(src.format(f=0))
    (w,) = Chip(loud.binary, debug_info=loud.debug_info()).run().runtime_warnings
    assert w.kind == "uninitialized" and w.line == 8


def test_parameters_result_and_assigned_locals_never_warn():
    prog = compile_source("PUB main | a\n  a := f(3)\n  outa := a\nPRI f(n) : r | i\n  r += n\n"
                          "  repeat i from 1 to n\n    r += i\n")
    assert Chip(prog.binary, debug_info=prog.debug_info()).run().runtime_warnings == []


def test_warnings_as_errors_stop_the_run_at_the_first_one():
    prog = compile_file(str(EXAMPLES / "uninitialized.spin"))
    info = prog.debug_info()
    chip = Chip(prog.binary, debug_info=info, warn=WarningLog(info.position, info.source_line, werror=True))
    with pytest.raises(RuntimeWarningError) as e:
        chip.run()
    assert e.value.path.endswith("uninitialized.spin") and e.value.line == 9
    assert "warnings are errors" in e.value.message


def test_without_debug_info_the_image_checks_still_run():
    prog = compile_file(str(EXAMPLES / "write_into_code.spin"))
    (w,) = Chip(prog.binary).run().runtime_warnings
    assert w.kind == "write-into-code" and w.path is None and "write to $001C" in w.message


def test_the_column_programs_do_not_warn():
    for name in ("corrected/stepper_demo.spin", "stepper_demo.spin", "simple_stepper.spin"):
        r = run(ROOT / "spin_src" / name, cycles=160_000_000)
        assert r.runtime_warnings == [], name


# ----------------------------------------------------------------------------- the command line
def cli(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


def test_run_prints_each_warning_at_its_spin_line_and_lists_it_in_the_summary():
    code, out, err = cli("run", EXAMPLES / "waitcnt_passed.spin", "--seconds", "0.2", "--no-progress")
    assert code == 0
    first = err.splitlines()[0]
    assert "waitcnt_passed.spin:11:3: warning: waitcnt for a count that passed" in first
    assert "^" in err
    assert "warnings" in out and "waitcnt_passed.spin:11: waitcnt-passed" in out


def test_no_warn_silences_them():
    code, out, err = cli("run", EXAMPLES / "waitcnt_passed.spin", "--seconds", "0.2", "--no-warn")
    assert code == 0 and "warning" not in err and "waitcnt-passed" not in out


def test_werror_stops_the_run_with_exit_status_1():
    code, out, err = cli("run", EXAMPLES / "pin_conflict.spin", "-Werror")
    assert code == 1 and ": error: P5: cog 1 drives it low" in err and "warnings are errors" in err
    assert "Traceback" not in err


BUSY_CALLS_UNINITIALIZED = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long flag, stack[32]
PUB main
  cognew(setter, @stack)
  repeat until flag
    peek
PRI peek | x
  return x
PRI setter
  waitcnt(cnt + 4_000_000)
  flag := 1
"""


def test_a_busy_loop_that_warns_every_time_is_not_skipped_past_its_warnings():
    # each call of peek is a new frame whose x is read unassigned: a warning per call.  The busy-loop
    # learner runs the bytecodes with the checks' wrapped handlers too, sees the warnings, and does
    # not skip the loop, so the count is the same with and without fast-forward
    prog = compile_source(BUSY_CALLS_UNINITIALIZED, "busy.spin")
    counts = []
    for ff in (True, False):
        r = Chip(prog.binary, debug_info=prog.debug_info(), fast_forward=ff).run(max_cycles=20_000_000)
        counts.append([(w.kind, w.line, w.count) for w in r.runtime_warnings])
    assert counts[0] == counts[1] and counts[0][0][2] > 1000
