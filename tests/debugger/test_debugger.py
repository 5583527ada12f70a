"""The debugger (spinemu.debugger): scripted sessions of ``spinemu debug --commands`` for each
kind of breakpoint, stepping and the stack view, and the same things from Python."""
import io
from pathlib import Path

import pytest

from spinemu.chip import Chip
from spinemu.cli import main
from spinemu.compiler import compile_file, compile_source
from spinemu.debugger import Debugger
from spinemu.debugger.session import DebugError

ROOT = Path(__file__).parent.parent.parent
DEMO = ROOT / "spin_src" / "corrected" / "stepper_demo.spin"


def session(tmp_path, commands, program=DEMO):
    script = tmp_path / "commands.txt"
    script.write_text(commands)
    out, err = io.StringIO(), io.StringIO()
    code = main(["debug", str(program), "--commands", str(script)], out, err)
    assert code == 0, err.getvalue()
    return out.getvalue()


def after(text, command):
    """The output of ``command`` in a transcript (up to the next prompt)."""
    part = text.split(f"(spin) {command}\n", 1)[1]
    return part.split("(spin) ", 1)[0]


# ----------------------------------------------------------------------------- scripted sessions
def test_a_line_breakpoint_stops_before_the_line_and_shows_it(tmp_path):
    out = session(tmp_path, "break stepper.spin:55\ncontinue\n")
    stop = after(out, "continue")
    assert "breakpoint #1 line" in stop and "cog 0 at spin_src/corrected/stepper.spin:55 in setMode" in stop
    assert "if (mode & M_ENABLED)" in stop


def test_a_method_breakpoint_stops_at_its_first_line(tmp_path):
    out = session(tmp_path, "break motor.setSteps\ncontinue\nprint s\n")
    assert "cog 0 at spin_src/corrected/stepper.spin:88 in setSteps" in after(out, "continue")
    assert after(out, "print s").strip() == "s = 48 ($00000030)"


def test_a_conditional_line_breakpoint_stops_only_when_it_holds(tmp_path):
    out = session(tmp_path, "break motor.setSteps if s < 0\ncontinue\nprint s\nbt\n")
    assert after(out, "print s").strip() == "s = -48 ($FFFFFFD0)"
    assert "main() at spin_src/corrected/stepper_demo.spin:44" in after(out, "bt")


def test_a_pin_breakpoint_stops_after_the_bytecode_that_changed_the_pin(tmp_path):
    out = session(tmp_path, "break pin 2\ncontinue\ncontinue\n")
    first = out.split("(spin) continue\n")[1].split("(spin)")[0]
    assert "pin P2: input -> low (cog 1 at spin_src/corrected/stepper.spin:136 in runStepper)" in first
    assert "dira[m4..m1]~~" in first
    second = out.split("(spin) continue\n")[2]
    assert "pin P2: low -> high (cog 1 at spin_src/corrected/stepper.spin:152 in runStepper)" in second


def test_a_watchpoint_stops_after_a_write_and_shows_old_and_new(tmp_path):
    out = session(tmp_path, "watch motor.numSteps\ncontinue\ncontinue\ncontinue\n")
    stops = [s.split("(spin)")[0] for s in out.split("(spin) continue\n")[1:]]
    assert "watchpoint numSteps: cog 0 at spin_src/corrected/stepper.spin:42 in start writes it: 0 -> 0" in stops[0]
    assert "stepper.spin:89 in setSteps writes it: 0 -> 48" in stops[1]
    assert "cog 1 at spin_src/corrected/stepper.spin:146 in runStepper writes it: 48 -> 47" in stops[2]


def test_a_condition_breakpoint_stops_where_it_becomes_true(tmp_path):
    out = session(tmp_path, "break if motor.stpIdx == 2\ncontinue\nprint motor.stpIdx\ncontinue 10ms\n")
    assert "condition motor.stpIdx == 2 holds: cog" in after(out, "continue")
    assert after(out, "print motor.stpIdx").strip() == "motor.stpIdx = 2 ($00000002)"
    assert "condition motor.stpIdx == 2 holds" not in after(out, "continue 10ms")  # it stays true: no new stop


