"""Running ahead: a Spin cog runs on past the other cogs while everything it touches is its own.

The exact order (:mod:`.scheduler`) runs every bytecode at its *key*, the
moment of its hub access (:func:`spinemu.chip.timing.access_offsets`), in
the order of the keys (lowest cog id first on a tie): a cog runs only until
the next other cog's access.  Two bytecodes of different cogs that touch
nothing in common give the same result in either order, so most of that
ordering is only needed between *conflicting* accesses.  This module lets a
Spin cog run far past the other cogs (a *private stretch*) through bytecodes
that provably conflict with nothing any other cog does:

* **Private blocks.**  A compiled block (:mod:`.blocks`) whose bytecodes
  touch only its own code, the cog's stack slots and its local variables
  has a *private variant*.  It runs whatever the other cogs' next accesses,
  bounded only by the run's cycle limit and :data:`RUN_AHEAD` cycles past
  the scheduler's limit.  Hub variables, memory through computed addresses
  (other than local arrays inside the window), registers, pins, locks, cogs
  and the clock are never private: a cog stops before them and waits for
  its turn exactly as before.
* **Windows.**  What a cog's private blocks may touch is its *window*
  (``Cog.wlo`` .. ``Cog.whi``, contiguous hub longs): claimed as its stack
  grows, only from longs that are in no other window, hold no compiled
  code, are not read by a parked busy loop (``Chip.watch`` all clear) and
  were never found shared (:data:`SHARED` in ``Chip.own``).  A claim is
  always safe: whatever other cogs did to those longs so far happened before
  the claiming cog's present.
* **Checkpoints.**  When a cog's private variant first runs past the
  scheduler's limit it opens a stretch: its registers and the bytes of its
  window are saved (:meth:`RunAhead._open`), and the window's longs get the
  :data:`AHEAD` watch bit.  The stretch closes when the scheduler next picks
  the cog (every other cog's next access then comes after everything it did).
* **Intrusions.**  While some cog is ahead, the other cogs' bytecodes that
  are not private are checked: the interpreter runs a guarded copy of its
  handlers (every hub read and write, and the fetch, looks at the
  :data:`AHEAD` bit first; writes go through the watch check they always
  had).  Touching a long of a cog that is ahead (a stack another cog reads,
  a local passed by address) rolls that cog back to the intruder's key: its
  checkpoint is restored and its private bytecodes are run again, exactly,
  up to that key (:meth:`RunAhead._rollback`), so the intruder sees what the
  exact order shows it.  The long then leaves the window for good.
  Stopping or restarting a cog that is ahead rolls it back the same way; a
  PASM cog or a translated cog (whose hub accesses are not checked) first
  rolls every cog back, and no cog runs ahead while one of them runs.

Everything stays cycle-exact: each cog runs the same bytecodes at the same
cycles with the same values as in the exact order (``Chip(run_ahead=False)``
runs that order; tests/chip/test_run_ahead.py compares the two).

Hot path: :meth:`RunAhead._run_private` (a loop over private blocks); the
rest runs rarely (a stretch opened per scheduler turn, a claim when a stack
grows, a rollback per intrusion).
"""
from __future__ import annotations

from .cog import RUNNING
from .control import CogStopped, RebootRequested, Reschedule

__all__ = ["RunAhead", "_hole_in", "AHEAD", "RO", "SHARED", "NORO", "CLAIM", "REDO", "WANT_RO", "NOPRIV", "RUN_AHEAD"]

#: ``Chip.watch`` bit: the long is in the window of a cog that is running ahead
AHEAD = 16
#: ``Chip.watch`` bit: private blocks may read the long; a write first rolls back every cog ahead
RO = 32
CODE = 2                                    # blockops.CODE: compiled code lies in the long
_WRITE_CHECKED = AHEAD | CODE | RO
#: ``Chip.own`` value of a long that more than one cog touched: never claimed again
SHARED = 0xFF
#: ``Chip.own`` value of a long written while read-only: never read-only again
NORO = 0xFE
#: cycles a cog may run past the scheduler's limit in one turn (then it lets the scheduler look again)
RUN_AHEAD = 1 << 20
#: what a private block returns when its footprint is not inside the cog's window
CLAIM = -(1 << 63)
#: what the private block table's stub returns after compiling: call again
REDO = CLAIM + 1
#: what a private block returns when a hub long it reads is not read-only (yet)
WANT_RO = CLAIM + 2
#: longs claimed past the footprint when a window grows (fewer claims)
_SLACK_LONGS = 16
#: private phases skipped at an address where the last one did nothing
_SKIP_AFTER_FAIL = 32
#: ``Cog.cp`` while a rollback runs the cog again (not ahead, but its private blocks open nothing)
_REPLAY = [0] * 12 + [[]]


