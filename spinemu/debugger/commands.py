"""``spinemu debug PROG``: a small command loop around :class:`~spinemu.debugger.session.Debugger`.

Commands are read from the terminal (with a ``(spin)`` prompt) or, with
``--commands FILE``, from a file (each echoed after the prompt, so a
session's transcript reads like an interactive one; ``#`` starts a
comment).  Output is rendered with rich.  ``help`` lists the commands.
"""
from __future__ import annotations

import re
from typing import Callable, Optional

from .expr import ExpressionError
from .frames import short_path, signed
from .session import DebugError, Debugger

__all__ = ["CommandLoop", "HELP", "parse_duration"]

PROMPT = "(spin) "

HELP = """\
break LOCATION [if COND]   stop before a line runs: LINE, FILE:LINE, METHOD or OBJECT.METHOD;
                           a DAT label or DAT line: before a PASM cog runs that instruction
break cog N @ADDR [if C]   stop PASM cog N before it runs cog address ADDR ($01A or a DAT label)
break pin N                stop after a bytecode or PASM instruction changes pin N
break if COND              stop at the first Spin line (any cog) where COND holds
watch NAME                 stop after a bytecode or PASM WRxxxx writes VAR/DAT variable NAME
delete [N]                 delete breakpoint N (all without N)
info breakpoints           list the breakpoints
continue [TIME]            run until a breakpoint, the end, or TIME more (10ms, 2s, 5000 cycles)
step [N] / next [N]        the selected cog's next Spin line, into / over calls
                           (a PASM cog: N instructions / over a call)
finish                     run until the selected cog's method returns
stepi [N]                  N bytecodes (a PASM cog: instructions) of the selected cog
until LOCATION             run to a location
run TIME                   let TIME pass (breakpoints still stop it)
cog N                      select cog N (step, next, print and bt follow it)
cogs                       where every cog is
regs                       the selected PASM cog's registers by DAT label, its flags and PC
bt [all]                   the call stack of the selected cog (all: of every cog), with values
frame N / up / down        select a frame of the selected cog's stack
print EXPR                 a local, parameter, result, VAR/DAT variable, register or expression
                           (a PASM cog: its registers by DAT label, cnt, ina, outa, dira, par)
set NAME = VALUE           write a local, a PASM cog's register or a VAR/DAT variable
list                       the source around the selected cog's line
time                       the current cycle
help / quit"""

_UNITS = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9}


def parse_duration(text: str, clock_hz: int) -> int:
    """Cycles in ``"10ms"``, ``"2s"``, ``"1_000"`` (cycles) or ``"5000 cycles"``.

    >>> parse_duration("10ms", 80_000_000), parse_duration("1_000", 80_000_000)
    (800000, 1000)
    """
    t = text.strip().lower().replace("_", "").replace("cycles", "").strip()
    m = re.fullmatch(r"([0-9.]+)\s*(s|ms|us|ns)?", t)
    if not m:
        raise DebugError(f"cannot read {text!r} as a time (10ms, 2s, 5000 cycles)")
    value, unit = float(m.group(1)), m.group(2)
    if unit is None:
        return int(value)
    return max(1, int(round(value * _UNITS[unit] * clock_hz)))


