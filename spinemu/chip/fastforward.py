"""Exact fast-forward of busy-wait loops (``repeat until motor.getSteps == 0``).

A cog that spins in a loop which changes nothing costs the interpreter a
bytecode every ~150 cycles for seconds of simulated time.  This module finds
such loops and lets the scheduler skip whole iterations without changing a
single result:

1. **Learning.**  A cog that ran many bytecodes without waiting is run for a
   while by a tracking copy of the interpreter, which records every hub read
   and write.  A stretch between two visits of the same bytecode address with
   the same cog state (registers, stack pointers, ``t mod 16``) is an
   *iteration*.  It qualifies when every write in it wrote the value already
   there, it used no time-dependent input (CNT, INA, PHSx), touched no cog
   register, lock, cog or clock, and did not wait.  Such an iteration is a
   pure function of the hub values it read: as long as those values stay the
   same, the cog repeats it exactly, every ``period`` cycles.
2. **Skipping.**  When the scheduler next runs that cog at the loop head, with
   the same state and every value in the iteration's read set unchanged, it
   advances the cog by as many whole periods as fit before the next bytecode
   of any other cog (and before the cycle limit or an input change).  Those
   iterations would have run before anything else happened on the chip and
   read unchanged memory, so they would have done exactly what was learned.
   The cog then continues normally; if another cog has changed something the
   loop reads, the check fails and the cog is simply interpreted again.

Skipped bytecodes are counted in the statistics as executed.
"""
from __future__ import annotations

from .ahead import _WRITE_CHECKED, AHEAD

__all__ = ["BusyLoop", "LoopMemory", "LoggedView", "learn_busy_loop", "IMPURE_OPS", "LEARN_AFTER", "LEARN_HORIZON"]

#: bytecodes a cog runs without a wait before a learning attempt
LEARN_AFTER = 2000
#: learn only when the cog has this many cycles to itself (its loop must repeat in them)
LEARN_HORIZON = 20_000
#: bytecodes the tracking interpreter runs in one attempt
LEARN_BUDGET = 600
#: repeated states whose iteration was not pure after which an attempt gives up
LEARN_TRIES = 4
#: what :func:`learn_busy_loop` returns when it had to stop before finding a loop
INTERRUPTED = "interrupted"
#: opcodes that touch time, pins, cogs, locks, the clock, or wait
IMPURE_OPS = frozenset({0x15, 0x1B, 0x1F, 0x20, 0x21, 0x22, 0x23, 0x25, 0x26, 0x27}
                       | set(range(0x28, 0x30)))
_TIME_REGS = frozenset({0x1F1, 0x1F2, 0x1FC, 0x1FD})


class LoggedView:
    """A memory view that logs every access as ``(write, shift, index, old, new)``: a read as
    ``(0, shift, index, value, None)``, a write as ``(1, shift, index, old value, new value)``
    (``shift`` 0 for bytes, 1 words, 2 longs).  The learner here and the steady-state recorder
    (steady.py) read their logs in this form.
    """

    __slots__ = ("view", "shift", "log")

    def __init__(self, view, shift, log):
        self.view, self.shift, self.log = view, shift, log

    def __getitem__(self, i):
        v = self.view[i]
        if isinstance(i, slice):
            for k in range(*i.indices(len(self.view))):
                self.log.append((0, self.shift, k, self.view[k], None))
        else:
            self.log.append((0, self.shift, i, v, None))
        return v

    def __setitem__(self, i, v):
        if isinstance(i, slice):
            old = list(self.view[i])
            self.view[i] = v
            for k, a, b in zip(range(*i.indices(len(self.view))), old, self.view[i]):
                self.log.append((1, self.shift, k, a, b))
        else:
            self.log.append((1, self.shift, i, self.view[i], v))
            self.view[i] = v

    def __len__(self):
        return len(self.view)


class _TrackedView(LoggedView):
    """A :class:`LoggedView` for the learner.

    Like the guarded interpreter's views (ahead.py) it first rolls back a cog
    that is ahead if the access reaches into its window.
    """

    __slots__ = ("chip", "watch")

    def __init__(self, view, shift, log, chip):
        LoggedView.__init__(self, view, shift, log)
        self.chip, self.watch = chip, chip.watch

    def _guard(self, i, write=False):
        if isinstance(i, slice):
            start, stop, _ = i.indices(len(self.view))
            if start < stop:
                self.chip._guard_range(start << self.shift, stop << self.shift, write)
        elif self.watch[((i << self.shift) & 0xFFFF) >> 2] & (_WRITE_CHECKED if write else AHEAD):
            if write:
                self.chip._guard_write(i << self.shift)
            else:
                chip = self.chip
                chip._intrude(chip._g_cog, i << self.shift, chip._g_key)

    def __getitem__(self, i):
        self._guard(i)
        return LoggedView.__getitem__(self, i)

    def __setitem__(self, i, v):
        self._guard(i, True)
        LoggedView.__setitem__(self, i, v)