def _hole_in(holes, a0: int, a1: int, db: int, locs) -> bool:
    """Does a hole (a hub long index) lie in stack bytes ``[a0, a1)`` or at a local ``db + off``?"""
    for k in holes:
        a = k << 2
        if a0 <= a < a1 or a - db in locs:
            return True
    return False


def _interpreted(c, tf, limit):
    """The exact block table's entry where the first bytecode is left to the interpreter."""
    return -1


def _no_private(c, tf, limit):
    """The private block table's entry for an address whose code is not private: never runs."""
    return -1


_no_private.reach = 0
#: marker of an address without a private block (a function, so that the table holds only callables)
NOPRIV = _no_private


class RunAhead:
    """Private stretches, windows, checkpoints and rollbacks of a chip (mixin of :class:`~.chip.Chip`)."""

    def _init_run_ahead(self, enabled: bool) -> None:
        self.run_ahead = enabled
        #: per hub long: 0 free, ``cog id + 1`` in that cog's window, :data:`SHARED`
        self.own = bytearray(0x4000)
        #: cogs with an open private stretch (ahead of the scheduler); mutated, never rebound
        self._ahead: list = []
        self._private_ok = False
        self._handlers_wrapped = False  # (Chip.wrap_handler: then no cog runs ahead)
        self._guard_handlers = None
        self._g_cog = None              # the guarded bytecode running now, and its key
        self._g_key = 0
        self._reboot_key = 0            # the key of the bytecode that rebooted the chip
        self._rollbacks = 0
        self._stretches = 0
        #: the hub address a private block wants read-only when it leaves (set by the block)
        self._want = [-1]
        self.watch[0x2000:] = bytes([RO]) * (len(self.watch) - 0x2000)    # the ROM is never written
        if enabled and self.compile_blocks:
            stub = self._make_private_stub()
            self._pblocks = [stub] * 0x10000
            self._pstub = stub
        else:
            self._pblocks = None
            self._pstub = None

    # ------------------------------------------------------------------ windows
    def _claim(self, c, a0: int, a1: int, touched=None) -> bool:
        """Grow cog ``c``'s window to cover hub bytes ``[a0, a1)``.

        Every long there that the cog touches (``touched``: long indices; all
        of them if ``None``) must be claimable; one it does not touch that
        cannot be claimed (shared, watched) becomes a hole.  Returns False if
        a touched long is not claimable.
        """
        k0, k1 = a0 >> 2, (a1 + 3) >> 2
        if k0 < 0 or k1 > 0x2000 or k0 >= k1:
            return False
        lo, hi = c.wlo >> 2, c.whi >> 2
        if lo == hi:
            lo, hi = k0, k0
        new_lo, new_hi = min(lo, k0), max(hi, k1)
        own, watch = self.own, self.watch
        holes = []
        for a, b in ((new_lo, lo), (hi, new_hi)):       # the longs added below and above the window
            if a < b and (own.count(0, a, b) != b - a or watch.count(0, a, b) != b - a):
                for k in range(a, b):
                    if own[k] or watch[k]:
                        if (touched is None or k in touched) or 1 <= own[k] <= 8:
                            return False
                        holes.append(k)
        if new_hi > hi:                 # a little room above, as far as it is free
            top = min(new_hi + _SLACK_LONGS, 0x2000)
            while new_hi < top and not own[new_hi] and not watch[new_hi]:
                new_hi += 1
        me = c.id + 1
        cp = c.cp
        if cp is _REPLAY:
            cp = None
        mem = self.mem
        for a, b in ((new_lo, lo), (hi, new_hi)):
            if a < b:
                keep = [(k, own[k]) for k in holes if a <= k < b]
                own[a:b] = bytes([me]) * (b - a)
                for k, o in keep:
                    own[k] = o
                if cp is not None:          # ahead: saved as they are now, and watched
                    cp[12].append((a << 2, bytes(mem[a << 2: b << 2])))
                    wkeep = [(k, watch[k]) for k in holes if a <= k < b]
                    watch[a:b] = bytes([AHEAD]) * (b - a)
                    for k, w in wkeep:
                        watch[k] = w
        c.holes.extend(holes)
        c.wlo, c.whi = new_lo << 2, new_hi << 2
        return True

    def _claim_for(self, c, fn) -> bool:
        """Claim the footprint of block ``fn`` at cog ``c``'s present stack pointer and frame."""
        lo, hi, dlo, dhi = fn.foot
        a0, a1 = 1 << 30, -(1 << 30)
        touched = set()
        if lo < hi:
            a0, a1 = c.sp + lo, c.sp + hi
            touched.update(range(a0 >> 2, (a1 + 3) >> 2))
        if dlo < dhi:
            db = c.dbase
            a0, a1 = min(a0, db + dlo), max(a1, db + dhi)
            touched.update((db + off) >> 2 for off in fn.locs)
        return a0 < a1 and self._claim(c, a0, a1, touched)

    def _release(self, c, k: int) -> None:
        """Take hub long ``k`` out of cog ``c``'s window for good (another cog touches it): a hole in it."""
        if c.wlo >> 2 <= k < c.whi >> 2 and k not in c.holes:
            c.holes.append(k)
        self.own[k] = SHARED

    def _release_window(self, c) -> None:
        """Cog ``c`` stopped: its window is free again."""
        if c.cp is not None:
            self._close(c)
        lo, hi = c.wlo >> 2, c.whi >> 2
        if lo < hi:
            self.own[lo:hi] = bytes(hi - lo)
        for k in c.holes:
            self.own[k] = SHARED
        c.holes = []
        c.wlo = c.whi = 0

    def _mark(self, c, bits: int) -> None:
        """Set the watch bits of cog ``c``'s window to ``bits`` (AHEAD or 0), its holes left as they are."""
        lo, hi = c.wlo >> 2, c.whi >> 2
        if lo < hi:
            watch = self.watch
            keep = [(k, watch[k]) for k in c.holes]
            watch[lo:hi] = bytes([bits]) * (hi - lo)
            for k, w in keep:
                watch[k] = w

    def _make_ro(self, k: int) -> bool:
        """Let private blocks read hub long ``k`` from now on (a write to it will roll back every cog ahead)."""
        if not 0 <= k < 0x2000:
            return k >= 0x2000
        o = self.own[k]
        if 1 <= o <= 8 or o == NORO or self.watch[k] & AHEAD:
            return False
        self.watch[k] |= RO
        return True

    @staticmethod
    def _base(c, base) -> int:
        return c.vbase if base == "vb" else c.pbase if base == "pb" else c.dbase if base == "db" else 0

    def _want_ro(self, c, fn) -> bool:
        """Make read-only the hub longs private block ``fn`` reads at cog ``c``'s present bases."""
        return all(self._make_ro(((self._base(c, base) + off) & 0xFFFF) >> 2) for base, off in fn.ro)

    def _ro_written(self, b, k: int, key: int) -> None:
        """Cog ``b`` writes read-only hub long ``k`` at ``key``: the cogs ahead may have read it later."""
        self.watch[k] &= ~RO
        self.own[k] = NORO
        if self._ahead:
            self._sync_all(b, key)
            self._request_preemption()

    def _share(self, k: int) -> None:
        """Hub long ``k`` is read by a parked loop or holds code: never in a window again."""
        o = self.own[k]
        if o > 8:
            return
        if o:
            c = self.cogs[o - 1]
            if c.cp is not None:        # only the cog itself can be running now; it is at its present
                self._close(c)
            self._release(c, k)
        self.own[k] = SHARED

    # ------------------------------------------------------------------ private stretches
    def _open(self, c) -> None:
        """Cog ``c`` starts running past the scheduler's limit: save what a rollback restores."""
        lo, hi = c.wlo, c.whi
        c.cp = [c.t, c.pc, c.pc_hi, c.sp, c.dbase, c.vbase, c.pbase, c.pbase_hi, c.dcall, c.bytecodes,
                lo, bytes(self.mem[lo:hi]), []]
        if c.holes:
            self._mark(c, AHEAD)
        elif lo < hi:
            self.watch[lo >> 2: hi >> 2] = bytes([AHEAD]) * ((hi - lo) >> 2)
        self._ahead.append(c)
        self._stretches += 1

    def _close(self, c) -> None:
        """Nothing can reach into cog ``c``'s past any more: forget its checkpoint."""
        if c.holes:
            self._mark(c, 0)
        else:
            lo, hi = c.wlo >> 2, c.whi >> 2
            if lo < hi:
                self.watch[lo:hi] = bytes(hi - lo)
        c.cp = None
        self._ahead.remove(c)

    def _rollback(self, c, key: int, by_id: int) -> None:
        """Bring cog ``c`` (ahead) back to where the exact order has it when cog ``by_id``'s access at ``key`` runs."""
        cp = c.cp
        (c.t, c.pc, c.pc_hi, c.sp, c.dbase, c.vbase, c.pbase, c.pbase_hi, c.dcall, c.bytecodes) = cp[:10]
        mem, L = self.mem, self.mem_longs
        lo, data = cp[10], cp[11]
        keep = [(k, L[k]) for k in c.holes]     # (other cogs write the holes)
        mem[lo: lo + len(data)] = data
        for a, data in cp[12]:
            mem[a: a + len(data)] = data
        for k, v in keep:
            L[k] = v
        self._close(c)
        self._rollbacks += 1
        c.cp = _REPLAY                      # (its private blocks must not open a stretch while replayed)
        outer = self.rmw_limit              # (the intruder's loop goes on with its own limit)
        try:
            self._replay(c, key + 1 if c.id < by_id else key)
        finally:
            c.cp = None
            self.rmw_limit = outer

    def _replay(self, c, limit: int) -> None:
        """Run cog ``c``'s private bytecodes again, in the exact order's way, while they start before ``limit``.

        Only private bytecodes can come (the stretch being replayed held
        nothing else, and the next shared access of ``c`` comes at or after
        ``limit``); they touch only ``c``'s window and code.
        """
        P = self._pblocks
        mem, H = self.mem, self._handlers
        self.rmw_limit = limit
        ph = c.hub_phase
        t = c.t
        pc = c.pc
        claimed = -1
        while 0 <= pc < 0xFFF0:
            tf = t + 12
            tf += (ph - tf) & 15
            f = P[pc]
            if f is not NOPRIV:
                r = f(c, tf, limit)
                if r >= 0:
                    t = r
                    pc = c.pc
                    continue
                if r == REDO:
                    continue
                if r == CLAIM or r == WANT_RO:
                    if claimed != pc and (self._claim_for(c, f) if r == CLAIM else self._want_ro(c, f)):
                        claimed = pc
                        continue
                elif r != -1:                   # stopped before a bytecode it does not compile
                    t = -2 - r
                    pc = c.pc
                    tf = t + 12
                    tf += (ph - tf) & 15
                self._want[0] = -1
            op = mem[pc]
            if tf + self.access_offset(pc) >= limit:
                break
            c.pc = pc + 1
            t = tf + H[op](c, op, t)
            c.bytecodes += 1
            pc = c.pc
        c.t = t

    def _intrude(self, b, hub_addr: int, key: int) -> None:
        """Cog ``b``'s bytecode with key ``key`` is about to touch ``hub_addr``, in the window of a cog ahead."""
        k = (hub_addr & 0xFFFF) >> 2
        o = self.own[k]
        if not 1 <= o <= 8:
            return
        a = self.cogs[o - 1]
        if a is b:
            return
        if a.cp is not None:
            self._rollback(a, key, b.id)
        self._release(a, k)
        # the owner's bytecodes touching that long are not private any more: the next of them may come
        # before the end of b's turn, so the scheduler looks again after this bytecode
        self._request_preemption()

    def _sync_all(self, b, key: int) -> None:
        """Roll every cog that is ahead back to cog ``b``'s access at ``key`` (before a PASM cog starts)."""
        for a in list(self._ahead):
            if a is not b:
                self._rollback(a, key, b.id)

    def _stop_ahead(self, c) -> None:
        """Cog ``c`` is being stopped or restarted: undo what it ran past the bytecode doing it, free its window."""
        if c.cp is not None:
            by = self._g_cog
            self._rollback(c, self._g_key if by is not None else self.now, by.id if by is not None else 8)
        self._release_window(c)

    # ------------------------------------------------------------------ the private loop (hot)
    def _run_private(self, c, limit: int, stop_pc: int) -> bool:
        """Run cog ``c``'s private blocks from where it is, past ``limit`` if need be. (Hot loop.)

        Opens a private stretch before the first block that reaches
        ``limit``.  Stops at the first address without a runnable private
        block, at ``stop_pc``, at the run's cycle limit or :data:`RUN_AHEAD`
        cycles past ``limit``.  Returns whether the cog moved.
        """
        P = self._pblocks
        bound = (limit if limit > c.t else c.t) + RUN_AHEAD
        if bound > self.run_limit:
            bound = self.run_limit
        ph = c.hub_phase
        t = c.t
        pc = c.pc
        moved = False
        claimed = -1
        want = self._want
        if pc == c.pfail:                       # it did nothing here last time: not every time again
            if c.pfail_n:
                c.pfail_n -= 1
                return False
            c.pfail = -1
        opened = c.cp is None                   # (a private block opens the stretch when it starts)
        while 0 <= pc < 0x10000:
            tf = t + 12
            tf += (ph - tf) & 15
            f = P[pc]
            if f is NOPRIV:
                break
            c.t = t
            r = f(c, tf, bound)
            if r >= 0:
                t = r
                pc = c.pc
                moved = True
                if pc == stop_pc:
                    break
                continue
            if r == REDO:
                continue
            if r == CLAIM or r == WANT_RO:
                if claimed != pc and (self._claim_for(c, f) if r == CLAIM else self._want_ro(c, f)):
                    claimed = pc
                    continue
                if r == WANT_RO and any(self.own[((self._base(c, base) + off) & 0xFFFF) >> 2] == NORO
                                        for base, off in f.ro):
                    P[pc] = NOPRIV              # it reads a long that is written: never private
                break
            if r != -1:                         # it stopped before a bytecode that is not private
                t = -2 - r
                pc = c.pc
                moved = True
                if want[0] >= 0:                # ... because a long it reads was not read-only yet
                    k = (want[0] & 0xFFFF) >> 2
                    want[0] = -1
                    if self._make_ro(k):
                        continue
            break
        want[0] = -1
        c.t = t
        if not moved:
            if opened and c.cp is not None:
                self._close(c)
            c.pfail, c.pfail_n = c.pc, _SKIP_AFTER_FAIL
        return moved

    def _make_private_stub(self):
        """The private block table's entry for an address not compiled yet: compile when hot."""
        from .blocks import HOT
        chip = self

        def pstub(c, tf, limit):
            pc = c.pc
            heat = chip._heat[pc]
            if heat < HOT:
                chip._heat[pc] = heat + 1
                return -1
            if chip._compiler is None:
                from .blocks import BlockCompiler
                chip._compiler = BlockCompiler(chip, chip._blocks, chip._block_stub)
            exact = chip._blocks[pc]
            if exact == chip._block_stub:       # the exact block tells whether a private one is worth it
                exact = chip._compiler.compile(pc)
                chip._blocks[pc] = exact if exact is not None else _interpreted
            if not getattr(exact, "privatable", False):
                chip._pblocks[pc] = NOPRIV
                return -1
            fn = chip._compiler.compile_private(pc) if heat < HOT + 8 else None
            chip._heat[pc] = min(heat + 1, 255)
            chip._pblocks[pc] = fn if fn is not None else NOPRIV
            return REDO if fn is not None else -1

        pstub.reach = -(1 << 62)
        return pstub

    # ------------------------------------------------------------------ guarded interpreter
    def _run_guarded(self, c, limit: int, stop_pc: int = -1) -> None:
        """:meth:`~.scheduler.Scheduler._run_spin` with the guarded handlers (while a cog is ahead)."""
        if self._preempt:                   # as _run_spin: a pending preemption runs nothing
            self._end_preemption()
            return
        mem, watch = self.mem, self.watch
        self.rmw_limit = limit
        H = self._guarded()
        ph = c.hub_phase
        t = c.t
        n = 0
        tf = t
        pc = c.pc
        try:
            while True:
                pc = c.pc
                op = mem[pc]
                tf = t + 12
                tf += (ph - tf) & 15
                key = tf + self.access_offset(pc)
                if key >= limit:
                    break
                if watch[(pc & 0xFFFF) >> 2] & AHEAD:   # code in the window of a cog ahead
                    self._intrude(c, pc, tf)
                    break
                self._g_cog, self._g_key = c, key
                c.pc = pc + 1
                t = tf + H[op](c, op, t)
                n += 1
                if self._preempt or c.pc == stop_pc:
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
            self._reboot_key = key
            raise
        except IndexError:
            raise self.fault(c, c.pc - 1, "stack or address out of hub range") from None
        finally:
            self._g_cog = None
        if self._preempt:
            self._end_preemption()
        c.bytecodes += n
        if c.state == RUNNING:
            c.t = t

    def _guarded(self):
        """The interpreter's handlers with every hub access checked against the windows of cogs ahead."""
        if self._guard_handlers is None:
            from .spin import build_handlers
            self._guard_handlers = build_handlers(_GuardedChip(self), self.timing)
        return self._guard_handlers

    def _guard_range(self, a0: int, a1: int, write: bool = False) -> None:
        """The guarded bytecode touches hub bytes ``[a0, a1)``: roll back the cogs ahead it reaches."""
        watch = self.watch
        for k in range((a0 & 0xFFFF) >> 2, min(((a1 - 1) & 0xFFFF) >> 2, 0x3FFF) + 1):
            w = watch[k]
            if w & AHEAD:
                self._intrude(self._g_cog, k << 2, self._g_key)
            elif write and w & (CODE | RO) and k < 0x2000:
                self._guard_write(k << 2)

    def _guard_write(self, hub_addr: int) -> None:
        """The guarded bytecode writes ``hub_addr`` (a stack push, say), which is watched for running ahead."""
        k = (hub_addr & 0xFFFF) >> 2
        if k >= 0x2000:
            return                              # the ROM: the write is ignored
        w = self.watch[k]
        if w & AHEAD:
            self._intrude(self._g_cog, hub_addr, self._g_key)
        elif w & RO:
            self._ro_written(self._g_cog, k, self._g_key)
        elif w & CODE:                          # compiled code: the cogs ahead may have run it
            self._code_write(self._g_cog, self._g_key)

    def _code_write(self, b, key: int) -> None:
        """Cog ``b`` writes compiled code at ``key``: a cog ahead may have run it later (roll them all back)."""
        if self._ahead:
            self._sync_all(b, key)
            self._request_preemption()


