"""Idle PASM loops cost nothing: a cog that polls is parked until what it reads changes.

PASM drivers spend most of their time polling: FullDuplexSerial's receive
and transmit coroutines (``jmpret``) test the RX pin and the buffer pointers
in hub RAM, a ``waitpeq``-style loop tests INA, a mailbox loop reads a hub
long until it changes, a delay loop compares CNT with a deadline.  Run
instruction by instruction, that is 20 million instructions a second of
simulated time that change nothing.  :class:`IdleSkipper` finds such loops
and skips them exactly:

1. **Learning.**  Every so often (:data:`FIRST_OFFER` cycles, doubling up to
   :data:`MAX_INTERVAL` while nothing is found) the run loop offers the cog
   where it stands.  The skipper runs one *pass* from there, back to the
   same address, on a copy of cog RAM, through the engine's own handlers
   (:class:`TrackingBuilder`: the same generated code, with hub and INA reads
   recorded, CNT read as an :class:`~.pasm_affine.Aff`, and anything with an
   effect outside the cog refused: pin, counter or changing hub writes,
   waits, hub operations).
2. **Qualifying.**  The pass qualifies when it ends where it began with the
   same cog RAM and flags, except registers that it writes from CNT before
   reading them (their value is then known for every pass), read INA at most
   once, and, if it used the hub, took a multiple of 16 cycles.  Then every
   further pass does exactly the same as long as the hub longs and the pins
   it read stay the same, and as long as each comparison involving CNT gives
   the same answer: :func:`~.pasm_affine.first_change` says for how many
   passes (the *horizon*; none for loops that do not read CNT).
3. **Parking.**  The cog is taken out of the schedule (``PARKED``) and
   reports the end of its horizon as its next event, so a program whose
   only live cogs are idle loops advances from event to event.  It is woken
   exactly where its passes stop being the learned one:

   * a hub write to a long it reads (``Chip.watch``, as for Spin's busy
     loops): before the write, the cog is brought to the last pass that
     starts before it and runs normally up to the write;
   * a change of the pins it reads (it waits like a ``WAITPNE`` on them: a
     cog's OUTA/DIRA write, the input model, a counter, a console's RX):
     the cog resumes at the pass whose INA read is the first to see it;
   * the horizon: it resumes at that pass;
   * the run's end, a COGSTOP: it is brought up to that cycle.

   Resuming at pass ``j`` sets the registers written from CNT to their value
   in pass ``j - 1``, the cycle to ``t0 + j * period`` and counts the skipped
   instructions; the cog then runs its instructions as usual.

Nothing a program can observe changes: the same pin trace, hub RAM, end
cycle and instruction counts as running every instruction
(tests/chip/test_pasm_speed.py runs random programs both ways).
"""
from __future__ import annotations

from .. import pasm as isa
from .blocks import BUSY
from .cog import PARKED, RUNNING
from .pasm_affine import Aff, Predicates, Unsupported, first_change
from .pasm_ops import AUX, FAMILIES, Fetched, HandlerBuilder, Handlers, Leave, Yield

__all__ = ["IdleSkipper", "IdleLoop", "TrackingBuilder", "FIRST_OFFER", "MAX_INTERVAL", "MIN_PASSES"]

NEVER = 1 << 62
M = 0xFFFFFFFF
#: cycles a PASM cog runs before its loop is first offered to the skipper
FIRST_OFFER = 4096
#: the longest interval between two offers while the cog's loops do not qualify
MAX_INTERVAL = 1 << 22
#: a loop is parked only when at least this many passes can be skipped
MIN_PASSES = 4
#: instructions and cycles in one pass at most
MAX_PASS_INSTRUCTIONS = 256
MAX_PASS_CYCLES = 1 << 14
_INA = isa.REGISTERS["INA"]
_MASKING = {("alu", "and"), ("alu", "andn")}


class Impure(Exception):
    """The pass did something with an effect outside its cog: it is no idle loop."""