def test_the_stack_view_names_parameters_locals_and_results_of_every_cog(tmp_path):
    out = session(tmp_path, "break stepper.spin:55\ncontinue\nbt all\n")
    bt = after(out, "bt all")
    assert "cog 0 (running):" in bt and "cog 1 (running):" in bt
    assert "> #0 setMode(m=0) at spin_src/corrected/stepper.spin:55  result=0" in bt
    assert "#1 start(ePin=0, mnTime=5) at spin_src/corrected/stepper.spin:39  okay=-1" in bt
    assert "#2 main() at spin_src/corrected/stepper_demo.spin:35  result=0" in bt
    assert "#0 runStepper(m1=1) at spin_src/corrected/stepper.spin:" in bt and "m4=4" in bt


def test_cogs_lists_where_each_cog_is(tmp_path):
    out = session(tmp_path, "break stepper.spin:55\ncontinue\ncogs\n")
    rows = after(out, "cogs").splitlines()
    assert rows[0].split() == ["cog", "state", "where", "method"]
    assert rows[1].split()[:3] == ["*0", "running", "spin_src/corrected/stepper.spin:55"]
    assert rows[2].split()[0] == "1" and "runStepper(m1=1)" in rows[2]


def test_step_next_finish_and_stepi(tmp_path):
    out = session(tmp_path, "break stepper_demo.spin:41\ncontinue\nstep\nnext\nfinish\nstepi 1\n")
    assert "cog 0 at spin_src/corrected/stepper.spin:88 in setSteps" in after(out, "step")   # into the call
    assert "cog 0 at spin_src/corrected/stepper.spin:89 in setSteps" in after(out, "next")
    assert "setSteps returned (its caller drops the result): cog 0 at spin_src/corrected/stepper_demo.spin:42" \
        in after(out, "finish")
    assert "cog 0 at spin_src/corrected/stepper_demo.spin:42 in main" in after(out, "stepi 1")


def test_finish_reports_the_value_a_method_returns(tmp_path):
    out = session(tmp_path, "break motor.getSteps\ncontinue\nfinish\n")
    assert "getSteps returned 48: cog 0 at spin_src/corrected/stepper_demo.spin:42 in main" in after(out, "finish")


def test_print_set_and_list_in_the_selected_frame(tmp_path):
    out = session(tmp_path, "break stepper.spin:55\ncontinue\nprint mode\nprint motor.stack\nset mode = 5\n"
                            "print mode + 1\nup\nprint mnTime\nlist\nprint motor.Steps\n")
    assert after(out, "print mode").strip() == "mode = 0 ($00000000)"
    assert after(out, "print motor.stack").startswith("motor.stack[64] = ")
    assert after(out, "print mode + 1").strip() == "mode + 1 = 6 ($00000006)"
    assert after(out, "print mnTime").strip() == "mnTime = 5 ($00000005)"
    assert "=>   39      setMode(%0000)" in after(out, "list")
    assert after(out, "print motor.Steps").strip() == "motor.Steps[4] = 3, 6, 12, 9"


def test_until_runs_to_a_line_and_run_lets_time_pass(tmp_path):
    out = session(tmp_path, "until stepper_demo.spin:43\ntime\nrun 1ms\ntime\n")
    assert "cog 0 at spin_src/corrected/stepper_demo.spin:43 in main" in after(out, "until stepper_demo.spin:43")
    t1 = int(after(out, "time").split()[1].replace(",", ""))
    t2 = int(out.rsplit("(spin) time\n", 1)[1].split()[1].replace(",", ""))
    assert t2 - t1 == 80_000


