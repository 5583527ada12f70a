"""The combined pin states of a run, folded in time order one stretch of time after another.

Two records make the pins (Propeller Manual v1.2, "I/O Pins": ``dir`` is the
OR of the running cogs' DIRA, ``out`` the OR of ``DIRA & (OUTA | counter
outputs)``):

* the pin record ``chip.pin_events``: ``(cycle, seq, cog, dira, outa,
  running)`` as the cogs write DIRA/OUTA, start and stop (:mod:`.pins`),
  appended slightly out of time order because each cog runs a slice ahead
  of the others;
* the counters' marks (:mod:`.countermarks`): where a counter's output
  changes, from the counters' register history.

:class:`PinFold` merges them, a counter mark before a pin event of the same
cycle and the lower cog's event first, and keeps every change of ``(dir, out)``
in :attr:`PinFold.changes`.
:meth:`PinFold.advance` folds up to a cycle; the scheduler's pin listeners
(:mod:`.listen`) call it as the run goes, the trace (:meth:`.pins.Pins._build_trace`)
at the end, so both see the same states.  Each call costs time in
proportion to the events and marks it folds.  The pin record itself is
never reordered (:mod:`.pinhistory` reads it by position).
"""
from __future__ import annotations

from bisect import bisect_left

from .countermarks import CounterMarks

__all__ = ["PinFold"]


def _order(event) -> tuple:
    """Pin events in time order; on one cycle the lower cog first (as spinsim steps its cogs), and
    one cog's in the order it made them."""
    return event[0], event[2], event[1]


class PinFold:
    """The pin states of a chip, folded up to :attr:`folded_to` (see the module docstring).

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip` whose records are folded.
    """

    def __init__(self, chip):
        self.chip = chip
        self.marks = CounterMarks(chip.counters)
        #: ``(cycle, dir, out)`` each time the combined state changed, from ``(0, 0)``, in time order
        self.changes: list = []
        #: everything before this cycle is folded
        self.folded_to = 0
        #: pin events that came after their cycle had been folded (folded at :attr:`folded_to` instead;
        #: 0 unless a timing rule is broken)
        self.late = 0
        self._seen = 0              # chip.pin_events before this index are taken
        self._pending: list = []    # taken, not folded yet, sorted
        self._drives: dict = {}     # running cog: (dira, outa | counter outputs, outa)
        self._ctr = [[0, 0] for _ in range(8)]     # what each cog's counters A and B drive high
        self._pins = (0, 0)
        self._stops = [-1] * 8      # per cog: record number (seq) of its last stop folded

    def advance(self, upto: int) -> int:
        """Fold the pin events and counter marks before cycle ``upto``.

        Returns:
            the index in :attr:`changes` of the first change this call added.
        """
        first = len(self.changes)
        floor = self.folded_to
        if upto <= floor:
            return first
        chip = self.chip
        events = chip.pin_events
        pending = self._pending
        if self._seen < len(events):
            new = events[self._seen:]
            self._seen = len(events)
            if floor and min(new)[0] < floor:
                for k, ev in enumerate(new):
                    if ev[0] < floor:       # too late for its cycle: folded now
                        self.late += 1
                        new[k] = (floor,) + ev[1:]
            pending += new
            pending.sort(key=_order)
        n = bisect_left(pending, (upto,))
        marks = self.marks.take(upto) if chip.counters_on else ()
        self.folded_to = upto
        if not n and not marks:
            return first
        drives, ctr, changes, stops = self._drives, self._ctr, self.changes, self._stops
        d, o = self._pins
        i = j = 0
        m = len(marks)
        while i < n or j < m:
            if j < m and (i >= n or marks[j][0] <= pending[i][0]):
                t, cog, ab, mask = marks[j]
                j += 1
                c = ctr[cog]
                c[ab] = mask
                if cog not in drives:
                    continue
                dira, _, outa = drives[cog]
                drives[cog] = (dira, outa | c[0] | c[1], outa)
            else:
                t, seq, cog, dira, outa, running = pending[i]
                i += 1
                if running and seq < stops[cog]:
                    continue                # written before, timed after, the cog's stop: never happened
                if not running:
                    stops[cog] = seq
                if running:
                    c = ctr[cog]
                    drives[cog] = (dira, outa | c[0] | c[1], outa)
                else:
                    drives.pop(cog, None)
            nd = no = 0
            for dd, oo, _ in drives.values():
                nd |= dd
                no |= dd & oo
            if nd != d or no != o:
                d, o = nd, no
                changes.append((t, d, o))
        del pending[:n]
        self._pins = (d, o)
        return first