class _TrackingChip:
    """The chip as the tracking interpreter sees it: memory views log accesses."""

    def __init__(self, chip, log):
        self._chip = chip
        self.mem = self._view(chip.mem, 0, log)
        self.mem_words = self._view(chip.mem_words, 1, log)
        self.mem_longs = self._view(chip.mem_longs, 2, log)
        self.registers = chip.registers

    def _view(self, view, shift: int, log: list):
        return _TrackedView(view, shift, log, self._chip)

    def __getattr__(self, name):
        return getattr(self._chip, name)

    def __setattr__(self, name, value):
        if name in ("_chip", "mem", "mem_words", "mem_longs", "registers"):
            object.__setattr__(self, name, value)
        else:
            setattr(self._chip, name, value)


class BusyLoop:
    """A learned pure loop of one cog.

    Attributes:
        head: bytecode address where an iteration starts.
        state: the cog state at the head (see :func:`cog_state`).
        phase: ``t mod 16`` at the head.
        period: cycles per iteration (a multiple of 16).
        bytecodes: bytecodes per iteration.
        reads: ``(shift, index, value)``: every hub value the iteration read.
        longs: the hub longs the iteration reads or writes, outside its own stack
            above the lowest stack pointer (no cog may run ahead through them, ahead.py).
    """

    __slots__ = ("head", "state", "phase", "period", "bytecodes", "reads", "skipped", "longs")

    def __init__(self, head, state, phase, period, bytecodes, reads, longs=()):
        self.head, self.state, self.phase = head, state, phase
        self.period, self.bytecodes, self.reads = period, bytecodes, reads
        self.skipped = 0
        self.longs = longs

    def still_valid(self, chip, c) -> bool:
        """Is cog ``c`` at the head, in the learned state, with the memory it reads unchanged?"""
        if c.pc != self.head or (c.t & 15) != self.phase or cog_state(c) != self.state:
            return False
        views = (chip.mem, chip.mem_words, chip.mem_longs)
        for shift, i, v in self.reads:
            if views[shift][i] != v:
                return False
        return True


class LoopMemory:
    """The busy loops learned so far, found again by the values they read.

    A parked loop is woken when a value it reads changes (``repeat until
    motor.getSteps == 0`` wakes at every step).  The loop the cog then runs
    is the same code in the same state, but its learned iteration was only
    proven for the old values; one proven for the new values may have been
    learned before (the stepper counts the same steps down again), and is
    as good as a new one: :meth:`BusyLoop.still_valid` checks the same things.
    """

    #: loops kept per cog and loop head (the oldest are dropped first)
    KEEP = 256

    def __init__(self):
        # (cog id, head, t mod 16, state) -> {read addresses: {read values: loop}}
        self._loops: dict = {}

    def add(self, c, loop: "BusyLoop") -> None:
        key = (c.id, loop.head, loop.phase, loop.state)
        shapes = self._loops.setdefault(key, {})
        addrs = tuple((s, i) for s, i, _ in loop.reads)
        known = shapes.setdefault(addrs, {})
        if len(known) >= self.KEEP:
            del known[next(iter(known))]
        known[tuple(v for _, _, v in loop.reads)] = loop

    def find(self, chip, c):
        """A remembered loop cog ``c`` (at a loop head) would run now, or ``None``."""
        shapes = self._loops.get((c.id, c.pc, c.t & 15, cog_state(c)))
        if not shapes:
            return None
        views = (chip.mem, chip.mem_words, chip.mem_longs)
        for addrs, known in shapes.items():
            loop = known.get(tuple(views[s][i] for s, i in addrs))
            if loop is not None:
                return loop
        return None


def cog_state(c) -> tuple:
    """Everything of a Spin cog's state a loop iteration could depend on, besides hub RAM."""
    return (c.pc, c.pc_hi, c.sp, c.dbase, c.pbase, c.pbase_hi, c.vbase, c.dcall, tuple(c.scratch),
            c.outa, c.dira, c.ctra, c.ctrb, c.frqa, c.frqb, c.vcfg, c.vscl, c.par)


def _impure(chip, c, op: int) -> bool:
    if op in IMPURE_OPS:
        return True
    if op in (0x3D, 0x3E, 0x3F):
        b = chip.mem[(c.pc + 1) & 0xFFFF]
        return (b >> 5) & 3 != 0 or (0x1E0 + (b & 0x1F)) in _TIME_REGS
    if op == 0x24:                  # SPR push: the index is on the stack
        return (0x1F0 + (chip.mem_longs[((c.sp - 4) & 0xFFFF) >> 2] & 0xF)) in _TIME_REGS
    return False


