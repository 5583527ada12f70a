"""The chip's drive history, as bench parts read it (the protocol of :mod:`spinemu.bench.history`).

A part whose outputs depend on what the program drives (an I2C EEPROM, an RC
circuit, an LCD's busy flag) reads the cogs' drives through this history.
It is built on the pin record (``chip.pin_events``: DIRA/OUTA as each cog
wrote them) sorted per cog by :class:`~spinemu.chip.pinhistory.PinHistory`:
``dir`` is the OR of the running cogs' DIRA, ``out`` the OR of
``DIRA & OUTA`` (Propeller Manual v1.2, "I/O Pins").  Counter outputs are
not in it: parts see the pins the cogs set (counter outputs reach the
trace, the pin listeners and the counters themselves).

Cogs run a slice apart, so a change may be recorded after a later one; it
is still recorded before any cog reads the pins at or after its cycle (reads
happen where the scheduler has run every other cog up to them), and
:meth:`ChipDrives.recorded_since` tells a part about it.
"""
from __future__ import annotations

from bisect import bisect_left, insort

__all__ = ["ChipDrives"]


class ChipDrives:
    """The drive history of a :class:`~spinemu.chip.chip.Chip` (see the module docstring)."""

    def __init__(self, chip):
        self.chip = chip
        self.history = chip.counters.history
        self._seen = 0
        self._times: list[int] = []

    def _update(self) -> None:
        events = self.chip.pin_events
        n = len(events)
        if self._seen == n:
            return
        times = self._times
        for k in range(self._seen, n):
            t = events[k][0]
            if not times or t > times[-1]:
                times.append(t)
            elif t != times[-1]:
                i = bisect_left(times, t)
                if i == len(times) or times[i] != t:
                    insort(times, t)
        self._seen = n

    def driven(self, cycle: int) -> tuple[int, int]:
        """``(dir, out)`` the running cogs drive at ``cycle``."""
        state = self.history.cog_state
        d = o = 0
        for cog in range(8):
            dira, outa, running = state(cog, cycle)
            if running:
                d |= dira
                o |= dira & outa
        return d, o

    def changes(self, start: int, end: int) -> list:
        """``(cycle, dir, out)`` at every recorded change in ``[start, end)``."""
        self._update()
        times = self._times
        i = bisect_left(times, start)
        j = bisect_left(times, end)
        driven = self.driven
        return [(t,) + driven(t) for t in times[i:j]]

    def recorded_since(self, mark: int):
        """``(earliest cycle recorded since mark or None, new mark)``."""
        events = self.chip.pin_events
        n = len(events)
        if mark >= n:
            return None, n
        return min(e[0] for e in events[mark:n]), n

    def recorded_end(self) -> int:
        """One past the latest cycle a change was recorded at."""
        self._update()
        return self._times[-1] + 1 if self._times else 0
