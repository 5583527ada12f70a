"""What the engine drove on the pins, as a part reads it: the drive history.

A part whose outputs depend on what the program does (an I2C EEPROM that
answers the master, an RC circuit whose level depends on when the program
stopped charging it, an LCD that shows its busy flag) computes them from the
*drive history* of its pins.  Every engine offers one as
``engine.drive_history``:

* ``driven(cycle) -> (dir, out)``: the drives in force at ``cycle``
  (``dir``: the pins the engine drives; ``out``: those driven high);
* ``changes(start, end) -> [(cycle, dir, out), ...]``: the drive state at
  every recorded change in ``[start, end)``, in time order;
* ``recorded_since(mark) -> (earliest, new_mark)``: the earliest cycle of
  the changes recorded since ``mark`` (``None`` if none); ``mark`` starts
  at 0.  An engine that runs several processors a little apart in time (the
  Propeller's cogs) may record a change after a later one: a part that has
  already worked past that cycle must work again from before it
  (:class:`spinemu.bench.part.ReactivePart` does);
* ``recorded_end() -> int``: one past the latest cycle a change was recorded at.

The rule that makes a part's outputs exact: when an engine asks an input
model for ``levels(t)`` (a program reads its pins at ``t``), every drive
before ``t`` is recorded.

:class:`TraceHistory` is the history of an engine that records its pins in
time order (the BASIC Stamp) or of a recorded :class:`~spinemu.trace.PinTrace`;
the Propeller's is :mod:`spinemu.chip.drives`.
"""
from __future__ import annotations

from bisect import bisect_left, bisect_right

__all__ = ["TraceHistory"]


class TraceHistory:
    """The drive history of a list of ``(cycle, dir, out)`` states kept in time order.

    Args:
        changes: the list the engine appends to (read live, never copied),
            e.g. ``PinTrace.changes``.

    >>> h = TraceHistory([(0, 0, 0), (10, 1, 1), (20, 1, 0)])
    >>> h.driven(15), h.changes(10, 21), h.recorded_end()
    ((1, 1), [(10, 1, 1), (20, 1, 0)], 21)
    """

    def __init__(self, changes: list):
        self.list = changes

    def driven(self, cycle: int) -> tuple[int, int]:
        ch = self.list
        i = bisect_right(ch, (cycle, 1 << 64, 0))
        if not i:
            return 0, 0
        _, d, o = ch[i - 1]
        return d, o

    def changes(self, start: int, end: int) -> list:
        ch = self.list
        i = bisect_left(ch, (start,))
        j = bisect_left(ch, (end,))
        return ch[i:j]

    def recorded_since(self, mark: int):
        ch = self.list
        n = len(ch)
        if mark >= n:
            return None, n
        return min(c for c, _, _ in ch[mark:]), n

    def recorded_end(self) -> int:
        return self.list[-1][0] + 1 if self.list else 0
