"""The Propeller 1 chip: hub RAM and ROM, eight cogs, locks, pins, the system counter.

:class:`Chip` boots an image the way the chip does (Propeller Manual v1.2,
"Boot Up Procedure"): the image is copied to hub RAM, the rest of RAM is
cleared, the boot frame ``$FFF9FFFF, $FFF9FFFF`` is placed below ``dbase``,
and cog 0 starts the ROM's Spin interpreter on the first method.  Time is one
32-bit system counter (CNT) shared by all cogs; each cog keeps the cycle at
which it starts its next bytecode, and the scheduler (:mod:`.scheduler`)
always advances the cog whose next hub access comes first, jumping over time
in which every cog waits.  Pins are in :mod:`.pins`, live pin listeners in
:mod:`.listen`, the Spin interpreter in :mod:`.spin`, PASM cogs in
:mod:`.pasm_cog`.

Two compatibility modes (``compat``):

``"spinsim"`` (default)
    The reference: what spinsim 0.99 (Parallax's ROM interpreter on
    cycle-exact cogs, the simulator behind the reference traces in
    tests/data/article) does, cycle for cycle: a cog starts 4 cycles after
    the COGINIT, lock 1 comes first, DIRA/OUTA survive a restart, undriven
    pins read 1, all cogs share one hub phase.
``"chip"``
    The silicon where it differs from that simulator: a started cog first
    loads 496 longs (``COG_LOAD_CYCLES``), ``LOCKNEW`` hands out lock 0 first,
    a restarted cog's DIRA/OUTA are cleared, undriven pins read 0 unless
    ``inputs`` says otherwise, and each cog's hub window is 2 clocks later
    than the previous cog's.

Hot paths are in :mod:`.scheduler` and :mod:`.spin`; this module is set-up,
cog and lock management, and the run's result.
"""
from __future__ import annotations

import time
from collections.abc import Callable

from ..diagnostics import EmulationError
from ..bench.inputs import make_input_model
from ..image import BOOT_FRAME, FALLBACK_CLOCK_HZ, HUB_SIZE, ImageHeader, load_image
from ..records import Record
from ..trace import PinTrace
from .ahead import RunAhead
from .blocks import HOT as BLOCK_THRESHOLD
from .cog import PARKED, PIN_WAIT, RUNNING, STOPPED, Cog
from .control import CogStopped, Halted, Reschedule
from .listen import Listeners
from .pins import Pins
from .registers import Registers
from .scheduler import NEVER, Scheduler
from .rom import INTERPRETER_ENTRY, build_rom
from .spin import build_handlers
from .timing import Timing, access_offsets, load_timing, wide_offsets

__all__ = ["Chip", "RunResult", "COG_LOAD_CYCLES", "COMPAT_MODES"]

COMPAT_MODES = ("chip", "spinsim")
#: Cycles from a COGINIT to the new cog's first instruction on the chip: 496
#: longs, one per hub window (16 clocks), plus the window of the COGINIT itself.
COG_LOAD_CYCLES = 496 * 16 + 16
_SPINSIM_START_CYCLES = -4          # spinsim: first instruction in the COGINIT's last cycle
_NEVER = NEVER
#: run endings after which no pin can change again
_FINAL_REASONS = ("all cogs stopped", "deadlock", "stalled")


def _spinsim_phase(cog_id: int) -> int:
    """Cog ``cog_id``'s hub window in spinsim: ``t mod 16`` when its hub instructions complete.

    Measured (spinsim 0.99 ``-p``, a hub loop started in each cog): cogs 0
    and 1 at 8, 2 and 3 at 12, 4 and 5 at 0, 6 and 7 at 4 (the silicon's
    windows 2 clocks apart, met on spinsim's 4-cycle instruction grid).
    """
    return (8 + 4 * (cog_id >> 1)) & 15


