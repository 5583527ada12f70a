"""What the outside world applies to the BS2's input pins.

A stimulus for one pin is a constant level, a list of ``(time_s, level)``
steps (the level holds from that time on), or a callable ``f(time_s) -> 0|1``.
Times are seconds since the start of the run; internally everything is in
microseconds, the BS2 time base of spinemu (see :mod:`.machine`).

An undriven pin with no stimulus reads ``float_level`` (README 1.1 OPEN:
default 0, settable).

>>> s = PinStimulus({3: [(0, 1), (0.010, 0)]})
>>> s.level(3, 9_999), s.level(3, 10_000), s.next_change(3, 0)
(1, 0, 10000)
"""
from __future__ import annotations

import bisect
from typing import Callable, Optional, Union

__all__ = ["PinStimulus", "parse_input_spec"]

Spec = Union[int, list, tuple, Callable[[float], int]]


class _Steps:
    __slots__ = ("times", "levels")

    def __init__(self, steps):
        pts = sorted((int(round(float(t) * 1_000_000)), 1 if lv else 0) for t, lv in steps)
        self.times = [t for t, _ in pts]
        self.levels = [lv for _, lv in pts]

    def level(self, t: int, default: int) -> int:
        i = bisect.bisect_right(self.times, t) - 1
        return self.levels[i] if i >= 0 else default

    def next_change(self, t: int, default: int) -> Optional[int]:
        cur = self.level(t, default)
        i = bisect.bisect_right(self.times, t)
        while i < len(self.times):
            if self.levels[i] != cur:
                return self.times[i]
            i += 1
        return None


class PinStimulus:
    """Levels of the input pins over time (16 pins, plus nothing else).

    Args:
        spec: ``{pin: level | [(time_s, level), ...] | callable}``.
        float_level: what an unstimulated, undriven pin reads (0 or 1).
    """

    #: Callables are sampled this often (microseconds) when searching for edges.
    CALLABLE_STEP_US = 1

    def __init__(self, spec: Optional[dict] = None, float_level: int = 0):
        self.float_level = 1 if float_level else 0
        self._const: dict[int, int] = {}
        self._steps: dict[int, _Steps] = {}
        self._calls: dict[int, Callable] = {}
        for pin, s in (spec or {}).items():
            pin = int(pin)
            if not 0 <= pin <= 15:
                raise ValueError(f"input pin {pin} is not 0..15")
            if callable(s):
                self._calls[pin] = s
            elif isinstance(s, (list, tuple)):
                self._steps[pin] = _Steps(s)
            else:
                self._const[pin] = 1 if s else 0
        self.static = not self._steps and not self._calls
        self.stimulated_mask = sum(1 << p for p in
                                   set(self._const) | set(self._steps) | set(self._calls))
        base = 0xFFFF if self.float_level else 0
        for pin, lv in self._const.items():
            base = (base | (1 << pin)) if lv else (base & ~(1 << pin))
        self._base_mask = base

    def level(self, pin: int, t_us: int) -> int:
        if pin in self._steps:
            return self._steps[pin].level(t_us, self.float_level)
        if pin in self._calls:
            return 1 if self._calls[pin](t_us / 1_000_000) else 0
        return self._const.get(pin, self.float_level)

    def mask(self, t_us: int) -> int:
        """All 16 input levels at ``t_us`` as a bit mask."""
        if self.static:
            return self._base_mask
        m = self._base_mask
        for pin in list(self._steps) + list(self._calls):
            if self.level(pin, t_us):
                m |= 1 << pin
            else:
                m &= ~(1 << pin)
        return m

    def next_change(self, pin: int, t_us: int, limit_us: Optional[int] = None) -> Optional[int]:
        """The first time after ``t_us`` at which the pin's level changes, or None."""
        if pin in self._steps:
            nxt = self._steps[pin].next_change(t_us, self.float_level)
            if nxt is not None and limit_us is not None and nxt > limit_us:
                return None
            return nxt
        if pin in self._calls:
            cur = self.level(pin, t_us)
            end = limit_us if limit_us is not None else t_us + 10_000_000
            t = t_us + self.CALLABLE_STEP_US
            while t <= end:
                if self.level(pin, t) != cur:
                    return t
                t += self.CALLABLE_STEP_US
            return None
        return None

    def edges(self, pin: int, start_us: int, end_us: int) -> list[int]:
        """Times of all level changes in ``(start_us, end_us]``."""
        out = []
        t = start_us
        while True:
            nxt = self.next_change(pin, t, end_us)
            if nxt is None or nxt > end_us:
                return out
            out.append(nxt)
            t = nxt


#: The latest time a stimulus step may name: about 32 years (any later time is never reached).
MAX_SECONDS = 1e9


def parse_input_spec(text: str) -> dict:
    """Parse a command-line stimulus: ``"3=1"``, ``"3=0@0,1@0.5,0@0.52"``.

    Several pins are separated by ``;``.  Times are seconds, 0 to
    :data:`MAX_SECONDS`.  Levels are 0 or 1.

    >>> parse_input_spec("3=1;5=0@0,1@0.25")
    {3: 1, 5: [(0.0, 0), (0.25, 1)]}
    >>> parse_input_spec("3=1@nan")
    Traceback (most recent call last):
    ...
    ValueError: time 'nan' in '3=1@nan' is not a number of seconds (0 to 1e+09)

    Raises:
        ValueError: saying which part of ``text`` is wrong.
    """
    out: dict = {}
    for part in text.split(";"):
        part = part.strip()
        if not part:
            continue
        pin, eq, rest = part.partition("=")
        pin = pin.strip().upper()
        pin = pin[1:] if pin.startswith("P") else pin
        if not eq or not _is_decimal(pin) or len(pin) > 3:
            raise ValueError(f"'{part}' does not start with a pin number and '=' (e.g. P3=1)")
        pin_n = int(pin)
        if "@" not in rest:
            out[pin_n] = _level(rest, part)
            continue
        steps = []
        for item in rest.split(","):
            lv, _, t = item.partition("@")
            steps.append((_seconds(t, part), _level(lv, part)))
        out[pin_n] = steps
    return out


def _is_decimal(text: str) -> bool:
    return text.isascii() and text.isdigit()


def _level(text: str, part: str) -> int:
    text = text.strip()
    if text not in ("0", "1"):
        raise ValueError(f"level '{text}' in '{part}' is not 0 or 1")
    return int(text)


def _seconds(text: str, part: str) -> float:
    import math

    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or not 0 <= value <= MAX_SECONDS:
        raise ValueError(f"time '{text.strip()}' in '{part}' is not a number of seconds (0 to {MAX_SECONDS:g})")
    return value