def learn_busy_loop(chip, c, handlers, log, limit: int):
    """Run cog ``c`` with the tracking interpreter and look for a pure loop.

    Executes up to :data:`LEARN_BUDGET` bytecodes (they really run: this is
    normal execution, only slower), stopping early at an impure bytecode or at
    ``limit``.  Returns a :class:`BusyLoop`, ``None`` (no pure loop found), or
    :data:`INTERRUPTED` (another cog's turn came first: try again soon).
    """
    mem = chip.mem
    log.clear()
    seen = {}                       # (pc, state, t mod 16) -> index into marks
    marks = []                      # per bytecode: (t, log position, stack pointer)
    P = c.hub_phase
    from .control import RebootRequested, Reschedule  # local: keep module import light
    chip.learn_tracked = 0
    chip.rmw_limit = limit
    failed = 0
    wlog = chip.warning_log
    warned = wlog.total if wlog is not None else 0
    for _ in range(LEARN_BUDGET):
        chip.learn_tracked += 1
        if c.state != "running" or chip._preempt:
            return INTERRUPTED
        op = mem[c.pc]
        tf = c.t + 12
        tf += (P - tf) & 15
        akey = tf + chip.access_offset(c.pc)
        if akey >= limit:
            return INTERRUPTED
        if _impure(chip, c, op):
            return None
        if chip.watch[c.pc >> 2] & AHEAD:   # code in the window of a cog ahead: the exact order decides
            return INTERRUPTED
        key = (c.pc, c.t & 15, cog_state(c))
        if key in seen:
            start = seen[key]
            t0, pos0, _ = marks[start]
            low_sp = min(m[2] for m in marks[start:])
            loop = _qualify(chip, log[pos0:], key, c.t - t0, len(marks) - start, low_sp)
            if loop is not None:
                return loop
            failed += 1
            if failed >= LEARN_TRIES:       # it keeps changing what it writes: not a busy-wait
                return None
            seen.clear()
            marks.clear()
            log.clear()
        seen[key] = len(marks)
        marks.append((c.t, len(log), c.sp))
        t = c.t
        c.pc = (c.pc + 1) & 0xFFFF
        chip._g_cog, chip._g_key = c, akey
        try:
            c.t = tf + handlers[op](c, op, t)
        except Reschedule as e:      # not expected for pure ops; be safe
            c.t = tf + e.rest
            return None
        except RebootRequested:
            chip._reboot_key = akey
            raise
        except IndexError:          # as the run loops: a stack or address past the end of memory
            raise chip.fault(c, c.pc - 1, "stack or address out of hub range") from None
        c.bytecodes += 1
        if wlog is not None and wlog.total != warned:
            return None             # a runtime check warned: skipping its repeats would lose them
    return None


def _qualify(chip, entries, key, period: int, bytecodes: int, sp_head: int):
    """A :class:`BusyLoop` if the logged iteration is pure, else ``None``.

    Pure: every byte it wrote ends the iteration with the value it had at the
    start, and bytes that change in between lie above the cog's stack pointer
    at its lowest point in the iteration (``sp_head``: the cog's own unused
    stack, which no other cog reads).
    The read set is every value it read that it had not written itself first.
    """
    if period <= 0 or period % 16:
        return None
    mem = chip.mem
    written = {}                    # byte address -> value at the start of the iteration
    reads = {}
    for write, shift, i, old, new in entries:
        size = 1 << shift
        base = i << shift
        if write:
            for k in range(size):
                b = base + k
                if b not in written:
                    written[b] = (old >> (8 * k)) & 0xFF
            if old != new and base < sp_head:
                return None
        elif (shift, i) not in reads:
            inside = [base + k in written for k in range(size)]
            if all(inside):
                continue
            if any(inside):
                return None
            reads[(shift, i)] = old
    for b, v in written.items():
        if mem[b] != v:
            return None
    pc, phase, state = key
    longs = {((i << s) & 0xFFFF) >> 2 for s, i in reads} | {(b & 0xFFFF) >> 2 for b in written if b < sp_head}
    return BusyLoop(pc, state, phase, period, bytecodes,
                    tuple((s, i, v) for (s, i), v in reads.items()), tuple(sorted(k for k in longs if k < 0x2000)))


def tracking_handlers(chip, timing):
    """The interpreter's handlers bound to logging memory views, wrapped as the chip's are (runtime
    checks: Chip.wrap_handler); returns ``(handlers, log)``."""
    from .spin import build_handlers
    log = []
    return chip.wrap_copy(build_handlers(_TrackingChip(chip, log), timing)), log
