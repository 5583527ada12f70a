"""Time on the chip: which cog runs next, the bytecode loops, and fast-forward parking.

:class:`Scheduler` is a mixin of :class:`spinemu.chip.chip.Chip`.  The cog
whose next bytecode touches shared state first runs (``_key``: the fetch plus
:func:`spinemu.chip.timing.access_offsets`), until another cog's next access
comes earlier.  A cog in WAITCNT simply has its next bytecode far in the
future; a stopped or pin-waiting cog is skipped; a parked busy loop
(:mod:`spinemu.chip.fastforward`) costs nothing until a write it would read.

Hot paths: :meth:`Scheduler._schedule` and :meth:`Scheduler._run_spin` (the
bytecode loop: one list-indexed handler per bytecode, no flag checks; a rare
event leaves it by exception, see :mod:`spinemu.chip.control`).  The
instrumented loops (:meth:`Scheduler._run_spin_traced` for the recorder,
:meth:`Scheduler._run_spin_probed` for a debugger or profiler) are only
chosen when one is attached.
"""
from __future__ import annotations

from .blocks import BUSY, CODE, PROGRAM, WATCHPOINT, BlockCompiler
from .checks import write_size
from .cog import PARKED, RUNNING, Cog
from .control import CogStopped, Halted, Preempted, RebootRequested, Reschedule
from .ahead import _WRITE_CHECKED, AHEAD, CLAIM, NOPRIV, RO, SHARED, _interpreted
from .fastforward import INTERRUPTED, LEARN_AFTER, LEARN_HORIZON, learn_busy_loop, tracking_handlers

__all__ = ["Scheduler", "NEVER"]

NEVER = 1 << 62
_NEVER = NEVER
_OBSERVED = PROGRAM | WATCHPOINT


def _preempt_handler(c, op, t):
    raise Preempted


#: compilations of one address (its code keeps changing) after which it stays interpreted
_RECOMPILE_LIMIT = 8
#: bytecodes between learning attempts of a cog whose attempts keep failing, at most
_LEARN_BACKOFF_MAX = 1 << 22