class RunResult(Record):
    """What a run produced.

    Attributes:
        trace: every pin change (first entry: the state at cycle 0).
        hub: the 32 KB of hub RAM when the run ended.
        end_cycle: the cycle the run ended at.
        reason: ``"all cogs stopped"``, ``"cycle limit"``, ``"reboot"``,
            ``"deadlock"`` (every cog waits on pins that can never change),
            or ``"stalled"`` (the cogs left spin in loops that can never end).
        cog_events: ``(cycle, cog, "start" | "stop", detail)``; a PASM
            start's detail names its hub address and, with ``labels``, its
            DAT label.
        warnings: things the emulation could not do faithfully.
        stats: bytecodes executed (total and per cog), PASM instructions
            (``pasm_instructions``, ``pasm_instructions_per_cog``), wall time, ...
        runtime_warnings: the program's likely mistakes the run saw
            (:class:`spinemu.runtime_warnings.RunWarning`, one per place).
    """

    _fields = ("trace", "hub", "end_cycle", "reason", "cog_events", "warnings", "stats", "runtime_warnings")

    def __init__(self, trace: PinTrace, hub: bytes, end_cycle: int, reason: str, cog_events: list | None = None,
                 warnings: list | None = None, stats: dict | None = None,
                 runtime_warnings: list | None = None):
        self.trace, self.hub, self.end_cycle, self.reason = trace, hub, end_cycle, reason
        self.cog_events = [] if cog_events is None else cog_events
        self.warnings = [] if warnings is None else warnings
        self.stats = {} if stats is None else stats
        self.runtime_warnings = [] if runtime_warnings is None else runtime_warnings


