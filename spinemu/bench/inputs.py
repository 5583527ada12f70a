"""Composing input models: a part that drives some pins on top of whatever else the run has.

An *input model* says what the pins nobody on the chip drives read (see
``spinemu.chip.inputs``): ``levels(cycle) -> int`` (32-bit pin levels) and
``next_change(cycle) -> int | None`` (the first cycle after ``cycle`` at which
``levels`` changes).  Engines skip time in pin waits by ``next_change``, so a
composed model must keep it exact: :class:`PinOverride` replaces the pins in
a mask by a part's levels and reports the earlier of both models' changes.
"""
from __future__ import annotations

from typing import Optional

__all__ = ["PinOverride"]


class PinOverride:
    """``base``'s levels, with the pins in ``mask`` taken from ``part``.

    Args:
        base: the input model underneath (pull-ups, ``--input`` stimuli, ...).
        mask: the pins ``part`` drives.
        part: an object with ``levels(cycle)`` and ``next_change(cycle)`` (only
            its bits in ``mask`` are used).

    >>> class High:
    ...     def levels(self, cycle): return 0xFFFFFFFF
    ...     def next_change(self, cycle): return None
    >>> class Blink:
    ...     def levels(self, cycle): return (cycle // 10 % 2) << 3
    ...     def next_change(self, cycle): return (cycle // 10 + 1) * 10
    >>> m = PinOverride(High(), 1 << 3, Blink())
    >>> hex(m.levels(5)), hex(m.levels(15)), m.next_change(5)
    ('0xfffffff7', '0xffffffff', 10)
    """

    def __init__(self, base, mask: int, part):
        self.base = base
        self.mask = mask & 0xFFFFFFFF
        self.keep = ~mask & 0xFFFFFFFF
        self.part = part

    def levels(self, cycle: int) -> int:
        return (self.base.levels(cycle) & self.keep) | (self.part.levels(cycle) & self.mask)

    def next_change(self, cycle: int) -> Optional[int]:
        a = self.part.next_change(cycle)
        b = self.base.next_change(cycle)
        if a is None:
            return b
        if b is None or a < b:
            return a
        return b