class Scheduler:
    """Scheduling and the run loops of a :class:`~spinemu.chip.chip.Chip` (mixin)."""

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
        while self._pend:                       # an update's write-back (no other cog runs in between)
            self._apply_pending()
        return c.t - t

    def _schedule(self, limit: int, progress) -> str:
        """Advance the cog furthest behind until every cog stopped or ``limit``. (Hot loop.)

        A cog whose ``engine`` is an object rather than a name (the PASM
        engine of :mod:`.pasm_cog`, the Python engine of
        :mod:`spinemu.translate`) is run by ``engine.run(cog, until)``, which
        must advance ``cog.t`` (or stop the cog) as the bytecode loop does
        and may not perform a shared access at or after ``until``; its next
        access comes from :meth:`_key`.
        """
        cogs = self.cogs
        mem, acc, wide = self.mem, self.access_at, self.access_wide
        next_report = 0
        self.run_limit = limit
        # a Spin cog's turn ends at the next progress report (a lone cog's, or one whose partner
        # sleeps, might otherwise last to the limit, past every report)
        cap = limit if progress is None else self.now + self.progress_every
        traced = self.recorder is not None
        probed = self.probe is not None
        ff = self.fast_forward and not traced and not probed
        run = self._run_spin_traced if traced else self._run_spin_probed if probed else self._run_plain
        running: list = []
        generic = False
        listening = bool(self.pin_listeners)
        while True:
            if self._cogs_changed:
                self._cogs_changed = False
                # a parked PASM cog (pasm_idle.py) stays listed: its key is the end of its loop's horizon
                running = [k for k in cogs if k.state == RUNNING
                           or (k.state == PARKED and k.engine.__class__ is not str)]
                generic = any(k.engine.__class__ is not str for k in running)
                # a cog may run ahead (ahead.py) unless a cog whose hub accesses are not checked runs
                self._private_ok = (self._pblocks is not None and not traced and not probed and not self._handlers_wrapped
                                    and not any(k.engine.__class__ is not str for k in cogs if k.running))
            # the two running cogs whose next bytecodes reach the hub first (lowest id on ties)
            c = c2 = None
            ck = ck2 = 0
            for k in running:
                if generic and k.engine.__class__ is not str:
                    key = k.engine.key(k)
                else:
                    pc = k.pc
                    op = mem[pc]
                    key = k.t + 12
                    key += ((k.hub_phase - key) & 15) + acc[op] + (wide[op] & (mem[(pc + 1) & 0xFFFF] >> 3))
                if c is None or key < ck:
                    c2, ck2 = c, ck
                    c, ck = k, key
                elif c2 is None or key < ck2:
                    c2, ck2 = k, key
            if ck >= _NEVER:
                c = None                        # only parked loops with no end of their own
            ext = self._next_external(limit) if self._pin_waiters else None
            if listening:
                now = ck if c is not None else ext
                if now is not None and now >= self._listen_at:
                    self._listen(running, ext, now,
                                 ck + 1 if c is not None else max(self.now, self._ext_seen) + 1)
                    if self._pin_waiters:       # a listener may have added input changes
                        ext = self._next_external(limit)
            # an update's write-back that another cog's access came between (defer_write)
            # (on the same cycle as another cog's access, the lower cog id first, as between two cogs)
            pa = self._pend_at
            if pa < limit and (c is None or pa < ck or pa == ck and self._pend_id < c.id) \
                    and (ext is None or pa <= ext):
                self._apply_pending()
                continue
            # an input edge or a counter edge first when it comes before the next cog's access
            # (a cog runs nothing with ``until`` at or before its key: the edge must go first)
            if ext is not None and (c is None or ext <= ck):
                self.now = self._ext_seen = ext
                self._wake_pin_waiters(ext)
                continue
            if c is None:
                if self._halt_reason is not None:   # a halt was asked for: stop before time is stepped
                    self._end_preemption()
                if self._parked and not self._pin_waiters:
                    if limit >= _NEVER:
                        return "stalled"
                    for p in list(self._parked):
                        self._unpark(p, limit)
                    continue
                if self._pin_waiters:           # nothing can change the pins they wait on
                    if listening and self._idle_listen(limit):
                        continue                # ... unless a pin listener sends something
                    if limit < _NEVER:
                        self.now = limit
                        for p in list(self._parked):
                            self._unpark(p, limit)
                        return "cycle limit"
                    # some cog spins in a parked loop (a PASM loop polling the pins too): stalled
                    return "stalled" if self._parked else "deadlock"
                return "all cogs stopped"
            t = c.t
            if ck >= limit:
                self.now = limit
                for p in list(self._parked):
                    self._unpark(p, limit)
                return "cycle limit"
            # run c until just before the next other cog's access (it goes first on a tie if its id is lower)
            until = limit
            if c2 is not None:
                until = ck2 + 1 if c.id < c2.id else ck2
                if until > limit:
                    until = limit
            if cap < until and c.engine.__class__ is str:
                until = cap if cap > ck else ck + 1     # (its time has come: one bytecode, then the report)
            if ext is not None and ext < until:
                until = ext
            if pa < until:
                until = pa + 1 if c.id < self._pend_id else pa
            if listening and until > self._listen_at:
                until = self._listen_at         # back here in time to tell the pin listeners
            self.now = t
            if c.cp is not None:        # every other cog's next access comes after what it ran ahead
                self._close(c)
            try:
                if generic and c.engine.__class__ is not str:
                    c.engine.run(c, until)
                elif ff and (c.busy is not None or (c.bytecodes - c.learn_mark > c.learn_after
                                                    and until - t > LEARN_HORIZON)):
                    self._run_with_fast_forward(c, until)
                else:
                    run(c, until)
                if self._pend and self._preempt:    # the loop ended at a deferred write-back already
                    self._end_preemption()
            except RebootRequested:
                self.now = c.t
                if self._ahead:         # the cogs ahead ran past the reboot: back to its moment
                    self._sync_all(c, self._reboot_key)
                self._pend.clear()      # write-backs after the reboot's moment do not come
                self._pend_at = _NEVER
                return "reboot"
            if progress is not None and t >= next_report:
                progress(t)
                next_report = t + self.progress_every
                cap = next_report

    def _key(self, c: Cog) -> int:
        """When cog ``c``'s next bytecode touches shared state (see timing.access_offsets).

        Engine hook: a cog whose ``engine`` is an object (not ``"spin"``)
        is run by ``engine.run(cog, limit)`` and reports this moment itself,
        ``engine.key(cog)``.  spinemu.translate's Python engine uses this.
        """
        if c.engine.__class__ is not str:
            return c.engine.key(c)
        tf = c.t + 12
        return tf + ((c.hub_phase - tf) & 15) + self.access_offset(c.pc)

    def access_offset(self, pc: int) -> int:
        """Cycles from the fetch of the bytecode at ``pc`` to its access of shared state (timing.access_offsets)."""
        mem = self.mem
        op = mem[pc]
        return self.access_at[op] + (self.access_wide[op] & (mem[(pc + 1) & 0xFFFF] >> 3))

    def _next_external(self, limit: int):
        """The next input change or counter edge after the last one handled, if before ``limit``."""
        t = self._ext_seen
        nxt = self.inputs.next_change(t)
        if self.counters_on:
            watched = 0                 # a counter edge on a pin no waiter watches wakes nobody
            for c in self._pin_waiters:
                watched |= c.pin_wait[0]
            ce = self.counters.next_edge(t, watched)
            if ce is not None and (nxt is None or ce < nxt):
                nxt = ce
        return nxt if nxt is not None and nxt < limit else None

    def _run_with_fast_forward(self, c: Cog, until: int) -> None:
        """Run ``c`` until ``until``, skipping iterations of a learned busy loop (see fastforward.py).

        A cog keeps its loop while it runs elsewhere; at the loop's head the
        loop is parked if it is still valid.  If only the values it reads
        changed (the usual reason it was woken), a loop learned before with
        the current values is taken from the loop memory, or one is learned
        at once from the head.
        """
        busy = c.busy
        if busy is None:
            if c.bytecodes - c.learn_mark > c.learn_after and until - c.t > LEARN_HORIZON:
                self._learn(c, until)
                busy = c.busy
                if busy is None or c.state != RUNNING or c.pc != busy.head:
                    self._run_plain(c, until)
                    return
            else:
                self._run_plain(c, until)
                return
        if c.pc == busy.head:
            if not busy.still_valid(self, c):
                loop = self._loop_memory.find(self, c)
                if loop is None:
                    if until - c.t <= LEARN_HORIZON:
                        self._run_plain(c, until)       # no time to learn now: at the next visit
                        return
                    self._learn(c, until)
                    loop = c.busy
                    if loop is busy or loop is None or c.state != RUNNING or c.pc != loop.head:
                        if c.state == RUNNING:
                            self._run_plain(c, until)
                        return
                c.busy = loop
            self._park(c)
            return
        self._run_plain(c, until, busy.head)
        if c.pc != busy.head and c.bytecodes - c.learn_mark > LEARN_AFTER:
            c.busy = None               # the program left that loop: look for the next one
            c.learn_after = 0
            c.learn_mark = c.bytecodes

    def _park(self, c: Cog) -> None:
        """Take cog ``c`` out of the schedule: it repeats its learned loop until something it reads changes."""
        c.state = PARKED
        self._cogs_changed = True
        c.park_t0 = c.t
        c.learn_mark = c.bytecodes
        watch = self.watch
        for shift, i, _ in c.busy.reads:
            watch[((i << shift) & 0xFFFF) >> 2] |= BUSY
        self._parked.append(c)

    def _unpark(self, c: Cog, t_limit: int) -> None:
        """Bring parked cog ``c`` to where it would be, running its loop, when bytecodes starting before ``t_limit`` are done."""
        if c.engine.__class__ is not str:       # a parked PASM cog: its engine knows its loop
            c.engine.idle.unpark(c, t_limit)
            return
        busy = c.busy
        k = max(0, (t_limit - 1 - c.park_t0) // busy.period)
        c.t = c.park_t0 + k * busy.period
        c.bytecodes += k * busy.bytecodes
        busy.skipped += k * busy.bytecodes
        self._ff_skipped += k * busy.bytecodes
        c.state = RUNNING
        self._cogs_changed = True
        self._parked.remove(c)
        watch = self.watch
        for shift, i, _ in busy.reads:
            watch[((i << shift) & 0xFFFF) >> 2] &= ~BUSY
        for p in self._parked:
            for shift, i, _ in p.busy.reads:
                watch[((i << shift) & 0xFFFF) >> 2] |= BUSY
        if c.t < t_limit:
            pending = self._preempt             # (meant for the cog whose write woke this one)
            if pending:
                self._end_preemption()
            outer = self.rmw_limit              # (the writer's loop goes on with its own limit)
            self._run_spin(c, t_limit)
            self.rmw_limit = outer
            if pending:
                self._request_preemption()

    def watch_hit(self, writer: Cog, hub_addr: int, t: int, op: int, pc: int = -1) -> None:
        """``writer``'s bytecode ``op`` (at ``pc`` if known), started at ``t``, is about to write a watched hub long.

        ``write_hooks`` (runtime checks, debugger watchpoints) are told
        first, as ``f(writer, hub_addr, size, t)`` (``size``: the bytes the
        bytecode writes), when the long carries one of their bits.  A parked
        cog that reads the long is brought up to ``t`` (it reads the old
        value, as it would have), and the writer's run loop
        is preempted after this bytecode, so that the scheduler interleaves
        the two cogs again.
        """
        if self.watch[hub_addr >> 2] & _OBSERVED:
            size = write_size(op)
            for f in self.write_hooks:
                f(writer, hub_addr, size, t)
        tf = t + 12
        at = self.access_offset(pc) if pc >= 0 else self.access_at[op]
        self.watch_hit_at(writer, hub_addr, tf + ((writer.hub_phase - tf) & 15) + at)

    def pasm_write_hit(self, writer: Cog, hub_addr: int, size: int, t: int, key: int, pc: int) -> None:
        """A PASM cog's WRBYTE/WRWORD/WRLONG (``size`` bytes) at cog address ``pc``, started at ``t``,
        is about to write a watched hub long at its hub window ``key``: :meth:`watch_hit` for PASM.

        The run loop keeps the cog's address in a local: ``writer.pc`` is set
        to the writing instruction's for the hooks (the loop sets it again
        when it ends its slice).
        """
        if self.watch[hub_addr >> 2] & _OBSERVED:
            writer.pc = pc
            for f in self.write_hooks:
                f(writer, hub_addr, size, t)
        self.watch_hit_at(writer, hub_addr, key)

    def watch_hit_at(self, writer: Cog, hub_addr: int, key: int) -> None:
        """:meth:`watch_hit` for a write at cycle ``key`` (a PASM cog's hub window)."""
        k = (hub_addr & 0xFFFF) >> 2
        w = self.watch[k]
        if w & RO:
            self._ro_written(writer, k, key)    # the cogs ahead may have read it after the write
        elif w & CODE and self._ahead:
            self._code_write(writer, key)       # ... or run that code
        woke = False
        for p in list(self._parked):
            if any(((i << shift) & 0xFFFF) >> 2 == hub_addr >> 2 for shift, i, _ in p.busy.reads):
                self._unpark(p, key + 1 if p.id < writer.id else key)
                woke = True
        if woke:
            self._request_preemption()

    def watch_hit_w(self, writer: Cog, hub_addr: int, size: int, t: int, key: int) -> None:
        """:meth:`watch_hit` for an update's write-back at cycle ``key`` (``size`` bytes)."""
        if self.watch[hub_addr >> 2] & _OBSERVED:
            for f in self.write_hooks:
                f(writer, hub_addr, size, t)
        self.watch_hit_at(writer, hub_addr, key)

    def defer_write(self, writer: Cog, size: int, hub_addr: int, value: int, t: int, key: int,
                    preempt: bool = True) -> None:
        """An update of ``writer`` (started at ``t``) read its variable before the run loop's
        limit and writes it back at ``key``, at or after that limit: another cog's access comes
        in between, so the write waits for its moment (:meth:`_apply_pending`).

        On the chip the update reads the variable in one hub window and writes it
        back in a later one; a write by another cog in between is lost, and a read
        in between sees the old value.  ``size``: 0 byte, 1 word, 2 long.  With
        ``preempt`` the writer's bytecode loop ends after this bytecode (its next
        access comes later anyway); the Python engine, whose statements store this
        way too (``spinemu.translate.runtime.defer_store``), hands over at its next
        access itself.
        """
        self._pend.append((key, writer.id, writer, size, hub_addr, value, t))
        self._pend.sort()
        self._pend_at, self._pend_id = self._pend[0][0], self._pend[0][1]
        if preempt:
            self._request_preemption()

    def _apply_pending(self) -> None:
        """Make the earliest deferred write-back (the scheduler's order: before any later access)."""
        key, _, c, size, a, v, t = self._pend.pop(0)        # (the lower cog id on a tie)
        self._pend_at, self._pend_id = (self._pend[0][0], self._pend[0][1]) if self._pend else (_NEVER, 8)
        k = a >> 2
        w = self.watch[k]
        if w:
            if self._ahead and w & _WRITE_CHECKED:          # the window of a cog ahead, or read-only
                self._g_cog, self._g_key = c, key
                try:
                    self._guard_write(a)
                finally:
                    self._g_cog = None
            self.watch_hit_w(c, a, 1 << size, t, key)
        if size == 2:
            self.mem_longs[k] = v
        elif size == 1:
            self.mem_words[a >> 1] = v
        else:
            self.mem[a] = v
        if self._preempt:                       # (meant for a run loop: none is running)
            self._end_preemption()

    def _drop_pending(self, c: Cog) -> None:
        """Cog ``c`` stops: its updates not written back yet never are."""
        self._pend = [p for p in self._pend if p[2] is not c]
        self._pend_at, self._pend_id = (self._pend[0][0], self._pend[0][1]) if self._pend else (_NEVER, 8)

    def _request_preemption(self) -> None:
        """End the running cog's loop after its current bytecode (see control.Preempted)."""
        self._preempt = True
        self.handlers[:] = [_preempt_handler] * 256

    def _end_preemption(self) -> None:
        self.handlers[:] = self._handlers
        self._preempt = False
        if self._halt_reason is not None:       # request_halt: stop here, at the start of a slice
            reason, self._halt_reason = self._halt_reason, None
            raise Halted(reason)

    def request_halt(self, reason: str) -> None:
        """Stop the run before the next bytecode that starts a scheduler slice (``advance`` returns ``reason``).

        Call it from a handler whose bytecode ends its cog's slice (one that
        raises :class:`~spinemu.chip.control.Reschedule`, such as a wait): the
        run then stops at a point where every cog's state is complete.  It
        rides on the preemption mechanism, so the fast loops check nothing new.
        """
        self._halt_reason = reason
        self._request_preemption()

    def _learn(self, c: Cog, until: int) -> None:
        if self._tracking is None or self._tracking_wraps != len(self._wraps):
            self._tracking = tracking_handlers(self, self.timing)
            self._tracking_wraps = len(self._wraps)
        handlers, log = self._tracking
        try:
            loop = learn_busy_loop(self, c, handlers, log, until)
        finally:
            log.clear()
            self._g_cog = None
        c.learn_mark = c.bytecodes
        if loop is INTERRUPTED:
            return                      # not a failure: try again at the next chance
        if loop is None:
            # wait until the failed attempt's cost is small against normal running, and
            # twice as long after each failure in a row (compiled code runs many times faster)
            c.busy = None
            c.learn_after = min(max(LEARN_AFTER, 16 * self.learn_tracked, 2 * c.learn_after), _LEARN_BACKOFF_MAX)
        else:
            c.busy = loop
            self._ff_loops += 1
            self._loop_memory.add(c, loop)
            own, me = self.own, c.id + 1
            frame = range((c.dbase - 8) >> 2, (c.sp + 3) >> 2)
            for k in loop.longs:            # a parked loop reads them all the time: in no other cog's window
                o = own[k]
                if o != SHARED and o != me and (o or k not in frame):
                    self._share(k)
            if self._compiler is not None:
                self._compiler.add_boundary(loop.head)

    def _run_spin(self, c: Cog, limit: int, stop_pc: int = -1) -> None:
        """Run cog ``c``'s bytecodes while it starts them before ``limit``. (Hot loop.)

        With ``stop_pc``, also stop when the cog comes back to that address
        (a loop head, for the fast-forward's learner).
        """
        if self._ahead:                         # another cog is ahead: every access is checked (ahead.py)
            return self._run_guarded(c, limit, stop_pc)
        self.rmw_limit = limit
        mem = self.mem
        H = self.handlers
        ACC = self.access_at
        WIDE = self.access_wide
        near = limit - 16                       # (only there can a two-byte offset's 16 cycles matter)
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
                if tf + ACC[op] >= near and tf + ACC[op] + (WIDE[op] & (mem[(pc + 1) & 0xFFFF] >> 3)) >= limit:
                    break                       # another cog touches the hub first
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
            self._reboot_key = tf + self.access_offset(pc)
            raise
        except IndexError:
            raise self.fault(c, c.pc - 1, "stack or address out of hub range") from None
        c.bytecodes += n
        if c.state == RUNNING:
            c.t = t

    # ------------------------------------------------------------------ compiled blocks
    def _run_blocks(self, c: Cog, limit: int, stop_pc: int = -1) -> None:
        """:meth:`_run_spin` a compiled block at a time (blocks.py); stops at ``stop_pc`` too. (Hot loop.)

        Blocks check themselves that they end before ``limit``; where one
        cannot run, the bytecode is interpreted exactly as :meth:`_run_spin`
        does it, with the same exits.  Where the next block cannot end before
        ``limit`` but has a private variant, the cog runs on past ``limit``
        through private blocks (:meth:`~.ahead.RunAhead._run_private`).  While
        another cog is ahead, bytecodes are interpreted by the guarded
        handlers (ahead.py).
        """
        if self._preempt:                       # as _run_spin: a pending preemption ends the slice at once
            self._end_preemption()
            return
        pc = c.pc
        if not 0 <= pc < 0x10000:
            return self._run_spin(c, limit, stop_pc)
        self.rmw_limit = limit
        B = self._blocks
        P = self._pblocks if self._private_ok else None
        AH = self._ahead
        mem = self.mem
        H = self.handlers
        ACC = self.access_at
        Ph = c.hub_phase
        t = c.t
        tf = t
        claimed = -1
        try:
            while True:
                tf = t + 12
                tf += (Ph - tf) & 15
                r = B[pc](c, tf, limit)
                if r >= 0:
                    t = r
                    pc = c.pc
                    if pc == stop_pc:
                        break
                    continue
                if r == CLAIM:                  # a cog is ahead: the block's stack must be this cog's
                    if claimed != pc and self._claim_for(c, B[pc]):
                        claimed = pc
                        continue
                elif r != -1:
                    t = -2 - r
                    pc = c.pc
                    tf = t + 12
                    tf += (Ph - tf) & 15
                elif P is not None and P[pc] is not NOPRIV:
                    c.t = t
                    if self._run_private(c, limit, stop_pc):
                        return
                # the interpreter's step, as in _run_spin
                op = mem[pc]
                key = tf + ACC[op] + (self.access_wide[op] & (mem[(pc + 1) & 0xFFFF] >> 3))
                if key >= limit:
                    if P is not None and P[pc] is not NOPRIV:
                        c.t = t
                        if self._run_private(c, limit, stop_pc):
                            return
                    break
                if AH:
                    if self.watch[(pc & 0xFFFF) >> 2] & AHEAD:    # code in the window of a cog ahead
                        self._intrude(c, pc, tf)            # (its bytes may change before the key)
                        self._end_preemption()
                        break
                    self._g_cog, self._g_key = c, key       # (operands are read through the guarded views)
                    c.pc = pc + 1
                    t = tf + self._guarded()[op](c, op, t)
                    self._g_cog = None
                else:
                    c.pc = pc + 1
                    t = tf + H[op](c, op, t)
                c.bytecodes += 1
                if self._preempt:
                    self._end_preemption()
                    break
                pc = c.pc
                if pc == stop_pc:
                    break
                if not 0 <= pc < 0x10000:
                    c.t = t
                    return self._run_spin(c, limit, stop_pc)
        except Reschedule as e:
            t = tf + e.rest
            c.bytecodes += 1
        except Preempted:
            c.pc = pc
            self._end_preemption()
        except CogStopped:
            c.bytecodes += 1
            return
        except RebootRequested:
            c.bytecodes += 1
            c.t = tf
            self._reboot_key = key
            raise
        except IndexError:
            raise self.fault(c, c.pc - 1, "stack or address out of hub range") from None
        finally:
            self._g_cog = None
        if c.state == RUNNING:
            c.t = t

    def _block_stub(self, c: Cog, tf: int, limit: int) -> int:
        """The block table's entry for an address without a block: count, compile when hot."""
        pc = c.pc
        heat = self._heat[pc]
        hot = self.block_threshold
        if heat < hot:
            self._heat[pc] = heat + 1
            return -1
        if self._compiler is None:
            self._compiler = BlockCompiler(self, self._blocks, self._block_stub)
        fn = self._compiler.compile(pc) if heat < hot + _RECOMPILE_LIMIT else None
        self._heat[pc] = min(heat + 1, 255)
        if fn is None:
            fn = _interpreted
        self._blocks[pc] = fn
        return fn(c, tf, limit)

    def _run_spin_probed(self, c: Cog, limit: int) -> None:
        """The instrumented twin of :meth:`_run_spin` for a probe (debugger, profiler).

        Runs ``c`` one bytecode at a time, exactly as the plain loop would
        (same limit test, same handlers, back to the scheduler after a
        bytecode that changes what the cogs do), and calls ``probe.before(chip, cog)``
        before each and ``probe.after(chip, cog, pc, t)`` after it (``pc``,
        ``t``: where and when it started).  Either may raise
        :class:`~spinemu.chip.control.Halted` to stop the run between two
        bytecodes.
        """
        if self._preempt:                       # as _run_spin: a pending preemption ends the slice at once
            self._end_preemption()
            return
        probe = self.probe
        run = self._run_spin
        try:
            while c.state == RUNNING:
                key = self._key(c)
                if key >= limit:
                    return
                probe.before(self, c)
                pc, t = c.pc, c.t
                self.now = t
                run(c, key + 1)
                if self._preempt:               # it woke a cog waiting on pins: let the scheduler look
                    self._end_preemption()
                    probe.after(self, c, pc, t)
                    return
                probe.after(self, c, pc, t)
                if self._cogs_changed:          # it started, stopped or parked a cog (Reschedule): so
                    return                      # does the plain loop, and the scheduler looks again
        except Halted:
            if c.state == RUNNING:
                self.now = c.t
            raise

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
