"""The debugger's Python API: :class:`Debugger`.

A :class:`Debugger` runs a program on a :class:`spinemu.chip.Chip` with
itself attached as the chip's *probe*: the scheduler then runs cogs through
its instrumented loop (``Scheduler._run_spin_probed``), which calls
:meth:`Debugger.before` and :meth:`Debugger.after` around every bytecode;
either raises :class:`~spinemu.chip.control.Halted` to stop the whole chip
between two bytecodes.  Compiled blocks and busy-loop fast-forward are off
in a debug session (results are the same; each bytecode is seen).

What can stop a run (each a :class:`Breakpoint`):

* a **line** (``file:line``, ``line``, ``method`` or ``object.method``):
  before the first bytecode of each run of bytecode the line compiled to;
* a **pin change** (``pin N``): after the bytecode that changed the pin's
  direction or level (the chip's pin hooks);
* a **watchpoint** on a VAR/DAT variable (``watch NAME``): after a bytecode
  that wrote any of its bytes (the chip's ``watch`` bits: writes to watched
  longs already leave the fast path);
* a **condition** (``break if EXPR``, or a line breakpoint ``... if EXPR``):
  checked at the start of every Spin line of every cog, in that cog's frame;
* a **PASM instruction** (a DAT label, a DAT line, or ``cog N @$01A``):
  before a PASM cog runs it (:mod:`spinemu.debugger.pasm_cogs`).

Stepping (:meth:`Debugger.step`, :meth:`~Debugger.next`,
:meth:`~Debugger.finish`, :meth:`~Debugger.stepi`) follows one cog while
every cog runs: a Spin cog by line or bytecode, a PASM cog by instruction
(:mod:`spinemu.debugger.pasm_cogs`).  Cogs are read through views
(:mod:`spinemu.debugger.frames`) chosen by what runs them.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Optional

from ..chip.blocks import WATCHPOINT
from ..chip.cog import RUNNING, STOPPED
from ..chip.control import Halted
from ..diagnostics import SpinError
from .expr import REGISTERS, Expression, ExpressionError
from .frames import cog_view, short_path, signed
from .pasm_cogs import PasmDebugging, is_pasm

__all__ = ["Debugger", "Breakpoint", "Stop", "DebugError"]


class DebugError(SpinError):
    """A debugger command that cannot be done (unknown line, variable, cog ...)."""


@dataclass
class Breakpoint:
    """A place or event that stops the run.

    Attributes:
        number: its number (for ``delete``).
        kind: ``"line"``, ``"pin"``, ``"watch"``, ``"condition"`` or ``"pasm"``.
        text: how it was given.
        addrs: for a line breakpoint, the bytecode addresses it stops at.
        hubs: the hub addresses of PASM instructions it stops at (in any
            PASM cog loaded with them): a DAT label or a DAT line.
        cog_addr: ``(cog, cog address)`` for ``break cog N @ADDR``.
        pin: for a pin breakpoint.
        var: for a watchpoint, ``(Instance, Variable)``.
        condition: an :class:`~spinemu.debugger.expr.Expression`, or ``None``.
        hits: how often it stopped the run.
        temporary: deleted after its first hit (``until``).
    """

    number: int
    kind: str
    text: str
    addrs: frozenset = frozenset()
    hubs: frozenset = frozenset()
    cog_addr: Optional[tuple] = None
    pin: Optional[int] = None
    var: Optional[tuple] = None
    condition: Optional[Expression] = None
    hits: int = 0
    temporary: bool = False
    last: bool = False                              # condition: its value where last evaluated

    def describe(self) -> str:
        cond = f" if {self.condition.text}" if self.condition is not None and self.kind != "condition" else ""
        return f"#{self.number} {self.kind} {self.text}{cond} (hit {self.hits} time{'s' if self.hits != 1 else ''})"


@dataclass
class Stop:
    """Why and where the run stopped.

    Attributes:
        reason: ``"breakpoint"``, ``"watchpoint"``, ``"pin"``, ``"condition"``,
            ``"step"``, ``"end"`` (the program ended), ``"limit"`` (the time
            asked for passed) or ``"interrupted"``.
        cog: the cog it is about (``None`` for the end or a limit).
        cycle: when.
        detail: one line for people.
        breakpoint: the :class:`Breakpoint` that stopped it, if any.
        pc: the bytecode it is about (the writer's, for a pin or a
            watchpoint); for a PASM cog, the hub address of the instruction
            (-1 for none).
        steps: the PASM instructions a step ran
            (:class:`~spinemu.chip.pasm_cog.PasmStep`).
    """

    reason: str
    cog: Optional[int]
    cycle: int
    detail: str
    breakpoint: Optional[Breakpoint] = None
    pc: Optional[int] = None
    steps: list = field(default_factory=list)

    def __str__(self) -> str:
        return self.detail


@dataclass
class _Step:
    kind: str                   # "step", "next", "finish", "stepi"; "pasm-stepi", "pasm-next"
    cog: int
    line: tuple = ()
    dbase: int = 0
    count: int = 0
    method: Optional[str] = None
    drops_result: bool = False
    target: int = -1            # pasm-next: the cog address after the call


class Debugger(PasmDebugging):
    """A program under the debugger.

    Args:
        target: a ``.spin`` file (compiled, with names and lines) or a
            :class:`~spinemu.compiler.CompiledProgram`.
        include_dirs, defines: for compiling.
        compat, inputs: as for :class:`spinemu.chip.Chip`.
        warn: runtime warnings (``True``, ``False`` or a ``WarningLog``).
    """

    def __init__(self, target, include_dirs=(), *, compat: str = "spinsim", inputs=None, warn=True,
                 defines=()):
        from ..chip import Chip
        from ..compiler import compile_file

        if isinstance(target, (str, os.PathLike)):
            path = os.fspath(target)
            if not path.lower().endswith(".spin"):
                raise DebugError("the debugger needs a .spin source (for its names and lines)", path=path)
            if not os.path.exists(path):
                raise SpinError("no such file", path=path)
            self.program = compile_file(path, include_dirs, defines=defines)
        else:
            self.program = target
        self.info = self.program.debug_info()
        self.chip = Chip(self.program.binary, compat=compat, inputs=inputs, debug_info=self.info, warn=warn,
                         fast_forward=False, compile_blocks=False)
        self.chip.probe = self
        self.chip.pin_hooks.append(self._on_pins)
        self.chip.write_hooks.append(self._on_write)
        self.breakpoints: list = []
        self.selected = 0           # the cog step/next/finish/print follow
        self.frame_index = 0        # the frame of the selected cog that print/list look at
        self.ended: Optional[str] = None
        self._numbers = 0
        self._line_addrs: dict = {}         # bytecode address -> [line Breakpoint]
        self._line_starts = {a for a, _p, _l in self.info.line_starts()}
        self._conditions: list = []
        self._pin_bps: list = []
        self._pin_levels: dict = {}
        self._watch_bps: list = []
        self._pending: Optional[Stop] = None
        self._step: Optional[_Step] = None
        self._skip: Optional[tuple] = None  # (cog, pc): resume there without stopping again
        self._interrupt = False
        self.last_stop: Optional[Stop] = None
        self._init_pasm()
        self.chip.advance(0)                # boot: cog 0 is at the first method's first bytecode

    # ------------------------------------------------------------------ time and cogs
    @property
    def now(self) -> int:
        return self.chip.now

    def cogs(self) -> list:
        """Views of the cogs that are not stopped (:mod:`spinemu.debugger.frames`)."""
        return [v for c in self.chip.cogs if (v := cog_view(self.chip, c, self.info)) is not None]

    def cog(self, n: Optional[int] = None):
        n = self.selected if n is None else n
        if not 0 <= n < 8:
            raise DebugError(f"there is no cog {n} (cogs are 0..7)")
        view = cog_view(self.chip, self.chip.cogs[n], self.info)
        if view is None:
            raise DebugError(f"cog {n} is not running")
        return view

    def stack(self, n: Optional[int] = None) -> list:
        """Cog ``n``'s call stack (innermost first): :class:`~spinemu.debugger.frames.Frame` records."""
        return self.cog(n).frames()

    def select(self, n: int) -> None:
        self.cog(n)
        self.selected = n
        self.frame_index = 0

    # ------------------------------------------------------------------ breakpoints
    def _add(self, bp: Breakpoint) -> Breakpoint:
        self.breakpoints.append(bp)
        self._add_pasm(bp)
        if bp.kind == "line":
            for a in bp.addrs:
                self._line_addrs.setdefault(a, []).append(bp)
        elif bp.kind == "condition":
            self._conditions.append(bp)
        elif bp.kind == "pin":
            self._pin_bps.append(bp)
            self._pin_levels[bp.pin] = self._pin_now(bp.pin)
        elif bp.kind == "watch":
            self._watch_bps.append(bp)
            _inst, v = bp.var
            for k in range(v.addr >> 2, ((v.end - 1) >> 2) + 1):
                self.chip.watch[k] |= WATCHPOINT
        return bp

    def _number(self) -> int:
        self._numbers += 1
        return self._numbers

    def _breakpoint(self, kind: str, text: str, **kw) -> Breakpoint:
        return Breakpoint(self._number(), kind, text, **kw)

    @staticmethod
    def _error(message: str) -> DebugError:
        return DebugError(message)

    def break_at(self, location: str, condition: Optional[str] = None, temporary: bool = False) -> Breakpoint:
        """Stop before a Spin line runs: ``"42"``, ``"stepper.spin:42"``, ``"runStepper"`` or ``"motor.setMode"``.

        A DAT line or a DAT label (``"loop"``, ``"obj.loop"``) stops a PASM
        cog before it runs the instruction loaded from there (any PASM cog
        loaded with that code).

        Raises:
            DebugError: no code was made from that line, or no such method or label.
        """
        addrs, text = self._resolve_location(location)
        spin, dat = self._pasm_location(addrs)
        cond = Expression(condition) if condition else None
        return self._add(Breakpoint(self._number(), "line" if spin else "pasm", text, frozenset(spin),
                                    frozenset(dat), condition=cond, temporary=temporary))

    def break_on_pin(self, pin: int) -> Breakpoint:
        """Stop after a bytecode changes pin ``pin`` (its level or whether it is driven)."""
        if not 0 <= pin < 32:
            raise DebugError(f"there is no pin {pin} (pins are 0..31)")
        return self._add(Breakpoint(self._number(), "pin", f"P{pin}", pin=pin))

    def watch(self, name: str) -> Breakpoint:
        """Stop after a bytecode writes any byte of VAR/DAT variable ``name`` (``obj.name`` for a child's)."""
        base = name.split("[")[0].strip()
        found = self.info.find_variable(base)
        if found is None:
            found = self._unique_variable(base)
        if found is None:
            raise DebugError(f"no VAR or DAT variable '{base}' (a child's is written obj.name)")
        return self._add(Breakpoint(self._number(), "watch", base, var=found))

    def break_if(self, condition: str) -> Breakpoint:
        """Stop at the start of the first Spin line (of any cog) where ``condition`` holds."""
        return self._add(Breakpoint(self._number(), "condition", condition, condition=Expression(condition)))

    def delete(self, number: Optional[int] = None) -> None:
        """Delete breakpoint ``number`` (all of them with ``None``)."""
        doomed = [b for b in self.breakpoints if number is None or b.number == number]
        if number is not None and not doomed:
            raise DebugError(f"there is no breakpoint #{number}")
        for bp in doomed:
            self.breakpoints.remove(bp)
            self._delete_pasm(bp)
            if bp.kind == "line":
                for a in bp.addrs:
                    self._line_addrs[a].remove(bp)
                    if not self._line_addrs[a]:
                        del self._line_addrs[a]
            elif bp.kind == "condition":
                self._conditions.remove(bp)
            elif bp.kind == "pin":
                self._pin_bps.remove(bp)
            elif bp.kind == "watch":
                self._watch_bps.remove(bp)
                self._rewatch()

    def _rewatch(self) -> None:
        watch = self.chip.watch
        for k in range(len(watch)):
            if watch[k] & WATCHPOINT:
                watch[k] &= ~WATCHPOINT
        for bp in self._watch_bps:
            v = bp.var[1]
            for k in range(v.addr >> 2, ((v.end - 1) >> 2) + 1):
                watch[k] |= WATCHPOINT

    def _resolve_location(self, location: str):
        loc = location.strip()
        path, line = None, None
        if ":" in loc and loc.rsplit(":", 1)[1].isdigit():
            fname, num = loc.rsplit(":", 1)
            path, line = self._find_file(fname), int(num)
        elif loc.isdigit():
            path, line = self.info.top.obj.path, int(loc)
        if line is not None:
            addrs = [a for a, p, ln in self.info.line_starts() if p == path and ln == line]
            if not addrs:
                raise DebugError(f"no code was made from {short_path(path)}:{line} "
                                 f"(a comment, a declaration or a blank line?)")
            return addrs, f"{short_path(path)}:{line}"
        try:
            method = self._find_method(loc)
        except DebugError:
            label = self._pasm_label(loc)
            if label is None:
                raise
            return [label[0]], label[1]
        return [method.start], f"{loc} ({short_path(method.path)}:{self.info.position(method.start)[1]})"

    def _find_file(self, fname: str) -> str:
        paths = list(self.info.sources)
        for p in paths:
            if os.path.normpath(p) == os.path.normpath(fname) or os.path.abspath(p) == os.path.abspath(fname):
                return p
        base = [p for p in paths if os.path.basename(p).lower() == os.path.basename(fname).lower()]
        if len(base) == 1:
            return base[0]
        raise DebugError(f"no source file '{fname}' in this program (files: "
                         f"{', '.join(os.path.basename(p) for p in paths)})")

    def _find_method(self, name: str):
        objname, _, mname = name.rpartition(".")
        if objname:
            inst = self.info.instance_named(objname)
            if inst is None:
                raise DebugError(f"no object '{objname}' in this program")
            cands = [m for m in inst.obj.methods if m.name.lower() == mname.lower()]
        else:
            cands = [m for m in self.info.methods if m.name.lower() == mname.lower()]
        if not cands:
            raise DebugError(f"no line, file:line, method or DAT label '{name}'")
        if len({m.start for m in cands}) > 1:
            raise DebugError(f"'{name}' is a method of several objects: write object.{mname}")
        return cands[0]

    def _unique_variable(self, name: str):
        found = [(inst, v) for inst in self.info.instances() for v in inst.variables()
                 if v.name.lower() == name.lower()]
        return found[0] if len({(v.addr, v.name) for _i, v in found}) == 1 else None

    # ------------------------------------------------------------------ the probe (hot during a session)
    def before(self, chip, c) -> None:
        """Called before every bytecode: line breakpoints, conditions, the end of a step."""
        if self._interrupt:
            self._interrupt = False
            raise self._halt(Stop("interrupted", c.id, c.t, f"interrupted in cog {c.id}"))
        pc = c.pc
        if self._skip is not None and self._skip[0] == c.id:
            skip = self._skip[1] == pc
            self._skip = None
            if skip:
                return
        step = self._step
        if step is not None and step.cog == c.id and step.kind != "stepi" and self._step_done(step, c):
            raise self._halt(self._step_stop(step, c))
        bps = self._line_addrs.get(pc)
        if bps is not None:
            for bp in bps:
                if bp.condition is None or self._holds(bp.condition, c):   # (None: names not here)
                    bp.hits += 1
                    if bp.temporary:
                        self.delete(bp.number)
                    raise self._halt(Stop("breakpoint", c.id, c.t, f"breakpoint {bp.describe()}: cog {c.id} "
                                          f"at {self._where(c)}", bp))
        if self._conditions and pc in self._line_starts:
            for bp in self._conditions:
                holds = self._holds(bp.condition, c)
                if holds is None:                   # names this cog's frame does not have
                    continue
                was, bp.last = bp.last, holds
                if holds and not was:               # it became true
                    bp.hits += 1
                    raise self._halt(Stop("condition", c.id, c.t, f"condition {bp.condition.text} holds: cog "
                                          f"{c.id} at {self._where(c)}", bp))

    def after(self, chip, c, pc: int, t: int) -> None:
        """Called after every bytecode: watchpoints, pin changes, single bytecodes, a cog that stopped."""
        if self._pending is not None:
            stop, self._pending = self._pending, None
            if stop.reason == "watchpoint":
                bp = stop.breakpoint
                inst, v = bp.var
                new = self._read_var(v)
                stop.detail += f" -> {new}"
            raise self._halt(stop)
        step = self._step
        if step is not None and step.cog == c.id:
            if c.state == STOPPED:
                raise self._halt(Stop("step", c.id, t, f"cog {c.id} stopped ({self._stop_reason(c.id)})"))
            if step.kind == "stepi":
                step.count -= 1
                if step.count <= 0:
                    raise self._halt(Stop("step", c.id, c.t, f"cog {c.id} at {self._where(c)}"))

    def _halt(self, stop: Stop) -> Halted:
        if stop.pc is None and stop.cog is not None:
            stop.pc = self.chip.cogs[stop.cog].pc
        self.last_stop = stop
        if stop.cog is not None:
            if stop.cog != self.selected:
                self.frame_index = 0
            self.selected = stop.cog
        self._step = None
        return Halted(stop.reason)

    def _writer(self, c) -> tuple:
        """Where the cog that is changing a pin or writing hub RAM is, and the address its line is found at."""
        if is_pasm(c):
            return self._pasm_writer(c)
        return self._where(c, c.pc - 1), (c.pc - 1) & 0xFFFF

    def _on_pins(self, c, t: int) -> None:
        for bp in self._pin_bps:
            now = self._pin_now(bp.pin, t)
            if now != self._pin_levels.get(bp.pin):
                old = self._pin_levels.get(bp.pin)
                self._pin_levels[bp.pin] = now
                bp.hits += 1
                where, pc = self._writer(c)
                self._pending = Stop("pin", c.id, t, f"pin P{bp.pin}: {_pin_text(old)} -> {_pin_text(now)} "
                                     f"(cog {c.id} at {where})", bp, pc)

    def _on_write(self, c, addr: int, size: int, t: int) -> None:
        a = addr & ~(size - 1)
        for bp in self._watch_bps:
            inst, v = bp.var
            if a < v.end and a + size > v.addr:
                bp.hits += 1
                where, pc = self._writer(c)
                self._pending = Stop("watchpoint", c.id, t, f"watchpoint {v.name}: cog {c.id} at "
                                     f"{where} writes it: {self._read_var(v)}", bp, pc)
                return

    def _pin_now(self, pin: int, t: Optional[int] = None):
        d, o = self.chip.pin_state(self.chip.now if t is None else t)
        return (d >> pin & 1, o >> pin & 1)

    # ------------------------------------------------------------------ stepping
    def _line_of(self, pc: int) -> tuple:
        pos = self.info.position(pc)
        return pos[:2] if pos else ()

    def _step_done(self, step: _Step, c) -> bool:
        if step.kind == "finish":
            return c.dbase < step.dbase or c.dbase >= 0x8000
        if c.pc not in self._line_starts:
            return False
        if step.kind == "next" and c.dbase > step.dbase:
            return False
        return self._line_of(c.pc) != step.line

    def _step_stop(self, step: _Step, c) -> Stop:
        if step.kind == "finish":
            if step.drops_result:
                what = "returned (its caller drops the result)"
            else:
                what = f"returned {signed(self.chip.mem_longs[((c.sp - 4) & 0xFFFF) >> 2])}"
            return Stop("step", c.id, c.t, f"{step.method} {what}: cog {c.id} at {self._where(c)}")
        return Stop("step", c.id, c.t, f"cog {c.id} at {self._where(c)}")

    def _start_step(self, kind: str, cog: Optional[int], count: int = 1) -> None:
        n = self.selected if cog is None else cog
        view = self.cog(n)
        if view.kind == "pasm":
            return self._start_pasm_step(kind, n, count)
        if view.kind != "spin":
            raise DebugError(f"cog {n} does not run Spin bytecode or PASM; the debugger cannot step it "
                             f"('cogs' shows where it is)")
        if self.chip.cogs[n].state != RUNNING and kind != "finish":
            pass                                # it is waiting: the step ends when it goes on
        c = self.chip.cogs[n]
        frames = view.frames()
        drops = bool(self.chip.mem_words[((c.dbase - 8) & 0xFFFF) >> 1] & 1)
        self._step = _Step(kind, n, self._line_of(c.pc), c.dbase, count,
                           frames[0].name if frames else None, drops)
        self.selected = n

    def step(self, cog: Optional[int] = None, limit: Optional[int] = None) -> Stop:
        """Run until cog ``cog`` (default: the selected one) starts another Spin line; into calls.

        On a PASM cog, :meth:`step` and :meth:`stepi` run one instruction (``stepi``: ``count``) and
        :meth:`next` runs over a ``call``; the stop's ``steps`` are the instructions it ran.
        """
        self._start_step("step", cog)
        return self._go(limit)

    def next(self, cog: Optional[int] = None, limit: Optional[int] = None) -> Stop:
        """Like :meth:`step`, but over calls (stops only in this method or after it returns)."""
        self._start_step("next", cog)
        return self._go(limit)

    def finish(self, cog: Optional[int] = None, limit: Optional[int] = None) -> Stop:
        """Run until the cog's current method returns; the stop says what it returned."""
        self._start_step("finish", cog)
        return self._go(limit)

    def stepi(self, count: int = 1, cog: Optional[int] = None, limit: Optional[int] = None) -> Stop:
        """Run ``count`` bytecodes of the cog (every other cog runs alongside)."""
        self._start_step("stepi", cog, count)
        return self._go(limit)

    def cont(self, limit: Optional[int] = None) -> Stop:
        """Run until a breakpoint stops it, the program ends, or ``limit`` more cycles have passed."""
        self._step = None
        return self._go(limit)

    def run_to(self, location: str, limit: Optional[int] = None) -> Stop:
        """Run until ``location`` (a one-time breakpoint)."""
        self.break_at(location, temporary=True)
        return self._go(limit)

    def run_for(self, cycles: int) -> Stop:
        """Let ``cycles`` pass (breakpoints still stop the run)."""
        return self._go(cycles)

    def interrupt(self) -> None:
        """Stop the run at the next bytecode (safe from a signal handler)."""
        self._interrupt = True

    def _go(self, limit: Optional[int]) -> Stop:
        if self.ended is not None:
            self._step = None
            return Stop("end", None, self.chip.now, f"the program has ended ({self.ended})")
        c = self.chip.cogs[self.selected]
        if c.state == RUNNING and c.engine == "spin":
            self._skip = (c.id, c.pc)
        self._sync_pasm()
        until = None if limit is None else self.chip.now + limit
        self.last_stop = None
        self.frame_index = 0
        reason = self.chip.advance(until)
        self._skip = None
        self._step = None
        if self.last_stop is not None:
            return self.last_stop
        if reason == "cycle limit":
            stop = Stop("limit", None, self.chip.now, f"cycle {self.chip.now:,}: the time asked for has passed")
        else:
            self.ended = reason
            stop = Stop("end", None, self.chip.now, f"the program has ended ({reason}) at cycle {self.chip.now:,}")
        self.last_stop = stop
        return stop

    # ------------------------------------------------------------------ values
    def _frame(self):
        frames = self.stack()
        if not frames:
            return None
        return frames[min(self.frame_index, len(frames) - 1)]

    def value(self, name: str, index: Optional[int] = None, cog: Optional[int] = None) -> int:
        """A local, parameter or result of the selected frame, a VAR/DAT variable, or a register."""
        c = self.chip.cogs[self.selected if cog is None else cog]
        frame = self._frame() if cog is None or cog == self.selected else None
        return self._lookup(name, index, c, frame)

    def evaluate(self, text: str, cog: Optional[int] = None):
        """Evaluate an expression (see :mod:`spinemu.debugger.expr`) in the selected frame."""
        c = self.chip.cogs[self.selected if cog is None else cog]
        frame = self._frame() if cog is None or cog == self.selected else None
        try:
            return Expression(text).evaluate(lambda n, i: self._lookup(n, i, c, frame))
        except ExpressionError as e:
            raise DebugError(str(e)) from None

    def _lookup(self, name: str, index: Optional[int], c, frame) -> int:
        low = name.lower()
        if low in REGISTERS and index is None:
            t = self.chip.now
            return {"cnt": t & 0xFFFFFFFF, "ina": self.chip.ina(t), "outa": c.outa, "dira": c.dira,
                    "par": c.par}[low]
        if frame is None and "." not in name and is_pasm(c):
            value = self._pasm_value(c, name, index)       # a register of the PASM cog, by its DAT label
            if value is not None:
                return value
        if frame is not None and frame.method is not None and "." not in name:
            slot = next((s for s in frame.method.slots if s.name.lower() == low), None)
            if slot is not None:
                k = index or 0
                if not 0 <= k < slot.count:
                    raise ExpressionError(f"{name}[{k}]: index outside 0..{slot.count - 1}")
                return signed(self.chip.peek((frame.dbase + slot.offset + 4 * k) & 0xFFFF))
        found = None
        if "." not in name and frame is not None and frame.instance is not None:
            v = frame.instance.find(name)
            found = (frame.instance, v) if v is not None else None
        if found is None:
            found = self.info.find_variable(name) or self._unique_variable(name)
        if found is None:
            raise ExpressionError(f"unknown name '{name}'")
        _inst, v = found
        k = index or 0
        if not 0 <= k < v.count:
            raise ExpressionError(f"{name}[{k}]: index outside 0..{v.count - 1}")
        return self._read_var(v, k)

    def _holds(self, cond: Expression, c) -> bool:
        view = cog_view(self.chip, c, self.info)
        frame = view.frames()[0] if view is not None and view.kind == "spin" else None
        try:
            return bool(cond.evaluate(lambda n, i: self._lookup(n, i, c, frame)))
        except (ExpressionError, ZeroDivisionError):
            return None                     # a name this cog's frame does not have: not here

    def _read_var(self, v, k: int = 0) -> int:
        a = v.addr + k * v.size
        value = self.chip.peek(a, v.size)
        return signed(value) if v.size == 4 else value

    def set_value(self, name: str, value: int, index: Optional[int] = None) -> None:
        """Write a local/parameter of the selected frame, a PASM cog's register (by label) or a VAR/DAT variable."""
        frame = self._frame()
        low = name.lower()
        c = self.chip.cogs[self.selected]
        if frame is None and "." not in name and is_pasm(c) and self._set_pasm_register(c, name, value, index):
            return
        if frame is not None and frame.method is not None and "." not in name:
            slot = next((s for s in frame.method.slots if s.name.lower() == low), None)
            if slot is not None:
                self.chip.poke(frame.dbase + slot.offset + 4 * (index or 0), value)
                return
        found = self.info.find_variable(name) or self._unique_variable(name)
        if found is None:
            raise DebugError(f"unknown name '{name}'")
        v = found[1]
        self.chip.poke(v.addr + (index or 0) * v.size, value & 0xFFFFFFFF, v.size)

    def variable(self, name: str):
        """``(Instance, Variable)`` of a VAR/DAT name (``obj.name``), or ``None``."""
        return self.info.find_variable(name) or self._unique_variable(name)

    # ------------------------------------------------------------------ places
    def _where(self, c, pc: Optional[int] = None) -> str:
        pc = c.pc if pc is None else pc
        pos = self.info.position(pc & 0xFFFF)
        m = self.info.method_at(pc & 0xFFFF)
        where = f"{short_path(pos[0])}:{pos[1]}" if pos else f"${pc & 0xFFFF:04X}"
        return where + (f" in {m.name}" if m else "")

    def _stop_reason(self, cog: int) -> str:
        for t, cid, kind, detail in reversed(self.chip.cog_events):
            if cid == cog and kind == "stop":
                return detail
        return "stopped"

    def source_lines(self, path: str, line: int, around: int = 5) -> list:
        """``(number, text)`` of the lines around ``line`` of ``path``."""
        lines = self.info.sources.get(path, [])
        lo, hi = max(1, line - around), min(len(lines), line + around)
        return [(n, lines[n - 1]) for n in range(lo, hi + 1)]


def _pin_text(state) -> str:
    if state is None:
        return "?"
    driven, level = state
    return f"{'high' if level else 'low'}" if driven else "input"
