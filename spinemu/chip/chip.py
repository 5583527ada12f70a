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
from .cog import PARKED, PIN_WAIT, RUNNING, STOPPED, IDLE_PASM, Cog
from .control import CogStopped, Preempted, RebootRequested, Reschedule
from .fastforward import INTERRUPTED, LEARN_AFTER, LEARN_HORIZON, learn_busy_loop, tracking_handlers
from .registers import Registers
from .rom import INTERPRETER_ENTRY, build_rom
from .spin import build_handlers
from .timing import Timing, access_offsets, load_timing

__all__ = ["Chip", "RunResult", "COG_LOAD_CYCLES", "COMPAT_MODES"]

COMPAT_MODES = ("chip", "spinsim")
#: Cycles from a COGINIT to the new cog's first instruction on the chip: 496
#: longs, one per hub window (16 clocks), plus the window of the COGINIT itself.
COG_LOAD_CYCLES = 496 * 16 + 16
_SPINSIM_START_CYCLES = -4          # spinsim: first instruction in the COGINIT's last cycle
_NEVER = 1 << 62
_WRAP = 1 << 32


def _preempt_handler(c, op, t):
    raise Preempted


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
        self.counters_on = False        # some counter is in an output mode (else pins skip them)
        self.registers = Registers(self)
        #: one flag per hub long: set while a parked busy loop (fastforward.py) reads it
        self.watch = bytearray(0x10000 >> 2)
        self._parked: list = []
        self.handlers = build_handlers(self, self.timing)
        self.access_at = access_offsets()
        self._handlers = list(self.handlers)      # the real ones, while a preemption is pending
        self._preempt = False
        self.pin_events: list = []          # (cycle, seq, cog, dira, outa, running)
        self.cog_events: list = []
        self.warnings: list = []
        self._seq = 0
        self._started = False
        self._booted = False
        #: when a list, every bytecode is appended to it as
        #: ``(cog, pc, op, t_start, t_fetched, t_next, stack_before, stack_after)``
        #: (the instrumented loop; used by the timing derivation and debugging)
        self.recorder = None
        self._tracking = None       # the learning interpreter (fastforward.py), built on first use
        self.learn_tracked = 0      # bytecodes the latest learning attempt ran
        self._ff_loops = self._ff_skipped = 0
        self.last_target = None     # the target value of the latest assignment operator
        self.now = 0

    # ------------------------------------------------------------------ pins
    def pin_state(self, t: int) -> tuple[int, int]:
        """``(dir, out)`` over running cogs at cycle ``t`` (counter outputs included)."""
        d = o = 0
        counters = self.counters if self.counters_on else None
        for c in self.cogs:
            if c.state != STOPPED:
                d |= c.dira
                out = c.outa
                if counters is not None:
                    out |= counters.outputs(c, t)
                o |= c.dira & out
        return d, o

    def ina(self, t: int) -> int:
        """What INA reads at cycle ``t``: driven pins as driven, the rest from the input model."""
        d, o = self.pin_state(t)
        return o | (self.inputs.levels(t) & ~d & 0xFFFFFFFF)

    def record_cog_pins(self, c: Cog, t: int) -> None:
        """Add cog ``c``'s pin drive at cycle ``t`` to the pin record."""
        out = c.outa
        if self.counters_on:
            out |= self.counters.outputs(c, t)
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, out, c.state != STOPPED))

    def note_pins(self, c: Cog, t: int) -> None:
        """Cog ``c`` changed DIRA, OUTA or a counter at cycle ``t`` (the pins change then)."""
        self.record_cog_pins(c, t)
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
        if c.state == PARKED:
            self._unpark(c, t)
        if c in self._pin_waiters:
            self._pin_waiters.remove(c)
        if self.counters_on:
            self.counters.flush(c, t)
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
        self._ext_seen = max(self._ext_seen, t)
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
        if not self._booted:
            self._boot()
        reason = self._schedule(limit, progress)
        end = self.now if reason != "cycle limit" else limit
        if self.counters_on:
            for c in self.cogs:
                if c.state != STOPPED:
                    self.counters.flush(c, end)
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

    def step(self, cog: int = 0) -> int:
        """Execute exactly one bytecode of cog ``cog`` (booting the chip first if needed).

        For tests and debuggers: no other cog runs, no fast-forward.

        Returns:
            the cycles from the start of that bytecode to the start of the next.
        """
        if not self._booted:
            self._boot()
        c = self.cogs[cog]
        t = c.t
        self._run_spin(c, self._key(c) + 1)
        return c.t - t

    def _boot(self) -> None:
        self._booted = True
        self._ext_seen = 0
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
        """Advance the cog furthest behind until every cog stopped or ``limit``. (Hot loop.)"""
        cogs = self.cogs
        inputs = self.inputs
        next_report = 0
        run = (self._run_spin_traced if self.recorder is not None
               else self._run_with_fast_forward if self.fast_forward else self._run_spin)
        while True:
            # the running cog whose next bytecode reaches the hub first (lowest id on ties)
            c = None
            ck = 0
            for k in cogs:
                if k.state == RUNNING:
                    key = self._key(k)
                    if c is None or key < ck:
                        c, ck = k, key
            ext = self._next_external(limit) if self._pin_waiters else None
            if ext is not None and (c is None or ext <= c.t):
                self.now = self._ext_seen = ext         # an input edge or a counter edge
                self._wake_pin_waiters(ext)
                continue
            if c is None:
                if self._parked and not self._pin_waiters:
                    if limit >= _NEVER:
                        return "stalled"
                    for p in list(self._parked):
                        self._unpark(p, limit)
                    continue
                if self._pin_waiters:           # nothing can change the pins they wait on
                    if limit < _NEVER:
                        self.now = limit
                        return "cycle limit"
                    return "deadlock"
                if any(k.state == IDLE_PASM for k in cogs):
                    return "cycle limit" if limit < _NEVER else "deadlock"
                return "all cogs stopped"
            t = c.t
            if ck >= limit:
                self.now = limit
                for p in list(self._parked):
                    self._unpark(p, limit)
                return "cycle limit"
            until = limit
            cid = c.id
            for o in cogs:
                if o.state == RUNNING and o is not c:
                    key = self._key(o)
                    bound = key + 1 if cid < o.id else key
                    if bound < until:
                        until = bound
            if ext is not None and ext < until:
                until = ext
            self.now = t
            try:
                run(c, until)
            except RebootRequested:
                self.now = c.t
                return "reboot"
            if progress is not None and t >= next_report:
                progress(t)
                next_report = t + 10_000_000

    def _key(self, c: Cog) -> int:
        """When cog ``c``'s next bytecode touches shared state (see timing.access_offsets)."""
        tf = c.t + 12
        return tf + ((c.hub_phase - tf) & 15) + self.access_at[self.mem[c.pc]]

    def _next_external(self, limit: int):
        """The next input change or counter edge after the last one handled, if before ``limit``."""
        t = self._ext_seen
        nxt = self.inputs.next_change(t)
        if self.counters_on:
            ce = self.counters.next_edge(t)
            if ce is not None and (nxt is None or ce < nxt):
                nxt = ce
        return nxt if nxt is not None and nxt < limit else None

    def _run_with_fast_forward(self, c: Cog, until: int) -> None:
        """Run ``c`` until ``until``, skipping iterations of a learned busy loop (see fastforward.py)."""
        busy = c.busy
        if busy is None:
            if c.bytecodes - c.learn_mark > c.learn_after and until - c.t > LEARN_HORIZON:
                self._learn(c, until)
                if c.busy is None or c.state != RUNNING or c.pc != c.busy.head:
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
            self._park(c)
            return
        self._run_spin_to(c, until, busy.head)
        if c.pc != busy.head and c.bytecodes - c.learn_mark > LEARN_AFTER:
            c.busy = None               # the program left that loop: look for the next one
            c.learn_after = 0
            c.learn_mark = c.bytecodes

    # ------------------------------------------------------------------ parking busy loops
    def _park(self, c: Cog) -> None:
        """Take cog ``c`` out of the schedule: it repeats its learned loop until something it reads changes."""
        c.state = PARKED
        c.park_t0 = c.t
        c.learn_mark = c.bytecodes
        for shift, i, _ in c.busy.reads:
            a = (i << shift) & 0xFFFF
            self.watch[a >> 2] = 1
        self._parked.append(c)

    def _unpark(self, c: Cog, t_limit: int) -> None:
        """Bring parked cog ``c`` to where it would be, running its loop, when bytecodes starting before ``t_limit`` are done."""
        busy = c.busy
        k = max(0, (t_limit - 1 - c.park_t0) // busy.period)
        c.t = c.park_t0 + k * busy.period
        c.bytecodes += k * busy.bytecodes
        busy.skipped += k * busy.bytecodes
        self._ff_skipped += k * busy.bytecodes
        c.state = RUNNING
        self._parked.remove(c)
        self.watch[:] = bytes(len(self.watch))
        for p in self._parked:
            for shift, i, _ in p.busy.reads:
                self.watch[((i << shift) & 0xFFFF) >> 2] = 1
        if c.t < t_limit:
            self._run_spin(c, t_limit)

    def watch_hit(self, writer: Cog, hub_addr: int, t: int, op: int) -> None:
        """``writer``'s bytecode ``op``, started at ``t``, is about to write a hub long a parked loop reads.

        The parked cog is brought up to ``t`` first (it reads the old value, as
        it would have), and the writer's run loop is preempted after this
        bytecode, so that the scheduler interleaves the two cogs again.
        """
        woke = False
        tf = t + 12
        key = tf + ((writer.hub_phase - tf) & 15) + self.access_at[op]
        for p in list(self._parked):
            if any(((i << shift) & 0xFFFF) >> 2 == hub_addr >> 2 for shift, i, _ in p.busy.reads):
                self._unpark(p, key + 1 if p.id < writer.id else key)
                woke = True
        if woke:
            self._preempt = True
            self.handlers[:] = [_preempt_handler] * 256

    def _end_preemption(self) -> None:
        self.handlers[:] = self._handlers
        self._preempt = False

    def _learn(self, c: Cog, until: int) -> None:
        if self._tracking is None:
            self._tracking = tracking_handlers(self, self.timing)
        handlers, log = self._tracking
        try:
            loop = learn_busy_loop(self, c, handlers, log, until)
        finally:
            log.clear()
        c.learn_mark = c.bytecodes
        if loop is INTERRUPTED:
            return                      # not a failure: try again at the next chance
        if loop is None:
            # wait until the failed attempt's cost is small against normal running
            c.learn_after = max(LEARN_AFTER, 16 * self.learn_tracked)
        else:
            c.busy = loop
            self._ff_loops += 1

    def _run_spin_to(self, c: Cog, limit: int, stop_pc: int) -> None:
        """:meth:`_run_spin`, but stop when the cog comes back to ``stop_pc`` (a loop head)."""
        mem = self.mem
        H = self.handlers
        ACC = self.access_at
        P = c.hub_phase
        t = c.t
        n = 0
        tf = t
        try:
            while True:
                pc = c.pc
                op = mem[pc]
                tf = t + 12
                tf += (P - tf) & 15
                if tf + ACC[op] >= limit:
                    break
                c.pc = pc + 1
                t = tf + H[op](c, op, t)
                n += 1
                if c.pc == stop_pc:
                    break
        except Reschedule as e:
            t = tf + e.rest
            n += 1
        except Preempted:
            c.pc = pc
            self._end_preemption()
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
        ACC = self.access_at
        P = c.hub_phase
        t = c.t
        n = 0
        tf = t
        try:
            while True:
                pc = c.pc
                op = mem[pc]
                tf = t + 12
                tf += (P - tf) & 15
                if tf + ACC[op] >= limit:       # another cog touches the hub first
                    break
                c.pc = pc + 1
                t = tf + H[op](c, op, t)
                n += 1
        except Reschedule as e:
            t = tf + e.rest
            n += 1
        except Preempted:
            c.pc = pc
            self._end_preemption()
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
        """The instrumented twin of :meth:`_run_spin`: runs one bytecode and records it."""
        L, W = self.mem_longs, self.mem_words
        if c.state == RUNNING and self._key(c) < limit:
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
            self._run_spin(c, self._key(c) + 1)
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