class _GuardedView:
    """A memory view that checks each access against the windows of cogs ahead (guarded interpreter)."""

    __slots__ = ("view", "shift", "chip", "watch")

    def __init__(self, view, shift, chip):
        self.view, self.shift, self.chip, self.watch = view, shift, chip, chip.watch

    def __getitem__(self, i):
        if isinstance(i, slice):
            start, stop, _ = i.indices(len(self.view))
            if start < stop:
                self.chip._guard_range(start << self.shift, stop << self.shift)
        elif self.watch[((i << self.shift) & 0xFFFF) >> 2] & AHEAD:
            chip = self.chip
            chip._intrude(chip._g_cog, i << self.shift, chip._g_key)
        return self.view[i]

    def __setitem__(self, i, v):
        if isinstance(i, slice):
            start, stop, _ = i.indices(len(self.view))
            if start < stop:
                self.chip._guard_range(start << self.shift, stop << self.shift, True)
        elif self.watch[((i << self.shift) & 0xFFFF) >> 2] & _WRITE_CHECKED:
            self.chip._guard_write(i << self.shift)
        self.view[i] = v

    def __len__(self):
        return len(self.view)


class _GuardedChip:
    """The chip as the guarded handlers see it: memory views check, RUN and COGINIT check what they touch."""

    def __init__(self, chip):
        object.__setattr__(self, "_chip", chip)
        object.__setattr__(self, "mem", _GuardedView(chip.mem, 0, chip))
        object.__setattr__(self, "mem_words", _GuardedView(chip.mem_words, 1, chip))
        object.__setattr__(self, "mem_longs", _GuardedView(chip.mem_longs, 2, chip))

    def __getattr__(self, name):
        return getattr(self._chip, name)

    def __setattr__(self, name, value):
        setattr(self._chip, name, value)

    def run_helper(self, c, tf):
        from .runhelper import run_spin_method
        return run_spin_method(self, c, tf)

    def coginit(self, c, cog_id, code, par, tf):
        chip = self._chip
        from .rom import INTERPRETER_ENTRY
        if (code & 0xFFFC) == INTERPRETER_ENTRY & 0xFFFC:
            p = par & 0xFFFC
            chip._guard_range(p, p + 12)        # the new interpreter reads pbase .. dcurr there
        else:
            chip._sync_all(c, chip._g_key)      # a PASM cog's hub accesses are not checked
        return chip.coginit(c, cog_id, code, par, tf)
