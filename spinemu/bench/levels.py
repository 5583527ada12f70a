"""Pin levels out of pin states: the common input of every protocol decoder.

Engines, listeners and traces give pin *states* ``(cycle, dir, out)``: the
pins driven and those driven high.  A decoder wants the *levels* of a few
pins, changing over time; a pin nobody drives reads an idle level chosen by
the decoder (a pulled-up I2C line reads 1, an idle UART line its idle level).

* :func:`level_changes` - ``(cycle, levels)`` of some pins from states;
* :class:`LevelTracker` - the same, fed a piece at a time (live decoding).
"""
from __future__ import annotations

from typing import Iterable, Sequence

__all__ = ["level_changes", "LevelTracker", "parse_pin_list"]


class LevelTracker:
    """The levels of ``pins`` from pin states fed in time order.

    Args:
        pins: the pins, in the order the levels are given.
        idle: what an undriven pin reads (one level for all, or one per pin).

    >>> t = LevelTracker([0, 1], idle=1)
    >>> t.feed([(0, 0, 0), (5, 0b11, 0b01), (9, 0b11, 0b11)])
    [(5, (1, 0)), (9, (1, 1))]
    """

    def __init__(self, pins: Sequence[int], idle=0):
        self.pins = tuple(pins)
        self.idle = tuple(idle) if isinstance(idle, (tuple, list)) else (idle,) * len(self.pins)
        self.levels = self.idle

    def level_of(self, d: int, o: int) -> tuple:
        return tuple(((o >> p) & 1) if (d >> p) & 1 else i for p, i in zip(self.pins, self.idle))

    def feed(self, changes: Iterable) -> list:
        """The ``(cycle, levels)`` changes among ``changes``."""
        out = []
        last = self.levels
        for c, d, o in changes:
            lv = self.level_of(d, o)
            if lv != last:
                out.append((c, lv))
                last = lv
        self.levels = last
        return out


def level_changes(changes: Iterable, pins: Sequence[int], idle=0) -> list:
    """``(cycle, levels)`` each time one of ``pins`` changes level (see :class:`LevelTracker`)."""
    return LevelTracker(pins, idle).feed(changes)


def parse_pin_list(text: str, pin_count: int = 32) -> list[int]:
    """``"28,29"`` or ``"P28,P29"`` -> ``[28, 29]``.

    Raises:
        ValueError: for text that is not pin numbers separated by commas, or a pin out of range.

    >>> parse_pin_list("P28, 29")
    [28, 29]
    """
    pins = []
    for item in text.split(","):
        item = item.strip().upper().removeprefix("P")
        if not item.isdigit():
            raise ValueError(f"expected pin numbers separated by commas, got {text!r}")
        p = int(item)
        if not 0 <= p < pin_count:
            raise ValueError(f"pin {p} does not exist (pins are 0..{pin_count - 1})")
        pins.append(p)
    return pins