class IdleLoop:
    """A parked loop (the cog's ``busy``): what it reads, its period, how far it is known.

    Attributes:
        head: the cog address a pass starts at.
        t0: the cycle pass 0 starts.
        period: cycles per pass.
        per_pass: instructions per pass.
        horizon: passes known to run as learned (``None``: until something it reads changes).
        cnt_regs: ``{register: Aff}``: registers each pass writes from CNT.
        reads: ``(2, long index, value)`` of the hub longs a pass reads (the scheduler's watch format).
        ina: ``(offset in the pass, mask, value)`` of its INA read, or ``None``.
        last: the offset of the pass's latest access to shared state (``None``: it has none).
    """

    __slots__ = ("head", "t0", "period", "per_pass", "horizon", "cnt_regs", "reads", "ina", "last")

    def __init__(self, head, t0, period, per_pass, horizon, cnt_regs, reads, ina, last):
        self.head, self.t0, self.period, self.per_pass = head, t0, period, per_pass
        self.horizon, self.cnt_regs, self.reads, self.ina, self.last = horizon, cnt_regs, reads, ina, last

    def end(self) -> int:
        """The cycle its horizon ends (``NEVER`` without one)."""
        return NEVER if self.horizon is None else self.t0 + self.horizon * self.period


class _Pass:
    """What one learning pass saw."""

    def __init__(self):
        self.hub_reads: dict = {}        # long index -> value
        self.ina: list = []              # (cycle, value, mask)
        self.hub = False
        self.last_access = None          # the cycle of its latest access to shared state
        self.predicates = Predicates()
        self.word = 0                    # the instruction being run
        self.ram = None


class _TrackedRam(list):
    """Cog RAM for a learning pass: which registers it read before writing them, and which it wrote."""

    def __init__(self, ram):
        super().__init__(ram)
        self.read_first: set = set()
        self.written: set = set()

    def __getitem__(self, i):
        if i not in self.written:
            self.read_first.add(i)
        return list.__getitem__(self, i)

    def __setitem__(self, i, v):
        self.written.add(i)
        list.__setitem__(self, i, v)


class _TrackedHub:
    """A hub view for a learning pass: reads recorded by long, writes allowed only when they change nothing."""

    def __init__(self, view, shift: int, seen: list):
        self.view, self.shift, self.seen = view, shift, seen

    def __getitem__(self, i):
        p = self.seen[0]
        p.hub = True
        long_index = (i << self.shift) >> 2
        p.hub_reads.setdefault(long_index, self.view.obj_longs[long_index])
        return self.view.data[i]

    def __setitem__(self, i, v):
        p = self.seen[0]
        p.hub = True
        if self.view.data[i] != v:
            raise Impure("a hub write that changes memory")
        long_index = (i << self.shift) >> 2         # watched too: another cog's write there changes what
        p.hub_reads.setdefault(long_index, self.view.obj_longs[long_index])    # later passes would do


class _View:
    def __init__(self, data, obj_longs):
        self.data, self.obj_longs = data, obj_longs


class _NoChip:
    """What handlers see of the chip during a learning pass (nothing that acts)."""

    _preempt = False

    def watch_hit_at(self, *args):          # pragma: no cover - the learning WATCH is all zero
        raise Impure("watched write")


def _impure(*args, **kwargs):
    raise Impure("an effect outside the cog")


def _impure_handler(R, pc, t):
    raise Impure("a hub operation or a wait")


class TrackingBuilder(HandlerBuilder):
    """The engine's handler generator, bound to recording stand-ins for the chip (learning passes).

    The handlers are the engine's own code, generated from the same table;
    only their globals differ: hub views that record reads, an INA that
    records its reads, CNT as an :class:`~.pasm_affine.Aff`, and stand-ins
    that refuse pin and counter writes, PHS reads and waits.
    """

    def __init__(self, engine, seen: list):
        super().__init__(engine)
        chip = engine.chip
        self.seen = seen
        longs = chip.mem_longs
        self.env.update({
            "U": [NEVER], "CH": _NoChip(), "WREG": _impure, "PHS": _impure, "ENG": None,
            "WATCH": bytes(len(chip.watch)), "INA": self._ina, "CNTV": self._cnt,
            "MEM": _TrackedHub(_View(chip.mem, longs), 0, seen),
            "W": _TrackedHub(_View(chip.mem_words, longs), 1, seen),
            "L": _TrackedHub(_View(longs, longs), 2, seen),
        })
        self.ina_now = chip.ina

    def _ina(self, t):
        p = self.seen[0]
        word = p.word
        mask = M
        if FAMILIES[word >> 26] in _MASKING and not word & isa.I_BIT and word & 0x1FF == _INA:
            d = list.__getitem__(p.ram, (word >> 9) & 0x1FF)
            if d.__class__ is int:
                mask = d                    # `test mask, ina`: only the masked pins matter
        v = self.ina_now(t)
        p.ina.append((t, v, mask))
        p.last_access = t
        return v

    def _cnt(self, t):
        return Aff.make(t & M, 1, 0, True, self.seen[0].predicates)

    def _source(self, word, checks):
        e = super()._source(word, checks)
        return "CNTV(t)" if e == "t & M" else e

    def build(self, word: int):
        fam = FAMILIES[word >> 26][0]
        if (word >> 18) & 15 and fam in ("hubop", "undefined", "wait"):
            return _impure_handler
        return super().build(word)


