"""Pulses: widths, periods and duty of a pin, live or on recorded traces (servo signals, PWM).

A *pulse* is a stretch at the active level (high unless set otherwise),
from a rising edge to the next falling edge.  Its *period* is the time from
its start to the next pulse's start.  A hobby servo reads the width (about
1-2 ms every 20 ms); a PWM output's duty is width over period.

:class:`PulseDecoder` is fed ``(cycle, level)`` in time order and makes
:class:`Pulse` records; :func:`decode_pulses` does it on a trace.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional

from .levels import level_changes

__all__ = ["Pulse", "PulseDecoder", "decode_pulses", "pulse_stats"]


@dataclass(frozen=True)
class Pulse:
    """One pulse: ``start`` and ``end`` cycles; ``period`` to the next pulse's start (``None`` for the last)."""

    start: int
    end: int
    period: Optional[int] = None

    @property
    def width(self) -> int:
        return self.end - self.start

    @property
    def duty(self) -> Optional[float]:
        return self.width / self.period if self.period else None


class PulseDecoder:
    """A streaming pulse decoder of one pin.

    Args:
        active: the level of a pulse (1: high pulses).
        on_pulse: called with each :class:`Pulse` when it ends (its period is not known yet).

    >>> d = PulseDecoder()
    >>> for t, lv in [(100, 1), (250, 0), (1100, 1), (1300, 0)]:
    ...     d.feed(t, lv)
    >>> [(p.width, p.period) for p in d.pulses]
    [(150, 1000), (200, None)]
    """

    def __init__(self, active: int = 1, on_pulse: Optional[Callable[[Pulse], None]] = None):
        self.active = 1 if active else 0
        self.on_pulse = on_pulse
        self.pulses: list[Pulse] = []
        self.level = 1 - self.active
        self._rise: Optional[int] = None
        self.high_cycles = 0        # cycles at the active level, pulses ended so far
        self.first: Optional[int] = None

    def feed(self, cycle: int, level: int) -> None:
        level = 1 if level else 0
        if level == self.level:
            return
        self.level = level
        if level == self.active:
            self._rise = cycle
            if self.first is None:
                self.first = cycle
            if self.pulses and self.pulses[-1].period is None:
                last = self.pulses[-1]
                self.pulses[-1] = Pulse(last.start, last.end, cycle - last.start)
        elif self._rise is not None:
            p = Pulse(self._rise, cycle)
            self._rise = None
            self.pulses.append(p)
            self.high_cycles += p.width
            if self.on_pulse is not None:
                self.on_pulse(p)

    @property
    def in_pulse(self) -> bool:
        return self._rise is not None


def pulse_stats(pulses, clock_hz: int) -> dict:
    """Widths (seconds: min, max, last), periods and mean duty of some pulses."""
    if not pulses:
        return {"count": 0}
    widths = [p.width / clock_hz for p in pulses]
    periods = [p.period / clock_hz for p in pulses if p.period]
    duties = [p.duty for p in pulses if p.duty is not None]
    return {"count": len(pulses), "min_width": min(widths), "max_width": max(widths), "last_width": widths[-1],
            "min_period": min(periods) if periods else None, "max_period": max(periods) if periods else None,
            "duty": sum(duties) / len(duties) if duties else None}


def decode_pulses(trace, pin: int, active: int = 1) -> PulseDecoder:
    """The pulses on ``pin`` of a recorded trace (an undriven pin reads inactive).

    Raises:
        ValueError: for a pin the trace does not have.
    """
    if not 0 <= pin < trace.pin_count:
        raise ValueError(f"pin {pin} does not exist (pins are 0..{trace.pin_count - 1})")
    d = PulseDecoder(active)
    for cycle, (lv,) in level_changes(trace.changes, (pin,), idle=1 - d.active):
        d.feed(cycle, lv)
    return d
