"""The Propeller 1 chip: hub RAM and ROM, eight cogs, locks, pins, the system counter.

:class:`Chip` boots an image the way the chip does (Propeller Manual v1.2,
"Boot Up Procedure"): the image is copied to hub RAM, the rest of RAM is
cleared, the boot frame ``$FFF9FFFF, $FFF9FFFF`` is placed below ``dbase``,
and cog 0 starts the ROM's Spin interpreter on the first method.  Time is one
32-bit system counter (CNT) shared by all cogs; each cog keeps the cycle at
which it starts its next bytecode, and the scheduler always advances the cog
that is furthest behind, jumping over time in which every cog waits.

Two compatibility modes (``compat``):

``"chip"`` (default)
    The real chip: a started cog first loads 496 longs (``COG_LOAD_CYCLES``),
    ``LOCKNEW`` hands out lock 0 first, a restarted cog's DIRA/OUTA are
    cleared, undriven pins read 0 unless ``inputs`` says otherwise, and each
    cog's hub window is 2 clocks later than the previous cog's.
``"spinsim"``
    What spinsim 0.99 (the simulator behind tests/data/article) does: a cog
    starts 4 cycles after the COGINIT, lock 1 comes first, DIRA/OUTA survive a
    restart, undriven pins read 1, all cogs share one hub phase.

Hot path: :meth:`Chip._run_spin` (the bytecode loop) and :meth:`Chip.run`.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable, Optional

from ..diagnostics import EmulationError, ImageError
from ..image import BOOT_FRAME, HUB_SIZE, ImageHeader, load_image
from ..trace import PinTrace
from .cog import PIN_WAIT, RUNNING, STOPPED, IDLE_PASM, Cog
from .control import CogStopped, RebootRequested, Reschedule
from .fastforward import LEARN_AFTER, LEARN_HORIZON, learn_busy_loop, tracking_handlers
from .registers import Registers
from .rom import INTERPRETER_ENTRY, build_rom
from .spin import build_handlers
from .timing import Timing, load_timing

__all__ = ["Chip", "RunResult", "COG_LOAD_CYCLES", "COMPAT_MODES"]

COMPAT_MODES = ("chip", "spinsim")
#: Cycles from a COGINIT to the new cog's first instruction on the chip: 496
#: longs, one per hub window (16 clocks), plus the window of the COGINIT itself.
COG_LOAD_CYCLES = 496 * 16 + 16
_SPINSIM_START_CYCLES = -4          # spinsim: first instruction in the COGINIT's last cycle
_NEVER = 1 << 62
_WRAP = 1 << 32


@dataclass
class RunResult:
    """What a run produced.

    Attributes:
        trace: every pin change (first entry: the state at cycle 0).
        hub: the 32 KB of hub RAM when the run ended.
        end_cycle: the cycle the run ended at.
        reason: ``"all cogs stopped"``, ``"cycle limit"``, ``"reboot"`` or
            ``"deadlock"`` (every cog waits on pins that can never change).
        cog_events: ``(cycle, cog, "start" | "stop", detail)``.
        warnings: things the emulation could not do faithfully.
        stats: bytecodes executed (total and per cog), wall time, ...
    """

    trace: PinTrace
    hub: bytes
    end_cycle: int
    reason: str
    cog_events: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    stats: dict = field(default_factory=dict)


class Chip:
    """A Propeller 1 running one image.

    Args:
        image: the bytes of a ``.binary`` or ``.eeprom`` image.
        compat: ``"chip"`` or ``"spinsim"`` (see the module docstring).
        inputs: what pins nobody drives read: ``"pullup"``, ``"pulldown"``, or
            a stimulus (see :mod:`spinemu.chip.inputs`).  Default: pull-down
            in chip mode, pull-up in spinsim mode (spinsim reads them as 1).
        source_map: optional ``hub_addr -> (path, line)`` for fault messages.
        fast_forward: skip provably idle busy-wait loops (results unchanged).

    Raises:
        ImageError: if ``image`` is not a valid Propeller image.

    >>> from spinemu.image import to_eeprom
    >>> img = bytes.fromhex("00b4c4046f001000180020001000240032000000")
    """

    def __init__(self, image: bytes, *, compat: str = "chip", inputs=None,
                 source_map: Optional[Callable] = None, fast_forward: bool = True,
                 timing: Optional[Timing] = None):
        if compat not in COMPAT_MODES:
            raise ValueError(f"compat must be one of {COMPAT_MODES}, not {compat!r}")
        binary = load_image(bytes(image))
        self.header = ImageHeader.parse(binary)
        self.compat = compat
        self.spinsim = compat == "spinsim"
        self.source_map = source_map
        self.fast_forward = fast_forward
        self.timing = timing or load_timing()
        from .inputs import make_input_model
        self.inputs = make_input_model(inputs, pull_up=self.spinsim)

        self.mem = bytearray(0x10000)
        self.mem[0x8000:] = build_rom()
        self.mem[: len(binary)] = binary
        frame = BOOT_FRAME.to_bytes(4, "little") * 2
        self.mem[self.header.dbase - 8: self.header.dbase] = frame
        view = memoryview(self.mem)
        self.mem_words = view.cast("H")
        self.mem_longs = view.cast("I")

        self.cogs = [Cog(i) for i in range(8)]
        for cog in self.cogs:
            cog.hub_phase = 8 if self.spinsim else (8 + 2 * cog.id) & 15
        self.locks = [False] * 8
        self.lock_used = [False] * 8
        if self.spinsim:
            self.lock_used[0] = True        # spinsim keeps lock 0 for itself
        self.clock_hz = self.header.clkfreq
        from .counters import Counters
        self.counters = Counters(self)
        self.registers = Registers(self)
        self.handlers = build_handlers(self, self.timing)
        self.pin_events: list = []          # (cycle, seq, cog, dira, outa, running)
        self.cog_events: list = []
        self.warnings: list = []
        self._seq = 0
        self._started = False
        #: when a list, every bytecode is appended to it as
        #: ``(cog, pc, op, t_start, t_fetched, t_next, stack_before, stack_after)``
        #: (the instrumented loop; used by the timing derivation and debugging)
        self.recorder = None
        self._tracking = None       # the learning interpreter (fastforward.py), built on first use
        self._ff_loops = self._ff_skipped = 0
        self.last_target = None     # the target value of the latest assignment operator
        self.now = 0

    # ------------------------------------------------------------------ pins
    def pin_state(self) -> tuple[int, int]:
        """``(dir, out)`` over running cogs right now."""
        d = o = 0
        for c in self.cogs:
            if c.state != STOPPED:
                d |= c.dira
                o |= c.dira & c.outa
        return d, o

    def ina(self, t: int) -> int:
        """What INA reads at cycle ``t``: driven pins as driven, the rest from the input model."""
        d, o = self.pin_state()
        return o | (self.inputs.levels(t) & ~d & 0xFFFFFFFF)

    def note_pins(self, c: Cog, t: int) -> None:
        """Cog ``c`` changed DIRA or OUTA at cycle ``t`` (the pins change then)."""
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, c.outa, c.state != STOPPED))
        if self._pin_waiters:
            self._wake_pin_waiters(t)

    # ------------------------------------------------------------------ faults
    def fault(self, c: Cog, hub_addr: int, message: str) -> EmulationError:
        """An :class:`EmulationError` naming the cog, the bytecode address and the source line."""
        where = f"cog {c.id}, bytecode at ${hub_addr & 0xFFFF:04X}"
        path = line = None
        if self.source_map is not None:
            try:
                found = self.source_map(hub_addr & 0xFFFF)
            except Exception:  # a broken map must not hide the fault
                found = None
            if found:
                path, line = found
        return EmulationError(f"{message} ({where})", path=path, line=line)

    # ------------------------------------------------------------------ cogs
    def start_spin_cog(self, c: Cog, par: int, t_first: int, by: Optional[Cog]) -> None:
        """Start the Spin interpreter in cog ``c``; its first instruction runs at ``t_first``."""
        keep = (c.dira, c.outa) if self.spinsim else (0, 0)
        c.reset_registers()
        c.dira, c.outa = keep
        c.par = par & 0xFFFC
        c.engine = "spin"
        c.state = RUNNING
        c.started_at = t_first
        m = self.mem_words
        base = (par & 0xFFFC) + 2
        c.pbase, c.vbase, c.dbase, c.pc, c.sp = (m[((base + 2 * i) & 0xFFFF) >> 1] for i in range(5))
        c.scratch[9] = c.id
        c.dcall = 0
        c.t = self.timing.interpreter_start(t_first, c.hub_phase)
        self.cog_events.append((t_first, c.id, "start",
                                f"Spin method at ${c.pc:04X}" + (f" (started by cog {by.id})" if by else "")))
        if keep != (0, 0):
            self.note_pins(c, t_first)

    def stop_cog(self, c: Cog, t: int, why: str) -> None:
        if c.state == STOPPED:
            return
        if c in self._pin_waiters:
            self._pin_waiters.remove(c)
        c.state = STOPPED
        c.pin_wait = None
        c.t = _NEVER
        self.now = max(self.now, t)
        self.cog_events.append((t, c.id, "stop", why))
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, c.outa, False))

    def coginit(self, c: Cog, cog_id: int, code: int, par: int, tf: int) -> int:
        """COGINIT/COGNEW from cog ``c``: returns the started cog's id, or -1 (as u32)."""
        done = tf + self.timing.coginit_done
        if cog_id >= 8:                         # the ROM clamps: 8 and up = "a free cog"
            free = [k for k in self.cogs if k.state == STOPPED]
            if not free:
                return 0xFFFFFFFF
            target = free[0]
        else:
            target = self.cogs[cog_id]
        if target.state != STOPPED:
            self.stop_cog(target, done, f"restarted by cog {c.id}")
        if self.spinsim:
            t_first = done + _SPINSIM_START_CYCLES
        else:
            t_first = done + COG_LOAD_CYCLES
        if (code & 0xFFFC) == INTERPRETER_ENTRY & 0xFFFC:
            self.start_spin_cog(target, par, t_first, c)
        else:
            self._start_pasm(target, code & 0xFFFC, par & 0xFFFC, t_first, c)
        return target.id

    def _start_pasm(self, target: Cog, code: int, par: int, t_first: int, by: Cog) -> None:
        target.reset_registers()
        target.state = IDLE_PASM
        target.engine = "pasm"
        target.par = par
        target.t = _NEVER
        msg = (f"cog {target.id} was started by cog {by.id} on PASM code at hub ${code:04X} "
               f"(PAR ${par:04X}); PASM is not emulated, so that cog stays idle and drives no pins")
        self.warnings.append(msg)
        self.cog_events.append((t_first, target.id, "start", f"PASM at ${code:04X} (not emulated)"))

    def cogstop(self, c: Cog, cog_id: int, tf: int, rest: int) -> int:
        t = tf + self.timing.cogstop_at
        target = self.cogs[cog_id]
        if target is c:
            self.stop_cog(c, t, "COGSTOP of itself" if c.pc != 0xFFFC else "returned from its top method")
            raise CogStopped(rest)
        if target.state != STOPPED:
            self.stop_cog(target, t, f"stopped by cog {c.id}")
            raise Reschedule(rest)
        return rest

    # ------------------------------------------------------------------ locks
    def locknew(self) -> int:
        for i in range(8):
            if not self.lock_used[i]:
                self.lock_used[i] = True
                self.locks[i] = False
                return i
        return 0xFFFFFFFF

    def lockret(self, i: int) -> None:
        if not (self.spinsim and i == 0):
            self.lock_used[i] = False

    def lockset(self, i: int, value: bool) -> bool:
        was = self.locks[i]
        self.locks[i] = value
        return was

    # ------------------------------------------------------------------ clock, video
    def set_clock(self, mode: int, freq: int) -> None:
        if freq != self.clock_hz:
            self.warnings.append(
                f"CLKSET changed clkfreq from {self.clock_hz} to {freq} Hz; trace times stay in cycles")

    def waitvid(self, c: Cog, colors: int, pixels: int, tf: int) -> int:
        """WAITVID: the video generator takes a new frame every VSCL[11:0] clocks (PLLA = system clock)."""
        T = self.timing
        issue = tf + T.waitvid_issue
        frame = (c.vscl & 0xFFF) or 4096
        start = max(issue, self._video_ready[c.id])
        self._video_ready[c.id] = start + frame
        return start - tf + T.waitvid_after

    # ------------------------------------------------------------------ pin waits
    def wait_pins(self, c: Cog, mask: int, state: int, equal: bool, tf: int) -> int:
        issue, after = self.timing.waitpin[equal]
        t = tf + issue
        if ((self.ina(t) & mask) == state) == equal:
            return issue + after
        c.pin_wait = (mask, state, equal, after)
        c.state = PIN_WAIT
        self._pin_waiters.append(c)
        raise Reschedule(_NEVER - tf)

    def _wake_pin_waiters(self, t: int) -> None:
        for c in list(self._pin_waiters):
            mask, state, equal, after = c.pin_wait
            if ((self.ina(t) & mask) == state) == equal:
                self._pin_waiters.remove(c)
                c.pin_wait = None
                c.state = RUNNING
                c.t = t + after

    # ------------------------------------------------------------------ RUN
    def run_helper(self, c: Cog, tf: int) -> int:
        from .runhelper import run_spin_method
        return run_spin_method(self, c, tf)

    # ------------------------------------------------------------------ running
    def run(self, max_cycles: Optional[int] = None, progress: Optional[Callable[[int], None]] = None) -> RunResult:
        """Run until every cog stopped or ``max_cycles`` cycles have passed.

        Args:
            max_cycles: stop at this cycle (``None``: run until all cogs stop).
            progress: called as ``progress(cycle)`` about every million cycles
                of simulated time... and at least every few seconds of wall time.

        Raises:
            EmulationError: on a runtime fault in the emulated program.
        """
        if self._started:
            raise RuntimeError("a Chip runs once; make a new Chip to run again")
        self._started = True
        wall = time.perf_counter()
        limit = _NEVER if max_cycles is None else max_cycles
        self._boot()
        reason = self._schedule(limit, progress)
        end = self.now if reason != "cycle limit" else limit
        wall = time.perf_counter() - wall
        trace = self._build_trace(end)
        per_cog = {c.id: c.bytecodes for c in self.cogs if c.bytecodes}
        stats = {"bytecodes": sum(per_cog.values()), "bytecodes_per_cog": per_cog,
                 "wall_seconds": wall, "simulated_seconds": end / self.clock_hz if self.clock_hz else 0.0}
        stats["realtime_factor"] = stats["simulated_seconds"] / wall if wall > 0 else 0.0
        stats.update(self._ff_stats())
        return RunResult(trace, bytes(self.mem[:HUB_SIZE]), end, reason, list(self.cog_events),
                         list(self.warnings), stats)

    def _ff_stats(self) -> dict:
        return {"fast_forward": self.fast_forward, "busy_loops_learned": self._ff_loops,
                "bytecodes_skipped": self._ff_skipped}

    def _boot(self) -> None:
        self._pin_waiters = []
        self._video_ready = [0] * 8
        cog0 = self.cogs[0]
        # The boot loader starts the interpreter in cog 0 with PAR = $0004
        # (pbase, vbase, dbase, pcurr, dcurr at $0006..$000E).  Cycle 0 is the
        # first instruction of that interpreter in both modes: the boot
        # loader's own time (reading the EEPROM, loading cog 0) is not counted.
        t_first = 0
        self.start_spin_cog(cog0, 0x0004, t_first, None)
        self.cog_events[-1] = (t_first, 0, "start", f"Spin method at ${cog0.pc:04X} (boot)")

    def _schedule(self, limit: int, progress) -> str:
        cogs = self.cogs
        next_report = 0
        while True:
            running = [c for c in cogs if c.state == RUNNING]
            if not running:
                if self._pin_waiters:
                    wake = self.inputs.next_change(self.now)
                    if wake is None or wake >= limit:
                        self.now = limit if limit < _NEVER else self.now
                        return "cycle limit" if limit < _NEVER else "deadlock"
                    self.now = wake
                    self._wake_pin_waiters(wake)
                    continue
                return "all cogs stopped" if not any(c.state == IDLE_PASM for c in cogs) else (
                    "cycle limit" if limit < _NEVER else "deadlock")
            c = min(running, key=lambda k: (k.t, k.id))
            if c.t >= limit:
                self.now = limit
                return "cycle limit"
            until = limit
            for o in running:
                if o is not c:
                    bound = o.t + (1 if c.id < o.id else 0)
                    if bound < until:
                        until = bound
            if self._pin_waiters:
                nxt = self.inputs.next_change(c.t)
                if nxt is not None and nxt < until:
                    until = max(nxt, c.t + 1)
            self.now = c.t
            try:
                if self.recorder is not None:
                    self._run_spin_traced(c, until)
                elif not self.fast_forward:
                    self._run_spin(c, until)
                else:
                    self._run_with_fast_forward(c, until)
            except RebootRequested:
                self.now = c.t
                return "reboot"
            if progress is not None and self.now >= next_report:
                progress(self.now)
                next_report = self.now + 10_000_000

    def _run_with_fast_forward(self, c: Cog, until: int) -> None:
        """Run ``c`` until ``until``, skipping iterations of a learned busy loop (see fastforward.py)."""
        busy = c.busy
        if busy is None:
            if c.bytecodes - c.learn_mark > c.learn_after and until - c.t > LEARN_HORIZON:
                self._learn(c, until)
                if c.busy is None or c.state != RUNNING:
                    self._run_spin(c, until)
                    return
                busy = c.busy
            else:
                self._run_spin(c, until)
                return
        if c.pc == busy.head:
            if not busy.still_valid(self, c):
                c.busy = None                   # learn again at once: often only a value changed
                c.learn_after = 0
                c.learn_mark = c.bytecodes
                self._run_spin(c, until)
                return
            k = (until - c.t) // busy.period
            if k > 0:
                c.t += k * busy.period
                c.bytecodes += k * busy.bytecodes
                busy.skipped += k * busy.bytecodes
                self._ff_skipped += k * busy.bytecodes
        self._run_spin_to(c, until, busy.head)

    def _learn(self, c: Cog, until: int) -> None:
        if self._tracking is None:
            self._tracking = tracking_handlers(self, self.timing)
        handlers, log = self._tracking
        try:
            loop = learn_busy_loop(self, c, handlers, log, until)
        finally:
            log.clear()
        c.learn_mark = c.bytecodes
        if loop is None:
            c.learn_after = min(max(2 * c.learn_after, LEARN_AFTER), 1 << 20)
        else:
            c.busy = loop
            self._ff_loops += 1

    def _run_spin_to(self, c: Cog, limit: int, stop_pc: int) -> None:
        """:meth:`_run_spin`, but stop when the cog comes back to ``stop_pc`` (a loop head)."""
        mem = self.mem
        H = self.handlers
        P = c.hub_phase
        t = c.t
        n = 0
        tf = t
        try:
            while t < limit:
                pc = c.pc
                op = mem[pc]
                c.pc = pc + 1
                tf = t + 12
                tf += (P - tf) & 15
                t = tf + H[op](c, op, tf)
                n += 1
                if c.pc == stop_pc:
                    break
        except Reschedule as e:
            t = tf + e.rest
            n += 1
        except CogStopped:
            c.bytecodes += n + 1
            return
        except RebootRequested:
            c.bytecodes += n + 1
            c.t = tf
            raise
        except IndexError:
            raise self.fault(c, c.pc - 1, "stack or address out of hub range") from None
        c.bytecodes += n
        if c.state == RUNNING:
            c.t = t

    def _run_spin(self, c: Cog, limit: int) -> None:
        """Run cog ``c``'s bytecodes while it starts them before ``limit``. (Hot loop.)

        Hook for other engines: when ``c.engine`` is not a string but an
        object, the scheduler hands the cog to ``c.engine.run(c, limit)``,
        which must advance ``c.t`` (or stop the cog) the same way.  The
        Spin->Python translation (spinemu.translate) runs its cogs this way.
        """
        if c.engine.__class__ is not str:
            c.engine.run(c, limit)
            return
        mem = self.mem
        H = self.handlers
        P = c.hub_phase
        t = c.t
        n = 0
        tf = t
        try:
            while t < limit:
                pc = c.pc
                op = mem[pc]
                c.pc = pc + 1
                tf = t + 12
                tf += (P - tf) & 15
                t = tf + H[op](c, op, tf)
                n += 1
        except Reschedule as e:
            t = tf + e.rest
            n += 1
        except CogStopped:
            c.bytecodes += n + 1
            return
        except RebootRequested:
            c.bytecodes += n + 1
            c.t = tf
            raise
        except IndexError:
            raise self.fault(c, c.pc - 1, "stack or address out of hub range") from None
        c.bytecodes += n
        if c.state == RUNNING:
            c.t = t

    def _run_spin_traced(self, c: Cog, limit: int) -> None:
        """The instrumented twin of :meth:`_run_spin`: one bytecode at a time, recorded."""
        L, W = self.mem_longs, self.mem_words
        while c.state == RUNNING and c.t < limit:
            pc, t, sp = c.pc, c.t, c.sp
            before = tuple(L[((sp - 4 * k) & 0xFFFF) >> 2] for k in range(1, 5))
            op = self.mem[pc]
            if 0x30 <= op <= 0x33:                  # frames unwound, and is the result pushed
                d, frames = c.dbase, 1
                while op < 0x32 and not W[((d - 8) & 0xFFFF) >> 1] & 2 and frames < 64:
                    d = W[((d - 4) & 0xFFFF) >> 1]
                    frames += 1
                before = before + (frames, not W[((d - 8) & 0xFFFF) >> 1] & 1)
            elif op == 0x17:                        # characters STRCOMP will compare
                a, b, n = before[1] & 0xFFFF, before[0] & 0xFFFF, 0
                while True:
                    x, y = self.mem[(a + n) & 0xFFFF], self.mem[(b + n) & 0xFFFF]
                    n += 1
                    if x != y or x == 0:
                        break
                before = before + (n,)
            self.last_target = None
            self._run_spin(c, t + 1)
            sp = c.sp
            after = tuple(L[((sp - 4 * k) & 0xFFFF) >> 2] for k in range(1, 3))
            t_next = c.t if c.state == RUNNING else self.now
            tf = t + 12
            tf += (c.hub_phase - tf) & 15
            self.recorder.append((c.id, pc, op, t, tf, t_next, before, after, self.last_target))

    # ------------------------------------------------------------------ trace
    def _build_trace(self, end: int) -> PinTrace:
        trace = PinTrace(self.clock_hz, end_cycle=end)
        trace.record(0, 0, 0)
        state = {}
        for t, _, cog_id, dira, outa, running in sorted(self.pin_events):
            if t > end:
                break
            if running:
                state[cog_id] = (dira, outa)
            else:
                state.pop(cog_id, None)
            d = o = 0
            for dd, oo in state.values():
                d |= dd
                o |= dd & oo
            trace.record(t, d, o)
        return trace