class CommandLoop:
    """Reads commands and prints what they do on a rich console.

    Args:
        debugger: the :class:`Debugger`.
        console: a ``rich.console.Console`` for the output.
        echo: print each command after the prompt (for command files).
    """

    def __init__(self, debugger: Debugger, console, echo: bool = False):
        self.dbg = debugger
        self.console = console
        self.echo = echo
        self.done = False
        self.commands: dict = {
            "break": self.do_break, "b": self.do_break, "watch": self.do_watch, "delete": self.do_delete,
            "info": self.do_info, "continue": self.do_continue, "c": self.do_continue,
            "step": self.do_step, "s": self.do_step, "next": self.do_next, "n": self.do_next,
            "finish": self.do_finish, "stepi": self.do_stepi, "si": self.do_stepi, "until": self.do_until,
            "u": self.do_until, "run": self.do_run, "cog": self.do_cog, "cogs": self.do_cogs,
            "bt": self.do_bt, "backtrace": self.do_bt, "where": self.do_bt, "frame": self.do_frame,
            "up": self.do_up, "down": self.do_down, "print": self.do_print, "p": self.do_print,
            "set": self.do_set, "list": self.do_list, "l": self.do_list, "time": self.do_time,
            "regs": self.do_regs, "registers": self.do_regs,
            "help": self.do_help, "quit": self.do_quit, "q": self.do_quit,
        }

    # ------------------------------------------------------------------ running
    def say(self, text: str = "", style: Optional[str] = None) -> None:
        self.console.print(text, markup=False, highlight=False, style=style, soft_wrap=True)

    def run_lines(self, lines) -> None:
        """Run commands from an iterable of lines until ``quit`` or the end."""
        for raw in lines:
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            if self.echo:
                self.say(PROMPT + line, style="bold")
            self.execute(line)
            if self.done:
                return

    def interactive(self, read: Callable[[str], str]) -> None:
        """Prompt with ``read(prompt)`` until ``quit`` or end of input."""
        while not self.done:
            try:
                line = read(PROMPT)
            except EOFError:
                return
            if line.strip():
                self.execute(line.strip())

    def execute(self, line: str) -> None:
        word, _, rest = line.partition(" ")
        fn = self.commands.get(word.lower())
        if fn is None:
            self.say(f"unknown command '{word}' (try help)", style="red")
            return
        try:
            fn(rest.strip())
        except (DebugError, ExpressionError) as e:
            self.say(f"error: {getattr(e, 'message', None) or e}", style="red")

    def show_stop(self, stop) -> None:
        self.say(stop.detail, style="yellow" if stop.reason in ("end", "limit") else "green")
        if stop.cog is not None and stop.reason not in ("end", "limit"):
            self._show_line(stop.cog, stop.pc)
        for w in self._new_warnings():
            self.say(w, style="magenta")

    def _new_warnings(self):
        log = self.dbg.chip.warning_log
        if log is None:
            return []
        seen = getattr(self, "_warned", 0)
        self._warned = len(log.items)
        return [w.render() for w in log.items[seen:]]

    def _show_line(self, cog: int, pc: Optional[int] = None) -> None:
        c = self.dbg.chip.cogs[cog]
        pos = self.dbg.info.position(c.pc if pc is None else pc)
        if pos is not None and c.state != "stopped":
            text = self.dbg.info.source_line(pos[0], pos[1]) or ""
            self.say(f"{pos[1]:>6}  {text.rstrip()}")

    # ------------------------------------------------------------------ breakpoints
    def do_break(self, arg: str) -> None:
        if not arg:
            raise DebugError("break what? (break 42, break stepper.spin:42, break pin 5, break if x == 3)")
        low = arg.lower()
        m = re.fullmatch(r"cog\s+(\S+)\s+@\s*(\S+)(?:\s+if\s+(.+))?", arg.strip(), re.IGNORECASE)
        if m:
            where = m.group(2)
            spot = _int(where) if where[:1].isdigit() or where[:1] == "$" else where
            bp = self.dbg.break_pasm(_int(m.group(1)), spot, m.group(3))
            self.say(f"breakpoint {bp.describe()}")
            return
        if low.startswith("cog "):
            raise DebugError("break cog N @ADDR (a cog address such as $01A, or a DAT label: break cog 1 @loop)")
        if low.startswith("pin "):
            bp = self.dbg.break_on_pin(_int(arg[4:]))
        elif low.startswith("if "):
            bp = self.dbg.break_if(arg[3:])
        else:
            loc, _, cond = arg.partition(" if ")
            bp = self.dbg.break_at(loc.strip(), cond.strip() or None)
        self.say(f"breakpoint {bp.describe()}")

    def do_watch(self, arg: str) -> None:
        bp = self.dbg.watch(arg)
        inst, v = bp.var
        self.say(f"watchpoint #{bp.number} on {v.describe()} ({v.section} of "
                 f"{short_path(inst.obj.path)}, ${v.addr:04X})")

    def do_delete(self, arg: str) -> None:
        self.dbg.delete(_int(arg.lstrip("#")) if arg else None)
        self.say("deleted" if arg else "all breakpoints deleted")

    def do_info(self, arg: str) -> None:
        if arg.startswith("b"):
            if not self.dbg.breakpoints:
                self.say("no breakpoints")
            for bp in self.dbg.breakpoints:
                self.say(bp.describe())
        elif arg.startswith("c"):
            self.do_cogs("")
        elif arg.startswith("r"):
            self.do_regs("")
        elif arg.startswith("w"):
            log = self.dbg.chip.warning_log
            for w in (log.items if log else []):
                self.say(w.render())
        else:
            raise DebugError("info breakpoints | info cogs | info registers | info warnings")

    # ------------------------------------------------------------------ running
    def _time(self, arg: str) -> Optional[int]:
        return parse_duration(arg, self.dbg.chip.clock_hz) if arg else None

    def do_continue(self, arg: str) -> None:
        self.show_stop(self.dbg.cont(self._time(arg)))

    def _repeat(self, fn, arg: str) -> None:
        n = _int(arg) if arg else 1
        stop = None
        for _ in range(n):
            stop = fn()
            if stop.reason != "step":
                break
        self.show_stop(stop)

    def do_step(self, arg: str) -> None:
        if self.dbg.cog().kind == "pasm":
            self.do_stepi(arg)                  # a PASM cog's step is an instruction
            return
        self._repeat(self.dbg.step, arg)

    def do_next(self, arg: str) -> None:
        self._repeat(self.dbg.next, arg)

    def do_finish(self, arg: str) -> None:
        self.show_stop(self.dbg.finish())

    def do_stepi(self, arg: str) -> None:
        self.show_stop(self.dbg.stepi(_int(arg) if arg else 1))

    def do_until(self, arg: str) -> None:
        self.show_stop(self.dbg.run_to(arg))

    def do_run(self, arg: str) -> None:
        if not arg:
            raise DebugError("run how long? (run 10ms, run 2s, run 5000)")
        self.show_stop(self.dbg.run_for(self._time(arg)))

    def do_time(self, arg: str) -> None:
        clock = self.dbg.chip.clock_hz
        self.say(f"cycle {self.dbg.now:,} ({self.dbg.now / clock * 1e3:.3f} ms at {clock / 1e6:g} MHz)")

    # ------------------------------------------------------------------ cogs and frames
    def do_cog(self, arg: str) -> None:
        self.dbg.select(_int(arg))
        self.say(self.dbg.cog().describe())

    def do_cogs(self, arg: str) -> None:
        from rich.table import Table

        table = Table(box=None, pad_edge=False, show_header=True, header_style="bold")
        for col in ("cog", "state", "where", "method"):
            table.add_column(col)
        for view in self.dbg.cogs():
            frames = view.frames()
            mark = "*" if view.id == self.dbg.selected else " "
            if frames:
                f = frames[0]
                table.add_row(f"{mark}{view.id}", view.state, f.place(), f.signature())
            else:
                table.add_row(f"{mark}{view.id}", view.state, view.place(), "")
        self.console.print(table)

    def do_bt(self, arg: str) -> None:
        views = self.dbg.cogs() if arg.strip() == "all" else [self.dbg.cog()]
        for view in views:
            self.say(f"cog {view.id} ({view.state}):", style="bold")
            frames = view.frames()
            if not frames:
                self.say("  " + view.place())
            for i, f in enumerate(frames):
                mark = ">" if view.id == self.dbg.selected and i == self.dbg.frame_index else " "
                self.say(f"{mark} #{i} {f.describe()}")
                for name, values in f.array_values.items():
                    shown = ", ".join(str(signed(v)) for v in values[:8]) + (", ..." if len(values) > 8 else "")
                    self.say(f"      {name}[{len(values)}] = {shown}")

    def do_regs(self, arg: str) -> None:
        view = self.dbg.cog()
        if view.kind != "pasm":
            raise DebugError(f"cog {view.id} runs Spin: 'bt' shows its locals, 'print' its variables")
        c = self.dbg.chip.cogs[view.id]
        flags = c.ram[512]
        self.say(f"cog {view.id} at {self.dbg.pasm_where(c)}")
        self.say(f"  Z={flags & 1} C={flags >> 1}  PAR ${c.par:04X}  OUTA ${c.outa:08X}  DIRA ${c.dira:08X}  "
                 f"loaded from hub ${c.code_addr:04X}")
        for k, label, value in self.dbg.registers(view.id):
            self.say(f"  ${k:03X} {label:<12} = {signed(value)} (${value:08X})")

    def do_frame(self, arg: str) -> None:
        frames = self.dbg.stack()
        n = _int(arg) if arg else self.dbg.frame_index
        if not 0 <= n < len(frames):
            raise DebugError(f"cog {self.dbg.selected} has frames #0..#{len(frames) - 1}")
        self.dbg.frame_index = n
        self.say(f"#{n} {frames[n].describe()}")

    def do_up(self, arg: str) -> None:
        self.do_frame(str(min(self.dbg.frame_index + 1, len(self.dbg.stack()) - 1)))

    def do_down(self, arg: str) -> None:
        self.do_frame(str(max(self.dbg.frame_index - 1, 0)))

    # ------------------------------------------------------------------ values
    def do_print(self, arg: str) -> None:
        if not arg:
            raise DebugError("print what? (print mode, print motor.stack[3], print timer + 1)")
        name = arg.strip()
        plain = re.fullmatch(r"[A-Za-z_][\w.]*", name)
        if plain:
            found = self._array(name)
            if found is not None:
                self.say(found)
                return
        value = self.dbg.evaluate(name)
        if isinstance(value, bool):
            self.say(f"{name} = {'TRUE' if value else 'FALSE'}")
        else:
            v = signed(value & 0xFFFFFFFF) if isinstance(value, int) else value
            self.say(f"{name} = {v} (${value & 0xFFFFFFFF:08X})")

    def _array(self, name: str) -> Optional[str]:
        """All elements of an array variable or local, or None for a single long."""
        frame = self.dbg._frame()
        if frame is not None and "." not in name:
            for slot in (frame.method.slots if frame.method else []):
                if slot.name.lower() == name.lower() and slot.count > 1:
                    vals = frame.array_values.get(slot.name, [])
                    return f"{name}[{slot.count}] = " + ", ".join(str(signed(v)) for v in vals)
                if slot.name.lower() == name.lower():
                    return None
        found = self.dbg.variable(name)
        if found is None or found[1].count == 1:
            return None
        v = found[1]
        vals = [self.dbg._read_var(v, k) for k in range(min(v.count, 64))]
        return f"{name}[{v.count}] = " + ", ".join(map(str, vals)) + (", ..." if v.count > 64 else "")

    def do_set(self, arg: str) -> None:
        m = re.fullmatch(r"([A-Za-z_][\w.]*)\s*(?:\[\s*(\d+)\s*\])?\s*:?=\s*(.+)", arg.strip())
        if not m:
            raise DebugError("set NAME = VALUE (or NAME[i] = VALUE)")
        value = self.dbg.evaluate(m.group(3))
        index = int(m.group(2)) if m.group(2) else None
        self.dbg.set_value(m.group(1), int(value), index)
        self.say(f"{m.group(1)}{'[' + m.group(2) + ']' if m.group(2) else ''} = {signed(int(value) & 0xFFFFFFFF)}")

    def do_list(self, arg: str) -> None:
        frame = self.dbg._frame()
        place = (frame.path, frame.line) if frame is not None else self.dbg.pasm_line()
        if place is None or place[0] is None:
            raise DebugError("no source line for the selected cog")
        path, line = place
        for n, text in self.dbg.source_lines(path, line):
            mark = "=>" if n == line else "  "
            self.say(f"{mark}{n:>5}  {text.rstrip()}")

    def do_help(self, arg: str) -> None:
        self.say(HELP)

    def do_quit(self, arg: str) -> None:
        self.done = True


def _int(text: str) -> int:
    """A number as Spin or Python writes it: ``12``, ``$1A``, ``%1010``, ``0x1A``."""
    t = text.strip().replace("_", "")
    try:
        if t[:1] == "$":
            return int(t[1:], 16)
        if t[:1] == "%":
            return int(t[1:], 2)
        return int(t, 0)
    except ValueError:
        raise DebugError(f"expected a number, got {text.strip()!r}") from None
