"""Live pin listeners: the bench's view of a running chip.

:class:`Listeners` is a mixin of :class:`spinemu.chip.chip.Chip`.  The pins
are recorded as the cogs write them (:mod:`.pins`), slightly out of time
order because each cog runs a slice ahead of the others.  A listener
(:meth:`Listeners.add_pin_listener`) is called as
``listener(changes, upto, present)``:

* ``changes``: the combined pin states ``(cycle, dir, out)`` that became
  final since the previous call, in time order, counter outputs included:
  the same list the trace is made of (both read one
  :class:`~spinemu.chip.pinfold.PinFold`, ``chip.pin_fold``);
* ``upto``: no pin changes before this cycle any more: the earliest next
  bytecode of the running cogs (for an engine object, its next shared
  access), or the next input change or counter edge that wakes a
  pin-waiting cog, counter edges up to it included, and never after
  ``present`` or the cycle limit;
* ``present``: the earliest cycle at which a new input change is still seen
  by the program (every read of the pins so far came before it): the next
  shared access of the running cogs, or, while every cog waits on pins, the
  latest moment one started waiting.

The scheduler calls :meth:`Listeners._listen` at least every
``listen_interval`` cycles (it shortens a cog's slice for that).  While every
cog waits on pins that nothing is going to change, :meth:`Listeners._idle_listen`
lets listeners see time pass (they may send input) before the run ends at the
cycle limit or in a deadlock.  The last call, at the end of the run, has
``upto`` one past the last cycle, or ``1 << 62`` when nothing can change the
pins any more (every cog stopped, a deadlock); then a listener object with a
``run_ended`` method is told the run's last cycle.  When the scheduler jumps
over more than two intervals (every cog in WAITCNT, a pin wait for a far
edge), the listeners still get a call every ``listen_interval`` cycles of it
(a live view keeps moving), each with the pins up to that cycle; shorter
jumps get one call, as before.  Without listeners none of
this runs.

Each call folds only what is new since the previous one (the pin events
and the counters' output changes before ``upto``; :mod:`.pinfold`,
:mod:`.countermarks`), so listening costs time in proportion to the calls
and the changes, however long the run.
"""
from __future__ import annotations


__all__ = ["Listeners"]

_NEVER = 1 << 62
#: while every cog waits and no input is due, how long listeners see the pins
#: unchanged before the run ends in a deadlock (in seconds of simulated time)
IDLE_SECONDS_BEFORE_DEADLOCK = 1.0


class Listeners:
    """Live pin listeners of a chip (mixin)."""

    def _init_listeners(self) -> None:
        self.pin_listeners: list = []
        self.listen_interval = None
        self._listen_at = 0                 # the scheduler tells the listeners when it reaches this cycle
        self._listen_from = 0               # pin_fold.changes before this index were handed over
        self._listened_to = 0
        self._listen_end = _NEVER           # one past the run's last cycle, when known (the cycle limit)

    @property
    def late_pin_events(self) -> int:
        """Pin events recorded before the cycle already handed to listeners (0 unless a timing rule is broken)."""
        return self.pin_fold.late

    def add_pin_listener(self, listener, interval_cycles: int | None = None) -> None:
        """Call ``listener(changes, upto, present)`` as the run goes (see the module docstring).

        Args:
            listener: the callable.  It may change the inputs (``self.inputs``)
                at or after ``present``.
            interval_cycles: call it at least this often in simulated time
                (default: a hundredth of a second).

        Raises:
            RuntimeError: once the run has started.
            ValueError: for an interval below 1.
        """
        if self._started:
            raise RuntimeError("add pin listeners before the run starts")
        if interval_cycles is None:
            interval_cycles = max(1, self.clock_hz // 100)
        if interval_cycles < 1:
            raise ValueError("interval_cycles must be at least 1")
        self.pin_listeners.append(listener)
        if self.listen_interval is None or interval_cycles < self.listen_interval:
            self.listen_interval = interval_cycles

    def _listen(self, running, ext, now: int, present: int) -> None:
        """The scheduler's hook (``now``: the next access or input change it handles)."""
        h = ext if ext is not None else now
        for k in running:
            x = k.t if k.engine.__class__ is str else self._key(k)
            if x < h:
                h = x
        self._listen_at = now + self.listen_interval
        # a listener may make an input change at present, which can wake a waiting cog there
        upto = min(h, present)
        step = self.listen_interval
        if upto - self._listened_to > 2 * step:     # time jumped (WAITCNT, a far pin edge): keep the interval
            t = self._listened_to + step
            while t < upto:
                self._deliver_pins(t, present)
                t += step
        self._deliver_pins(upto, present)

    def _run_ended(self, end: int) -> None:
        """After the last call: tell the listeners that have ``run_ended`` the run's last cycle."""
        for listener in self.pin_listeners:
            ended = getattr(listener, "run_ended", None)
            if ended is not None:
                ended(end)

    def _idle_listen(self, limit: int) -> bool:
        """Every cog waits on pins nothing will change: step time for the listeners.

        Returns ``True`` as soon as one of them has made an input change due
        (the scheduler then runs on), ``False`` at the cycle limit or, without
        one, after :data:`IDLE_SECONDS_BEFORE_DEADLOCK`.
        """
        t = max(self._listened_to, self.now, self._ext_seen)
        end = limit if limit < _NEVER else t + int(IDLE_SECONDS_BEFORE_DEADLOCK * self.clock_hz)
        step = self.listen_interval
        while t < end:
            t = min(t + step, end)
            self._deliver_pins(t, t)
            if self._next_external(limit) is not None:
                self._listen_at = t + self.listen_interval
                return True
            step = min(2 * step, max(self.listen_interval, self.clock_hz))
        return False

    def _deliver_pins(self, upto: int, present: int) -> None:
        """Fold the pins before ``upto`` and hand the new states over.

        Nothing after the run's last cycle is folded (:attr:`_listen_end`):
        the scheduler may know that no cog changes the pins for a while past
        the cycle limit, but the run, its trace and the counters stop there.
        ``upto`` is :data:`_NEVER` only in the last call, after the run.
        """
        end = self._listen_end
        if upto > end and upto < _NEVER:
            upto = end
        if upto < self._listened_to:
            upto = self._listened_to
        fold = self.pin_fold
        fold.advance(upto if upto < end else end)
        changes = fold.changes[self._listen_from:]
        self._listen_from = len(fold.changes)
        self._listened_to = upto
        for listener in self.pin_listeners:
            listener(changes, upto, present)
