"""Live pin listeners: the bench's view of a running chip.

:class:`Listeners` is a mixin of :class:`spinemu.chip.chip.Chip`.  The pins
are recorded as the cogs write them (:mod:`.pins`), slightly out of time
order because each cog runs a slice ahead of the others.  A listener
(:meth:`Listeners.add_pin_listener`) is called as
``listener(changes, upto, present)``:

* ``changes``: the combined pin states ``(cycle, dir, out)`` (as in the
  trace) that became final since the previous call, in time order;
* ``upto``: no pin changes before this cycle any more: the earliest next
  bytecode of the running cogs (for an engine object, its next shared
  access), or the next input change or counter edge that wakes a
  pin-waiting cog, counter edges up to it included, and never after
  ``present``;
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
pins any more (every cog stopped, a deadlock).  Without listeners none of
this runs.
"""
from __future__ import annotations

from typing import Optional

from .cog import STOPPED

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
        self._listen_pos = 0                # pin_events before this index were handed over
        self._listen_state: dict = {}       # cog -> (dira, outa) of the handed-over events
        self._listen_pins = (0, 0)
        self._listened_to = 0
        #: pin events recorded before the cycle already handed to listeners (0 unless a timing rule is broken)
        self.late_pin_events = 0

    def add_pin_listener(self, listener, interval_cycles: Optional[int] = None) -> None:
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
        self._deliver_pins(min(h, present), present)

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
        """Fold the recorded pin events before ``upto`` and hand them to the listeners."""
        if upto < self._listened_to:
            upto = self._listened_to
        if self.counters_on:
            for c in self.cogs:
                if c.state != STOPPED:
                    self.counters.flush(c, upto - 1)
        ev = self.pin_events
        i = self._listen_pos
        n = len(ev)
        if n - i > 1:
            tail = ev[i:]
            tail.sort()
            ev[i:] = tail
        state = self._listen_state
        d, o = self._listen_pins
        floor = self._listened_to
        changes = []
        while i < n:
            t, _, cog_id, dira, outa, running = ev[i]
            if t >= upto:
                break
            i += 1
            if t < floor:               # came later than promised: hand it over at once
                self.late_pin_events += 1
                t = floor
            if running:
                state[cog_id] = (dira, outa)
            else:
                state.pop(cog_id, None)
            nd = no = 0
            for dd, oo in state.values():
                nd |= dd
                no |= dd & oo
            if nd != d or no != o:
                d, o = nd, no
                changes.append((t, d, o))
        self._listen_pos = i
        self._listen_pins = (d, o)
        self._listened_to = upto
        for listener in self.pin_listeners:
            listener(changes, upto, present)
