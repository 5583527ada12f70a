"""The debugger on PASM cogs (spinemu.debugger.pasm_cogs): stepping by instruction, breakpoints on
cog addresses, DAT labels and DAT lines, registers by label, watchpoints and pin breakpoints hit
by PASM writes; and a run stopped at every instruction is the same run as a free one."""
import glob
import hashlib
import io
import json
import os
import random
from pathlib import Path

import pytest

from spinemu.chip import Chip
from spinemu.cli import main
from spinemu.compiler import compile_file
from spinemu.debugger import Debugger
from spinemu.debugger.session import DebugError

ROOT = Path(__file__).parent.parent.parent
COUNTER = ROOT / "tests" / "data" / "debugger" / "pasm_counter.spin"
PROBES = ROOT / "tests" / "data" / "chip" / "pasm"
NAMES = sorted(os.path.basename(p)[:-len(".expected.json")] for p in glob.glob(str(PROBES / "*.expected.json")))


def session(tmp_path, commands, program=COUNTER):
    script = tmp_path / "commands.txt"
    script.write_text(commands)
    out, err = io.StringIO(), io.StringIO()
    code = main(["debug", str(program), "--commands", str(script)], out, err)
    assert code == 0, err.getvalue()
    return out.getvalue()


def after(text, command, nth=1):
    """The output of the ``nth`` ``command`` in a transcript (up to the next prompt)."""
    part = text.split(f"(spin) {command}\n")[nth]
    return part.split("(spin) ", 1)[0]


# ----------------------------------------------------------------------------- scripted sessions
def test_a_dat_label_breakpoint_stops_the_pasm_cog_before_that_instruction(tmp_path):
    out = session(tmp_path, "break entry\ncontinue\n")
    assert "breakpoint #1 pasm entry (" in after(out, "break entry")
    stop = after(out, "continue")
    assert "cog 1 at $000 (entry, " in stop and "pasm_counter.spin:14): mov addr, PAR" in stop
    assert "14  entry   mov     addr, par" in stop


def test_stepi_shows_cycle_address_instruction_flags_and_the_value_written(tmp_path):
    out = session(tmp_path, "break entry\ncontinue\nstepi 3\nstep\n")
    lines = after(out, "stepi 3").splitlines()
    assert lines[0].split() == ["936", "cog", "1", "$000", "entry", "mov", "addr,", "PAR", "Z=0", "C=0",
                                "->", "$00000068"]
    assert lines[1].split()[:4] == ["940", "cog", "1", "$001"] and lines[1].endswith("-> $00000000")
    assert "cog 1 at $003 (loop, " in lines[3] and lines[3].endswith("call #bump")
    assert "17  loop    call    #bump" in lines[4]
    step = after(out, "step").splitlines()           # a PASM cog's step is one instruction (into the call)
    assert step[0].split()[:6] == ["948", "cog", "1", "$003", "loop", "call"]
    assert "cog 1 at $00A (bump, " in step[1]


def test_next_runs_over_a_call(tmp_path):
    out = session(tmp_path, "break loop\ncontinue\nnext\nprint n\n")
    assert "cog 1 at $004 (" in after(out, "next") and "wrlong n, addr" in after(out, "next")
    assert after(out, "print n").strip() == "n = 1 ($00000001)"


def test_a_cog_address_breakpoint_with_a_condition_on_registers(tmp_path):
    out = session(tmp_path, "break cog 1 @$007 if n == 3\ncontinue\nprint n\nbreak cog 1 @bump\ncontinue\n")
    assert "breakpoint #1 pasm cog 1 @$007 if n == 3 (hit 0 times)" in after(out, "break cog 1 @$007 if n == 3")
    assert "cog 1 at $007 (" in after(out, "continue") and "if_nz jmp #loop" in after(out, "continue")
    assert after(out, "print n").strip() == "n = 3 ($00000003)"
    assert "breakpoint #2 pasm cog 1 @bump ($00A)" in after(out, "continue", 2)


def test_a_dat_line_breakpoint_and_list(tmp_path):
    out = session(tmp_path, f"break {COUNTER}:22\ncontinue\nlist\n")
    assert after(out, f"break {COUNTER}:22").startswith("breakpoint #1 pasm ")
    assert "pasm_counter.spin:22 (hit 0 times)" in after(out, f"break {COUNTER}:22")
    assert "cog 1 at $008 (" in after(out, "continue") and "cogid n" in after(out, "continue")
    assert "=>   22          cogid   n" in after(out, "list")


def test_regs_print_and_set_read_and_write_a_pasm_cogs_registers_by_label(tmp_path):
    out = session(tmp_path, "break bump\ncontinue\ncontinue\nregs\nset n = 4\nprint n + 1\nstepi\n")
    regs = after(out, "regs").splitlines()
    assert "cog 1 at $00A (bump, " in regs[0]
    assert regs[1].split()[:3] == ["Z=0", "C=0", "PAR"] and "DIRA $00000001" in regs[1]
    assert regs[2].split() == ["$00C", "addr", "=", "104", "($00000068)"]
    assert regs[3].split() == ["$00D", "n", "=", "1", "($00000001)"]
    assert regs[4].split()[:2] == ["$00E", "spare"]              # a RES label names the register after it
    assert after(out, "print n + 1").strip() == "n + 1 = 5 ($00000005)"
    assert after(out, "stepi").splitlines()[0].endswith("-> $00000005")


def test_a_watchpoint_stops_after_a_pasm_wrlong(tmp_path):
    out = session(tmp_path, "watch count\ncontinue\ncontinue\n")
    first = after(out, "continue")
    assert "watchpoint count: cog 1 at $004 (" in first and "wrlong n, addr writes it: 0 -> 1" in first
    assert "18          wrlong  n, addr" in first
    assert "writes it: 1 -> 2" in after(out, "continue", 2)