def test_continue_to_the_end_of_the_program(tmp_path):
    out = session(tmp_path, "continue\ncontinue\n", ROOT / "spin_src" / "warnings" / "uninitialized_fixed.spin")
    assert "the program has ended (all cogs stopped)" in after(out, "continue")


def test_mistakes_are_explained_and_the_session_goes_on(tmp_path):
    out = session(tmp_path, "break 3\nbreak nosuch\nprint nosuch\ncog 7\nwatch nothing\nfoo\ntime\n")
    assert "error: no code was made from" in after(out, "break 3")
    assert "error: no line, file:line, method or DAT label 'nosuch'" in after(out, "break nosuch")
    assert "error: unknown name 'nosuch'" in after(out, "print nosuch")
    assert "error: cog 7 is not running" in after(out, "cog 7")
    assert "error: no VAR or DAT variable 'nothing'" in after(out, "watch nothing")
    assert "unknown command 'foo'" in after(out, "foo")
    assert "cycle 0" in after(out, "time")


def test_debug_needs_a_spin_source(tmp_path):
    out, err = io.StringIO(), io.StringIO()
    assert main(["debug", str(ROOT / "tests" / "data" / "article" / "corrected_stepper_demo.binary")], out, err) == 2
    assert "needs its names and lines" in err.getvalue()


# ----------------------------------------------------------------------------- from Python
def test_the_python_api_steps_and_reads_frames():
    dbg = Debugger(str(DEMO))
    bp = dbg.break_at("stepper.spin:135")
    stop = dbg.cont()
    assert stop.reason == "breakpoint" and stop.cog == 1 and stop.breakpoint is bp
    frames = dbg.stack(1)
    assert frames[0].name == "runStepper" and frames[0].value("m1") == 1
    assert dbg.value("m1") == 1 and dbg.evaluate("m1 + 3") == 4
    stop = dbg.next()
    assert stop.reason == "step" and dbg.stack(1)[0].line == 136
    assert dbg.value("m4") == 4                               # assigned by line 135


def test_a_debugged_run_is_the_same_run_to_the_cycle():
    dbg = Debugger(str(ROOT / "spin_src" / "examples" / "two_cogs.spin"))
    dbg.break_on_pin(17)
    stops = 0
    while dbg.cont().reason == "pin":
        stops += 1
    assert stops > 20
    plain = Chip(compile_file(str(ROOT / "spin_src" / "examples" / "two_cogs.spin")).binary).run()
    assert dbg.chip.pin_trace().changes == plain.trace.changes and dbg.now == plain.end_cycle


def test_a_pasm_cog_is_shown_and_stepped_by_instruction():
    prog = compile_source("PUB main\n  cognew(@code, 0)\n  waitcnt(cnt + 10_000)\nDAT\ncode  nop\nloop  jmp #loop\n")
    dbg = Debugger(prog)
    dbg.run_for(5_000)
    view = dbg.cog(1)
    assert view.kind == "pasm" and view.place().startswith("PASM at cog $001: jmp #$001 (loop in ")
    assert view.place().endswith("main.spin), PAR $0000")
    stop = dbg.step(cog=1)
    assert stop.reason == "step" and [(s.pc, s.executed) for s in stop.steps] == [(1, True)]
    assert stop.detail.endswith("cog 1 at $001 (loop, main.spin:6): jmp #loop")


def test_the_documented_session_prints_what_the_docs_show(update_golden, monkeypatch):
    monkeypatch.chdir(ROOT)                          # the transcript shows paths relative to the project
    script = ROOT / "docs" / "examples" / "debug_demo.txt"
    golden = ROOT / "docs" / "examples" / "debug_demo.out"
    out, err = io.StringIO(), io.StringIO()
    assert main(["debug", "spin_src/corrected/stepper_demo.spin", "--commands", str(script)], out, err) == 0
    if update_golden:
        golden.write_text(out.getvalue())
    assert out.getvalue() == golden.read_text()
    assert golden.read_text() in (ROOT / "docs" / "debugger.md").read_text()