class IdleSkipper:
    """Finds, parks and wakes idle loops of one engine's cogs (see the module docstring).

    Args:
        engine: the :class:`~.pasm_cog.PasmEngine`.
        enabled: ``False``: never park (every instruction runs).
    """

    def __init__(self, engine, enabled: bool = True):
        self.engine = engine
        self.chip = engine.chip
        self.enabled = enabled
        self.first_offer = FIRST_OFFER if enabled else NEVER
        self._seen = [None]
        self._handlers = None
        #: statistics: loops parked, passes and instructions skipped, learning passes tried
        self.parked = self.passes_skipped = self.instructions_skipped = self.tries = 0

    # ------------------------------------------------------------------ learning
    def offer(self, c, R: list, pc: int, t: int, w: int) -> bool:
        """The run loop's offer: park cog ``c`` at ``pc`` (cycle ``t``, fetched ``w``) if its loop is idle.

        Returns ``True`` when it parked the cog; otherwise sets the next offer.
        """
        A = R[AUX]
        loop = self.learn(c, R, pc, t) if w == R[pc] else None
        if loop is None:
            A.idle_every = min(max(2 * A.idle_every, FIRST_OFFER), MAX_INTERVAL)
            A.idle_at = t + A.idle_every
            return False
        A.idle_every = FIRST_OFFER
        self.park(c, loop)
        return True

    def learn(self, c, R: list, head: int, t0: int):
        """Run one pass from ``head`` at ``t0`` on a copy of cog RAM: an :class:`IdleLoop`, or ``None``."""
        self.tries += 1
        if self._handlers is None:
            self._handlers = Handlers(TrackingBuilder(self.engine, self._seen).build)
        H = self._handlers
        p = _Pass()
        TR = p.ram = _TrackedRam(R)
        self._seen[0] = p
        get = list.__getitem__
        pc, t, w = head, t0, get(TR, head)
        n = 0
        try:
            while True:
                pc1 = (pc + 1) & 511
                w1 = get(TR, pc1)
                p.word = w
                hub = p.hub
                p.hub = False
                x = H[w](TR, pc, t)
                n += 1
                if p.hub:                   # a hub instruction: its access is at its end
                    p.last_access = x >> 9
                else:
                    p.hub = hub
                if x is None:
                    pc, w, t = pc1, w1, t + 4
                elif x >= 0:
                    t, pc = x >> 9, x & 511
                    w = w1 if pc == pc1 else get(TR, pc)
                else:
                    return None
                if pc == head:
                    break
                if n >= MAX_PASS_INSTRUCTIONS or t - t0 > MAX_PASS_CYCLES:
                    return None
        except (Impure, Unsupported, Leave, Fetched, Yield):
            return None
        finally:
            self._seen[0] = None
        return self._qualify(c, R, TR, p, head, t0, t, w, n)

    def _qualify(self, c, R, TR, p: _Pass, head: int, t0: int, t: int, w, n: int):
        period = t - t0
        if period <= 0 or (p.hub and period & 15) or w.__class__ is not int or w != R[head]:
            return None
        if len(p.ina) > 1:
            return None
        cnt_regs = {}
        get = list.__getitem__
        for i in TR.written:
            v = get(TR, i)
            if v.__class__ is Aff:
                if i in TR.read_first or not v.exact or v.c or i >= 512:
                    return None
                cnt_regs[i] = v
            elif v != R[i]:
                return None                 # the pass changed the cog's state: no repeat
        horizon = None
        for a, b, lo, hi in p.predicates:
            k = first_change(a, b * period, lo, hi)
            if horizon is None or k < horizon:
                horizon = k
        if horizon is not None and horizon < MIN_PASSES:
            return None
        ina = None
        if p.ina:
            r, value, mask = p.ina[0]
            ina = (r - t0, mask, value & mask)
        reads = tuple((2, i, v) for i, v in p.hub_reads.items())
        last = None if p.last_access is None else p.last_access - t0
        return IdleLoop(head, t0, period, n, horizon, cnt_regs, reads, ina, last)

    # ------------------------------------------------------------------ parking
    def park(self, c, loop: IdleLoop) -> None:
        """Take cog ``c`` out of the schedule until ``loop`` ends or what it reads changes."""
        chip = self.chip
        R = c.ram
        c.busy = loop
        c.park_t0 = loop.t0
        c.pc = loop.head
        c.ir = R[loop.head]
        c.t = c.key = loop.end()
        c.state = PARKED
        chip._cogs_changed = True
        chip._parked.append(c)
        watch = chip.watch
        for _, i, _ in loop.reads:
            watch[i] |= BUSY
        if loop.ina is not None:
            _, mask, value = loop.ina
            c.pin_wait = (mask, value, False, None)
            chip._pin_waiters.append(c)
        self.parked += 1

    def resume(self, c, t_limit: int) -> None:
        """Bring parked cog ``c`` past the passes whose accesses to shared state all come before
        ``t_limit`` (no further than its horizon), running again; nothing is executed."""
        loop = c.busy
        j = loop.horizon if loop.horizon is not None else 0
        if t_limit < NEVER:
            k = (t_limit - loop.t0) // loop.period      # passes that start by then ...
            if loop.last is not None:                   # ... and do their last shared access before it
                k = min(k, -(-(t_limit - loop.t0 - loop.last) // loop.period))
            k = max(k, 0)
            j = k if loop.horizon is None else min(k, loop.horizon)
        self._restore(c, loop, j)

    def _restore(self, c, loop: IdleLoop, j: int) -> None:
        chip = self.chip
        R = c.ram
        if j > 0:
            step = loop.period * (j - 1)
            for reg, v in loop.cnt_regs.items():
                R[reg] = (v.a + v.b * step) & M
        skipped = j * loop.per_pass
        c.instructions += skipped
        self.engine.instructions += skipped
        self.instructions_skipped += skipped
        self.passes_skipped += j
        c.pc = loop.head
        c.ir = R[loop.head]
        c.t = c.key = loop.t0 + j * loop.period
        c.busy = None
        c.pin_wait = None
        c.state = RUNNING
        chip._cogs_changed = True
        if c in chip._parked:
            chip._parked.remove(c)
        if c in chip._pin_waiters:
            chip._pin_waiters.remove(c)
        watch = chip.watch
        for _, i, _ in loop.reads:
            watch[i] &= ~BUSY
        for p in chip._parked:                  # longs other parked loops read stay watched
            for shift, i, _ in p.busy.reads:
                watch[((i << shift) & 0xFFFF) >> 2] |= BUSY
        A = R[AUX]
        A.idle_at = c.t + A.idle_every

    def unpark(self, c, t_limit: int) -> None:
        """The scheduler's unpark: resume cog ``c`` and run it up to ``t_limit`` (before a hub write it
        reads, the run's end, a COGSTOP).  It is not parked again on the way."""
        if c.busy is None or c.state != PARKED:
            self.forget(c)
            return
        self.resume(c, t_limit)
        if c.t >= t_limit:
            return
        engine = self.engine
        A = c.ram[AUX]
        saved_until, saved_idle = engine.until[0], A.idle_at
        A.idle_at = NEVER
        try:
            engine.run(c, t_limit)
        finally:
            engine.until[0] = saved_until
            A.idle_at = saved_idle

    def wake_time(self, c, t: int, writer, seen=None) -> int:
        """A pin it reads changed at ``t``: resume parked cog ``c`` at the first pass whose INA read sees
        the change, and return that pass's cycle.

        ``writer`` is the cog whose write it was (``None``: an input or a
        counter, seen from ``t`` on), ``seen`` the cycle of the writer's
        access (default ``t - 4``, a PASM instruction's): a read in that very
        cycle sees it when the writer's id is lower.
        """
        loop = c.busy
        if writer is not None:
            base = t - 4 if seen is None else seen
            visible = base if writer.id < c.id else base + 1
        else:
            visible = t
        offset = loop.ina[0]
        j = max(0, -(-(visible - loop.t0 - offset) // loop.period))
        if loop.horizon is not None and j > loop.horizon:
            j = loop.horizon
        self._restore(c, loop, j)
        return c.t

    def forget(self, c) -> None:
        """Drop cog ``c``'s park without running anything (the cog was restarted or stopped)."""
        chip = self.chip
        loop = c.busy
        c.busy = None
        if c in chip._parked:
            chip._parked.remove(c)
        if c in chip._pin_waiters:
            chip._pin_waiters.remove(c)
        if loop is not None and hasattr(loop, "head"):
            watch = chip.watch
            for _, i, _ in loop.reads:
                watch[i] &= ~BUSY
            for p in chip._parked:
                for shift, i, _ in p.busy.reads:
                    watch[((i << shift) & 0xFFFF) >> 2] |= BUSY