def test_a_pin_breakpoint_stops_after_the_pasm_instruction_that_changed_it(tmp_path):
    out = session(tmp_path, "break pin 0\ncontinue\ncontinue\n")
    assert "pin P0: input -> low (cog 1 at $002 (" in after(out, "continue")
    assert "pin P0: low -> high (cog 1 at $005 (" in after(out, "continue", 2)


def test_pasm_mistakes_are_explained(tmp_path):
    out = session(tmp_path, "break entry\ncontinue\nfinish\nbreak cog 1 @nosuch\nbreak cog 1\ncog 0\nregs\n"
                            "break nosuch\n")
    assert "error: cog 1 runs PASM: it has no method to finish" in after(out, "finish")
    assert "error: cog 1 runs no PASM code with a label 'nosuch'" in after(out, "break cog 1 @nosuch")
    assert "error: break cog N @ADDR" in after(out, "break cog 1")
    assert "error: cog 0 runs Spin" in after(out, "regs")
    assert "error: no line, file:line, method or DAT label 'nosuch'" in after(out, "break nosuch")


# ----------------------------------------------------------------------------- the same run
def _probe(name):
    with open(PROBES / f"{name}.expected.json") as f:
        return json.load(f)


def _free_run(name):
    r = Chip(compile_file(str(PROBES / f"{name}.spin")).binary).run(max_cycles=50_000_000)
    return r.end_cycle, r.trace.changes, r.hub


def _ended(dbg):
    r = dbg.chip.result(dbg.ended)
    return r.end_cycle, r.trace.changes, r.hub


@pytest.mark.parametrize("name", [n for n in NAMES if n != "spin_pasm"])
def test_stopping_before_every_pasm_instruction_gives_the_same_run(name):
    """Breakpoints on every cog address of every cog: the stops are spinsim's instructions, in
    order, at their cycles, and the run ends with the free run's pins, hub RAM and cycle."""
    expected = _probe(name)
    dbg = Debugger(str(PROBES / f"{name}.spin"))
    for cog in range(1, 8):
        for k in range(512):
            dbg.break_pasm(cog, k)
    seen: dict = {}
    while (stop := dbg.cont()).reason == "breakpoint":
        seen.setdefault(str(stop.cog), []).append([stop.cycle, dbg.chip.cogs[stop.cog].pc])
    assert seen == {k: [s[:2] for s in v] for k, v in expected["steps"].items()}
    assert _ended(dbg) == _free_run(name)
    assert hashlib.sha256(_ended(dbg)[2]).hexdigest() == expected["hub_sha256"]


@pytest.mark.parametrize("name", NAMES)
def test_stepping_pasm_cogs_gives_the_same_run(name):
    """stepi of random lengths on each PASM cog as it starts: each instruction a step shows is
    one spinsim ran at that cycle, and the run ends as the free run does."""
    expected = _probe(name)
    rnd = random.Random(name)
    dbg = Debugger(str(PROBES / f"{name}.spin"))
    for cog in range(1, 8):
        dbg.break_pasm(cog, 0)
    last = max((v[-1][0] for v in expected["steps"].values()), default=0)
    shown = 0
    stop = dbg.cont()
    while stop.reason != "end":
        c = dbg.chip.cogs[stop.cog] if stop.cog is not None else None
        if dbg.now > last:                                      # past what was recorded: to the end
            dbg.delete()
            stop = dbg.cont()
        elif c is not None and c.engine != "spin" and c.state != "stopped":
            stop = dbg.stepi(rnd.randint(1, 5), cog=stop.cog)
            for s in stop.steps:                                # (another cog's breakpoint may end it)
                recorded = expected["steps"][str(s.cog)]
                if s.cycle > recorded[-1][0]:
                    continue                                    # past what was recorded
                got = [s.cycle, s.pc, s.word, s.executed, s.result, s.z, s.c]
                assert any(all(w is None or w == g for w, g in zip(rec, got)) for rec in recorded), s.text()
                shown += 1
        else:
            stop = dbg.cont()
    assert shown >= min(200, sum(len(v) for v in expected["steps"].values()))
    assert _ended(dbg) == _free_run(name)


def test_the_python_api_steps_a_pasm_cog():
    dbg = Debugger(str(COUNTER))
    bp = dbg.break_at("bump")
    stop = dbg.cont()
    assert stop.reason == "breakpoint" and stop.breakpoint is bp and stop.cog == 1
    assert dbg.pasm_symbols(1)[10] == "bump" and dbg.value("n") == 0
    stop = dbg.stepi(2)
    assert [(s.pc, s.result) for s in stop.steps] == [(10, 1), (11, None)]
    assert dbg.registers(1)[:2] == [(12, "addr", 0x68), (13, "n", 1)]
    with pytest.raises(DebugError, match="no method to finish"):
        dbg.finish()


def test_the_documented_pasm_session_prints_what_the_docs_show(update_golden, monkeypatch):
    monkeypatch.chdir(ROOT)                          # the transcript shows paths relative to the project
    script = ROOT / "docs" / "examples" / "debug_pasm.txt"
    golden = ROOT / "docs" / "examples" / "debug_pasm.out"
    out, err = io.StringIO(), io.StringIO()
    assert main(["debug", "spin_src/accel/fast_demo.spin", "--commands", str(script)], out, err) == 0
    if update_golden:
        golden.write_text(out.getvalue())
    assert out.getvalue() == golden.read_text()
    assert golden.read_text() in (ROOT / "docs" / "debugger.md").read_text()