class Chip(Pins, Listeners, RunAhead, Scheduler):
    """A Propeller 1 running one image.

    Args:
        image: the bytes of a ``.binary`` or ``.eeprom`` image (a 32 KB
            EEPROM image is loaded whole, as the boot loader does).
        compat: ``"spinsim"`` (default) or ``"chip"`` (see the module docstring).
        inputs: what pins nobody drives read: ``"pullup"``, ``"pulldown"``, or
            a stimulus (see :mod:`spinemu.chip.inputs`).  Default: pull-down
            in chip mode, pull-up in spinsim mode (spinsim reads them as 1).
        source_map: optional ``hub_addr -> (path, line)`` for fault messages.
        labels: optional ``hub_addr -> name`` of DAT labels (a compiled
            program's ``dat_labels()``); a PASM cog's start then names its label.
        fast_forward: skip provably idle busy-wait loops (results unchanged).
        compile_blocks: run hot bytecode as compiled blocks (:mod:`.blocks`;
            results unchanged).
        run_ahead: let a cog run past the others through bytecodes that touch
            only its own stack and code (:mod:`.ahead`; results unchanged;
            needs ``compile_blocks``).  ``False`` hands over at every hub
            access in cycle order.
        warn: runtime warnings (:mod:`spinemu.runtime_warnings`): ``True``
            (default) collects them in ``RunResult.runtime_warnings``, ``False``
            turns the checks off, or pass your own
            :class:`~spinemu.runtime_warnings.WarningLog` (``werror``, a sink).
        debug_info: the program's :class:`spinemu.debuginfo.DebugInfo` (from
            ``CompiledProgram.debug_info()``): warnings then name variables and
            methods, point at file:line:col, and the checks that need names
            (stack arrays, uninitialized locals) run.
        steady_skip: skip whole periods of a steady state paced by WAITCNT
            (:mod:`.steady`; results unchanged; needs ``fast_forward``).

    Raises:
        ImageError: if ``image`` is not a valid Propeller image.

    Bench parts (:mod:`spinemu.bench`) attach through ``clock_hz``,
    ``pin_count``, ``inputs``, :attr:`drive_history` and
    ``add_pin_listener``.
    """

    #: pins of the P8X32A (port A)
    pin_count = 32

    def __init__(self, image: bytes, *, compat: str = "spinsim", inputs=None,
                 source_map: Callable | None = None, fast_forward: bool = True,
                 timing: Timing | None = None, compile_blocks: bool = True, labels=None,
                 run_ahead: bool = True, warn=True, debug_info=None, steady_skip: bool = True):
        if compat not in COMPAT_MODES:
            raise ValueError(f"compat must be one of {COMPAT_MODES}, not {compat!r}")
        binary = load_image(bytes(image))
        self.header = ImageHeader.parse(binary)
        self.compat = compat
        self.spinsim = compat == "spinsim"
        self.source_map = source_map
        self.labels = labels or {}
        self.fast_forward = fast_forward
        self.compile_blocks = compile_blocks
        self.timing = timing or load_timing()
        self.inputs = make_input_model(inputs, pull_up=self.spinsim)

        self.mem = bytearray(0x10000)
        self.mem[0x8000:] = build_rom()
        # the boot loader copies all 32 KB of an EEPROM (data a program stored there included)
        boot = bytes(image) if len(image) == HUB_SIZE else binary
        self.mem[: len(boot)] = boot
        frame = BOOT_FRAME.to_bytes(4, "little") * 2
        self.mem[self.header.dbase - 8: self.header.dbase] = frame
        view = memoryview(self.mem)
        self.mem_words = view.cast("H")
        self.mem_longs = view.cast("I")

        self.cogs = [Cog(i) for i in range(8)]
        self._pasm_tracers: dict = {}
        self._cogs_changed = True       # a cog's state changed: the scheduler lists the running ones again
        for cog in self.cogs:
            cog.hub_phase = _spinsim_phase(cog.id) if self.spinsim else (8 + 2 * cog.id) & 15
        self.locks = [False] * 8
        self.lock_used = [False] * 8
        if self.spinsim:
            self.lock_used[0] = True        # spinsim keeps lock 0 for itself
        self.clock_hz = self.header.clkfreq or FALLBACK_CLOCK_HZ     # the time base of the trace
        from .counters import Counters
        from .pinfold import PinFold
        self.counters = Counters(self)
        self.counters_on = False        # some counter is in an output mode (else pins skip them)
        self.registers = Registers(self)
        #: one flag per hub long: set while a parked busy loop (fastforward.py) reads it; the
        #: other bits of blocks.py (CODE, PROGRAM, WATCHPOINT) also send writes to watch_hit
        self.watch = bytearray(0x10000 >> 2)
        self._parked: list = []
        #: updates whose write-back another cog's access comes before (Scheduler.defer_write), and
        #: the earliest of their write moments; the run loops' limit the handlers compare against
        self._pend: list = []
        self._pend_at = _NEVER
        self._pend_id = 8
        self.rmw_limit = 0
        self.debug_info = debug_info
        #: called as f(cog, cycle) right after a cog changes its DIRA/OUTA (before other cogs run);
        #: f(cog, hub_addr, size, cycle) before a write of size bytes (a bytecode's or a PASM cog's)
        #: to a long with a PROGRAM or WATCHPOINT watch bit
        #: (runtime checks, debuggers; the bench's live listeners are pin_listeners, listen.py)
        self.pin_hooks: list = []
        self.write_hooks: list = []
        #: bytecode addresses no compiled block may start at or run through; calls stay interpreted
        self.interpret_only: set = set()
        self.interpret_calls = False
        #: a debugger or profiler: ``before(chip, cog)`` / ``after(chip, cog, pc, t)`` around every
        #: bytecode, run by the instrumented loop (Scheduler._run_spin_probed); None for full speed
        self.probe = None
        self.warning_log = None
        self.checks = None
        if warn is not False:
            from .checks import RuntimeChecks
            self.warning_log = _default_log(debug_info, source_map) if warn is True else warn
            self.checks = RuntimeChecks(self, self.warning_log, debug_info)
        self.handlers = build_handlers(self, self.timing)
        #: (bytecode, rewrap) of every handler wrap_handler replaced, in order
        self._wraps: list = []
        self.access_at = access_offsets()
        self.access_wide = wide_offsets()     # +16 for a two-byte offset (timing.wide_offsets)
        self._handlers = list(self.handlers)      # the real ones, while a preemption is pending
        self._preempt = False
        self._halt_reason = None
        self.pin_events: list = []          # (cycle, seq, cog, dira, outa, running)
        self.pin_fold = PinFold(self)       # pin events and counter outputs folded into pin states (pinfold.py)
        self._init_listeners()              # live pin listeners (listen.py)
        self._drives = None                 # the drive history bench parts read (drives.py), on first use
        self.cog_events: list = []
        self.warnings: list = []
        if not self.header.clkfreq:
            self.warnings.append(f"the image's header gives a clock of 0 Hz; times are counted at "
                                 f"{FALLBACK_CLOCK_HZ:,} Hz (RCFAST)")
        self._seq = 0
        self._started = False
        self._booted = False
        #: when a list, every bytecode is appended to it as
        #: ``(cog, pc, op, t_start, t_fetched, t_next, stack_before, stack_after)``
        #: (the instrumented loop; used by the timing derivation and debugging)
        self.recorder = None
        self._tracking = None       # the learning interpreter (fastforward.py), built on first use
        self._tracking_wraps = 0    # ... wrapped as the chip's handlers were then (wrap_handler)
        self.learn_tracked = 0      # bytecodes the latest learning attempt ran
        self._ff_loops = self._ff_skipped = 0
        from .fastforward import LoopMemory
        self._loop_memory = LoopMemory()
        self.last_target = None     # the target value of the latest assignment operator
        # compiled blocks (blocks.py): one entry per hub address, a stub until compiled
        self._compiler = None
        #: where compiled blocks' code comes from between runs (codecache.py; ``spinemu run`` sets it)
        self.code_cache = None
        #: times a bytecode address starts a run before a block is compiled for it
        self.block_threshold = BLOCK_THRESHOLD
        if compile_blocks:
            self._blocks = [self._block_stub] * 0x10000
            self._heat = bytearray(0x10000)
            self._run_plain = self._run_blocks
        else:
            self._run_plain = self._run_spin
        self._init_run_ahead(run_ahead)     # running ahead (ahead.py)
        #: cycles between two calls of the scheduler's progress hook
        self.progress_every = 10_000_000
        #: skipping the periods of a steady state (steady.py), or None
        self._steady = None
        if steady_skip and fast_forward:
            from .steady import LOOK_EVERY, SteadySkip
            self._steady = SteadySkip(self)
            self.progress_every = LOOK_EVERY
        self.now = 0
        #: the run's cycle limit (engines that run ahead never pass it)
        self.run_limit = _NEVER
        self._last_stop = 0
        self._last_limit = _NEVER       # the limit of the latest advance()
        self.pasm = None            # the PASM engine (pasm_cog.py), made when a PASM cog starts
        self._clock_mode = self.header.clkmode
        if self.checks is not None:
            self.checks.install()

    def wrap_handler(self, op: int, handler, rewrap=None) -> None:
        """Replace the interpreter's handler for bytecode ``op`` (runtime checks, tools).

        ``rewrap(inner)``, if given, makes the same wrapper around another
        handler: the copies of the interpreter that learn busy loops and record
        steady states (fastforward.py, steady.py) are then wrapped alike, so
        they run the bytecode as the chip does.  Without it the steady-state
        skip stays off.  No cog runs ahead from then on (the checked copy of the
        handlers that running ahead needs, ahead.py, would not have the wrapped
        one).
        """
        self.handlers[op] = handler
        self._handlers[op] = handler
        self._handlers_wrapped = True
        self._wraps.append((op, rewrap))

    def wrap_copy(self, handlers: list) -> list:
        """Wrap ``handlers`` (a copy of the interpreter's) as :meth:`wrap_handler` wrapped the chip's own."""
        for op, rewrap in self._wraps:
            if rewrap is not None:
                handlers[op] = rewrap(handlers[op])
        return handlers


    @property
    def drive_history(self):
        """What the cogs drove on the pins, for bench parts (:class:`spinemu.chip.drives.ChipDrives`)."""
        if self._drives is None:
            from .drives import ChipDrives
            self._drives = ChipDrives(self)
        return self._drives

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
    def start_spin_cog(self, c: Cog, par: int, t_first: int, by: Cog | None) -> None:
        """Start the Spin interpreter in cog ``c``; its first instruction runs at ``t_first``."""
        keep = (c.dira, c.outa) if self.spinsim else (0, 0)
        c.reset_registers()
        c.dira, c.outa = keep
        c.par = par & 0xFFFC
        c.engine = "spin"
        c.state = RUNNING
        self._cogs_changed = True
        c.started_at = t_first
        m = self.mem_words
        base = (par & 0xFFFC) + 2
        c.pbase, c.vbase, c.dbase, c.pc, c.sp = (m[((base + 2 * i) & 0xFFFF) >> 1] for i in range(5))
        c.scratch[9] = c.id
        c.dcall = 0
        c.t = self.timing.interpreter_start(t_first, c.hub_phase)
        if self.checks is not None:
            self.checks.cog_started(c)
        self.cog_events.append((t_first, c.id, "start",
                                f"Spin method at ${c.pc:04X}" + (f" (started by cog {by.id})" if by else "")))
        if keep != (0, 0):
            self.note_pins(c, t_first)

    def stop_cog(self, c: Cog, t: int, why: str, by: Cog | None = None, seen: int | None = None,
                 restart: bool = False) -> None:
        """Stop cog ``c`` at cycle ``t`` (its pins float then).

        ``by`` is the cog whose instruction stops it (default ``c``) and
        ``seen`` the cycle of that instruction's access (default ``t``): a
        pin read by another cog at that cycle sees the stop when ``by``'s id
        is lower, a later one always (as for a pin write, :meth:`note_pins`).
        ``restart``: a COGINIT restarts it at once; in spinsim mode the cog keeps
        its DIRA/OUTA across the restart (``start_spin_cog``), so its pins never float.
        """
        if c.state == STOPPED:
            return
        if c.state == PARKED:
            self._unpark(c, t)
        self._stop_ahead(c)
        if self._pend:                          # stopped before its update's write-back: none comes
            self._drop_pending(c)
        if c in self._pin_waiters:
            self._pin_waiters.remove(c)
        h = c.pin_hist
        if h and h[-1][0] > t:                  # stopped inside a bytecode, before the write it made
            c.dira, c.outa, _ = self._pins_before(c, t)     # (the record drops the write: pinfold, pinhistory)
        c.state = STOPPED
        self._cogs_changed = True
        c.pin_wait = None
        c.t = _NEVER
        self.now = max(self.now, t)
        self._last_stop = max(self._last_stop, t)
        self.cog_events.append((t, c.id, "stop", why))
        if restart and self.spinsim:
            return
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, c.outa, False))
        self._pin_history(c, t, False)
        if self._pin_waiters and c.dira:        # the pins it drove float: cogs waiting on them may wake
            seen = t if seen is None else seen
            self._wake_pin_waiters(seen + 4, c if by is None else by, seen)

    def coginit(self, c: Cog, cog_id: int, code: int, par: int, tf: int) -> int:
        """COGINIT/COGNEW bytecode of Spin cog ``c``: returns the started cog's id, or -1 (as u32)."""
        return self.start_cog(c, cog_id, code, par, tf + self.timing.coginit_done)

    def start_cog(self, c: Cog, cog_id: int, code: int, par: int, done: int) -> int:
        """Start cog ``cog_id`` (8 and up: the first free one) on ``code`` with ``par``.

        ``done`` is the cycle the COGINIT's hub access completes (a running
        target stops then).  The interpreter's address starts a Spin cog,
        any other address a PASM cog.  Returns the cog's id, or -1 (as u32)
        when no cog is free.
        """
        if cog_id >= 8:                         # the ROM clamps: 8 and up = "a free cog"
            free = [k for k in self.cogs if k.state == STOPPED]
            if not free:
                if self.checks is not None:
                    self.checks.no_free_cog(c, code, par, done)
                return 0xFFFFFFFF
            target = free[0]
        else:
            target = self.cogs[cog_id]
        if target.state != STOPPED:
            self.stop_cog(target, done, f"restarted by cog {c.id}", by=c, seen=done - 4, restart=True)
        if self.spinsim:
            # the new cog's first slot is the COGINIT's last cycle, one step later
            # when spinsim has already stepped the target in that cycle (a lower id, or itself)
            t_first = done + _SPINSIM_START_CYCLES + (4 if target.id <= c.id else 0)
        else:
            t_first = done + COG_LOAD_CYCLES
        if (code & 0xFFFC) == INTERPRETER_ENTRY & 0xFFFC:
            self.start_spin_cog(target, par, t_first, c)
        else:
            self._start_pasm(target, code & 0xFFFC, par & 0xFFFC, t_first, c)
        return target.id

    def _start_pasm(self, target: Cog, code: int, par: int, t_first: int, by: Cog) -> None:
        if self.pasm is None:
            from .pasm_cog import PasmEngine
            self.pasm = PasmEngine(self)
            for cog_id, callback in self._pasm_tracers.items():
                self.pasm.tracers[cog_id] = callback
        self.pasm.start(target, code, par, t_first, by)

    def code_label(self, hub_addr: int) -> str:
        """The DAT label at ``hub_addr`` (from ``labels``), else the source line, else ``""``."""
        name = self.labels.get(hub_addr & 0xFFFF)
        if name:
            return name
        if self.source_map is not None:
            try:
                found = self.source_map(hub_addr & 0xFFFF)
            except Exception:  # a broken map must not stop the run
                found = None
            if found:
                return f"{found[0]}:{found[1]}"
        return ""

    def trace_cog(self, cog_id: int, callback: Callable | None) -> None:
        """Report every PASM instruction cog ``cog_id`` executes to ``callback``.

        ``callback(step)`` gets a :class:`spinemu.chip.pasm_cog.PasmStep`
        (cycle, cog, address, long, whether it ran, flags after it, the value
        written); ``step.text()`` is one log line.  The traced cog runs an
        instrumented loop; the others are not slowed down.  Call before
        :meth:`run` (or between :meth:`advance` calls: a debugger does);
        ``callback=None`` ends the tracing.  A callback with a ``before(cog)``
        method is called before each instruction too
        (:meth:`~spinemu.chip.pasm_cog.PasmEngine.run_traced`).
        """
        if callback is None:
            self._pasm_tracers.pop(cog_id, None)
            if self.pasm is not None:
                self.pasm.tracers.pop(cog_id, None)
            return
        self._pasm_tracers[cog_id] = callback
        if self.pasm is not None:
            self.pasm.tracers[cog_id] = callback

    def cogstop(self, c: Cog, cog_id: int, tf: int, rest: int) -> int:
        t = tf + self.timing.cogstop_at
        target = self.cogs[cog_id]
        if target is c:
            self.stop_cog(c, t, "COGSTOP of itself" if c.pc != 0xFFFC else "returned from its top method")
            raise CogStopped(rest)
        if target.state != STOPPED:
            self.stop_cog(target, t, f"stopped by cog {c.id}", by=c)
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
        # spinsim too frees lock 0 (checked on spinsim 0.99: LOCKRET(0), then LOCKNEW gives 0)
        self.lock_used[i] = False

    def lockset(self, i: int, value: bool) -> bool:
        was = self.locks[i]
        self.locks[i] = value
        return was

    # ------------------------------------------------------------------ clock, video
    def set_clock_mode(self, mode: int) -> None:
        """CLKSET from PASM (the CLK register only; clkfreq in hub RAM is the program's business)."""
        if mode != self._clock_mode:
            self._clock_mode = mode
            self.warnings.append(f"CLKSET set the clock mode to ${mode:02X}; trace times stay in cycles")

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


    # ------------------------------------------------------------------ RUN
    def run_helper(self, c: Cog, tf: int) -> int:
        from .runhelper import run_spin_method
        return run_spin_method(self, c, tf)

    # ------------------------------------------------------------------ running
    def run(self, max_cycles: int | None = None, progress: Callable[[int], None] | None = None) -> RunResult:
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
        reason = self.advance(max_cycles, progress)
        return self.result(reason, time.perf_counter() - wall)

    def advance(self, until: int | None = None, progress: Callable[[int], None] | None = None) -> str:
        """Run on from where the chip is until cycle ``until`` (``None``: until every cog stops).

        Unlike :meth:`run`, this can be called again and again (the test
        harness and the debugger do): the chip goes on exactly as one long
        run would.  Returns why it stopped: a :class:`RunResult` reason, or
        the reason a probe gave when it stopped the run (a breakpoint).
        """
        limit = _NEVER if until is None else until
        if not self._booted:
            self._boot()
        self._cogs_changed = True
        self._last_limit = limit
        self._listen_end = limit + 1 if limit < _NEVER else _NEVER
        try:
            if self._steady is not None:
                return self._steady.advance(limit, progress)
            return self._schedule(limit, progress)
        except Halted as h:
            return h.reason
        finally:
            if self._halt_reason is not None:   # a halt nobody reached: forget it
                self._halt_reason = None
                self.handlers[:] = self._handlers
                self._preempt = False

    def result(self, reason: str = "cycle limit", wall: float = 0.0) -> RunResult:
        """The :class:`RunResult` of the run so far (trace, hub RAM, statistics) at cycle ``now``."""
        end = self._last_limit if reason == "cycle limit" and self._last_limit < _NEVER else self.now
        if reason == "all cogs stopped":        # an engine may stop a cog ahead of another's last events
            end = max(end, self._last_stop)
        if self.pin_listeners:      # pins nothing can change any more stay as they are for ever
            self._listen_end = end + 1
            self._deliver_pins(_NEVER if reason in _FINAL_REASONS else end + 1, end + 1)
            self._run_ended(end)
        trace = self._build_trace(end)
        warnings = list(self.warnings) + list(self.counters.end_warnings(end))
        per_cog = {c.id: c.bytecodes for c in self.cogs if c.bytecodes}
        pasm_cogs = {c.id: c.instructions for c in self.cogs if c.instructions}
        stats = {"bytecodes": sum(per_cog.values()), "bytecodes_per_cog": per_cog,
                 "pasm_instructions": sum(pasm_cogs.values()), "pasm_instructions_per_cog": pasm_cogs,
                 "wall_seconds": wall, "simulated_seconds": end / self.clock_hz if self.clock_hz else 0.0}
        stats["realtime_factor"] = stats["simulated_seconds"] / wall if wall > 0 else 0.0
        stats.update(self._ff_stats())
        if self.pasm is not None:
            stats.update(self.pasm.stats())
        stats["pll"] = [p._asdict() for p in self.counters.pll_outputs(end)]
        return RunResult(trace, bytes(self.mem[:HUB_SIZE]), end, reason, list(self.cog_events),
                         warnings, stats,
                         list(self.warning_log.items) if self.warning_log is not None else [])

    # ------------------------------------------------------------------ tools
    def peek(self, hub_addr: int, size: int = 4) -> int:
        """The byte, word or long (``size`` 1, 2, 4) of hub RAM at ``hub_addr`` (unsigned).

        An update whose bytecode has run but whose write-back still waits for its
        moment (``Scheduler.defer_write``: another cog's access comes first) shows
        its new value: what the cog wrote, as a debugger or test reads it between
        bytecodes.
        """
        a = hub_addr & 0xFFFF
        if self._pend:
            mem = bytearray(self.mem[a & ~3: (a & ~3) + 4])
            for _key, _id, _c, psize, pa, v, _t in self._pend:
                for k in range(1 << psize):
                    if (pa + k) & ~3 == a & ~3:
                        mem[(pa + k) & 3] = (v >> (8 * k)) & 0xFF
            return int.from_bytes(mem[a & 3: (a & 3) + size], "little")
        if size == 1:
            return self.mem[a]
        if size == 2:
            return self.mem_words[a >> 1]
        return self.mem_longs[a >> 2]

    def poke(self, hub_addr: int, value: int, size: int = 4) -> None:
        """Write hub RAM from outside the program, now (between bytecodes).

        A parked busy loop that reads the long is brought up to the present
        first, so the program sees the new value exactly from this cycle on.
        """
        a = hub_addr & 0xFFFF
        if a >= HUB_SIZE:
            raise ValueError(f"${a:04X} is not in hub RAM ($0000-$7FFF)")
        for p in list(self._parked):
            if any(((i << shift) & 0xFFFF) >> 2 == a >> 2 for shift, i, _ in p.busy.reads):
                self._unpark(p, self.now)
                self._cogs_changed = True
        if size == 1:
            self.mem[a] = value & 0xFF
        elif size == 2:
            self.mem_words[a >> 1] = value & 0xFFFF
        else:
            self.mem_longs[a >> 2] = value & 0xFFFFFFFF

    def release_pin_wait(self, cog_id: int, t: int | None = None) -> None:
        """End cog ``cog_id``'s WAITPEQ/WAITPNE as if its condition had come true at cycle ``t`` (default ``now``)."""
        c = self.cogs[cog_id]
        if c.state != PIN_WAIT:
            raise ValueError(f"cog {cog_id} is not waiting on pins")
        after = c.pin_wait[3]
        self._pin_waiters.remove(c)
        c.pin_wait = None
        c.state = RUNNING
        c.t = (self.now if t is None else t) + after
        self._cogs_changed = True

    def pin_trace(self, until: int | None = None):
        """The :class:`~spinemu.trace.PinTrace` of the run so far (up to ``until``, default ``now``)."""
        return self._build_trace(self.now if until is None else until)

    def _ff_stats(self) -> dict:
        return {"fast_forward": self.fast_forward, "busy_loops_learned": self._ff_loops,
                "bytecodes_skipped": self._ff_skipped,
                "blocks_compiled": self._compiler.count if self._compiler is not None else 0,
                "run_ahead": self.run_ahead, "private_stretches": self._stretches, "rollbacks": self._rollbacks,
                "steady_periods_skipped": self._steady.periods if self._steady is not None else 0,
                "steady_bytecodes_skipped": self._steady.skipped if self._steady is not None else 0}


    def _boot(self) -> None:
        self._booted = True
        self._ext_seen = 0
        self._pin_waiters = []
        self._reactive_inputs = bool(getattr(self.inputs, "reactive", False))
        self._video_ready = [0] * 8
        cog0 = self.cogs[0]
        # The boot loader starts the interpreter in cog 0 with PAR = $0004
        # (pbase, vbase, dbase, pcurr, dcurr at $0006..$000E).  Cycle 0 is the
        # first instruction of that interpreter in both modes: the boot
        # loader's own time (reading the EEPROM, loading cog 0) is not counted.
        t_first = 0
        self.start_spin_cog(cog0, 0x0004, t_first, None)
        self.cog_events[-1] = (t_first, 0, "start", f"Spin method at ${cog0.pc:04X} (boot)")


def _default_log(debug_info, source_map):
    """A WarningLog that places warnings with the debug info (file:line:col) or the source map."""
    from ..runtime_warnings import WarningLog

    if debug_info is not None:
        return WarningLog(debug_info.position, debug_info.source_line)
    return WarningLog(source_map)

