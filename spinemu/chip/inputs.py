"""What the pins nobody drives read: the input model behind INA.

A pin is driven when some running cog has its DIRA bit set; INA then reads the
driven level.  Every other pin reads what the input model says:

* ``"pulldown"``: 0 (default in chip mode: on a bare chip a floating input
  reads whatever leaks onto it; pick what your board has);
* ``"pullup"``: 1 (what spinsim 0.99 reads; default in spinsim mode);
* a :class:`PinStimulus`: levels that change at given cycles (a waveform
  generator on the pins);
* any object with ``levels(cycle) -> int`` (32-bit pin levels) and
  ``next_change(cycle) -> int | None`` (the first cycle after ``cycle`` at
  which ``levels`` changes, or ``None``); ``WAITPEQ``/``WAITPNE`` on undriven
  pins wake exactly at those cycles;
* a plain callable ``f(cycle) -> int``: like ``levels``; since it cannot say
  when it changes, a cog waiting on it re-reads it every
  :data:`CALLABLE_POLL_CYCLES` cycles.
"""
from __future__ import annotations

import bisect
from typing import Iterable, Optional

__all__ = ["PinStimulus", "make_input_model", "CALLABLE_POLL_CYCLES"]

#: how often a cog waiting on a plain-callable stimulus re-reads it
CALLABLE_POLL_CYCLES = 1000


class _Constant:
    def __init__(self, level: int):
        self.level = level

    def levels(self, cycle: int) -> int:
        return self.level

    def next_change(self, cycle: int) -> Optional[int]:
        return None


class PinStimulus:
    """Pin levels that change at given cycles.

    Args:
        changes: ``(cycle, mask, levels)``: from ``cycle`` on, the pins in
            ``mask`` read the bits of ``levels``.
        initial: the levels before the first change.

    >>> s = PinStimulus([(1000, 0x1, 0x1), (5000, 0x1, 0x0)])
    >>> s.levels(999), s.levels(1000), s.next_change(1000), s.next_change(6000)
    (0, 1, 5000, None)
    """

    def __init__(self, changes: Iterable[tuple[int, int, int]], initial: int = 0):
        self.times: list[int] = []
        self.values: list[int] = []
        level = initial & 0xFFFFFFFF
        for cycle, mask, levels in sorted(changes, key=lambda ch: ch[0]):
            level = (level & ~mask) | (levels & mask)
            if self.times and self.times[-1] == cycle:
                self.values[-1] = level
            else:
                self.times.append(cycle)
                self.values.append(level)
        self.initial = initial & 0xFFFFFFFF

    def levels(self, cycle: int) -> int:
        i = bisect.bisect_right(self.times, cycle)
        return self.values[i - 1] if i else self.initial

    def next_change(self, cycle: int) -> Optional[int]:
        i = bisect.bisect_right(self.times, cycle)
        return self.times[i] if i < len(self.times) else None


class _Polled:
    def __init__(self, fn):
        self.fn = fn

    def levels(self, cycle: int) -> int:
        return int(self.fn(cycle)) & 0xFFFFFFFF

    def next_change(self, cycle: int) -> Optional[int]:
        return cycle + CALLABLE_POLL_CYCLES


def make_input_model(inputs, *, pull_up: bool):
    """The input model for a ``Chip(inputs=...)`` argument.

    Raises:
        ValueError: for a string other than ``"pullup"``/``"pulldown"``.
    """
    if inputs is None:
        return _Constant(0xFFFFFFFF if pull_up else 0)
    if isinstance(inputs, str):
        if inputs == "pullup":
            return _Constant(0xFFFFFFFF)
        if inputs == "pulldown":
            return _Constant(0)
        raise ValueError(f"inputs must be 'pullup', 'pulldown' or a stimulus, not {inputs!r}")
    if hasattr(inputs, "levels") and hasattr(inputs, "next_change"):
        return inputs
    if callable(inputs):
        return _Polled(inputs)
    raise ValueError("inputs must be 'pullup', 'pulldown', an object with levels()/next_change(), or a callable")
