"""A push button on a pin: pressed at given times, with contact bounce if asked.

A button with a pull-down resistor reads high while pressed
(``active="high"``, the Board of Education and Propeller board wiring); one
with a pull-up reads low while pressed (``active="low"``).  A real contact
bounces: for a few milliseconds after it closes or opens, the level flips
back and forth before it settles.  With ``bounce`` (seconds), each press
and each release starts with ``bounce_edges`` extra flips at times spread
over that window (the same times on every run: they come from a seeded
generator), which is what BASIC Stamp ``BUTTON`` and debouncing loops in
Spin are written for.
"""
from __future__ import annotations

import math
import random
from typing import Iterable, Optional

from .inputs import PinStimulus
from .part import Part, check_pin

__all__ = ["Button"]


class Button(Part):
    """A push button (see the module docstring).

    Args:
        pin: its pin.
        presses: ``(press, release)`` times in seconds (more with :meth:`press`).
        active: ``"high"`` (reads 1 while pressed) or ``"low"``.
        bounce: how long the contact bounces after each change (seconds; 0: clean).
        bounce_edges: extra level flips in each bounce (even, so that it settles).
        seed: the bounce times' seed (default: the pin number).

    Raises:
        ValueError: for a bad pin, times that are not increasing, an odd ``bounce_edges``.
    """

    kind = "button"

    def __init__(self, *, pin: int, presses: Iterable = (), active: str = "high", bounce: float = 0.0,
                 bounce_edges: int = 4, seed: Optional[int] = None, name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        if active not in ("high", "low"):
            raise ValueError(f"active must be 'high' or 'low', not {active!r}")
        if not (isinstance(bounce, (int, float)) and math.isfinite(bounce) and bounce >= 0):
            raise ValueError(f"bounce must be a number of seconds >= 0, not {bounce!r}")
        if bounce_edges < 0 or bounce_edges % 2:
            raise ValueError(f"bounce_edges must be an even number >= 0, not {bounce_edges!r}")
        self.active = 1 if active == "high" else 0
        self.bounce, self.bounce_edges = float(bounce), bounce_edges
        self.seed = pin if seed is None else seed
        self.presses: list[tuple[float, float]] = []
        self._stim: Optional[PinStimulus] = None
        for p in presses:
            self.press(*p) if isinstance(p, (tuple, list)) else self.press(p)

    @property
    def name(self) -> str:
        return self._name or f"button P{self.pin}"

    def press(self, at: float, release: Optional[float] = None) -> None:
        """Press at ``at`` seconds, release at ``release`` (default 0.1 s later).

        Raises:
            ValueError: for times that are not finite, not increasing, or overlap an earlier press.
        """
        release = at + 0.1 if release is None else release
        for v in (at, release):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                raise ValueError(f"press times must be seconds >= 0, not {v!r}")
        if release <= at:
            raise ValueError(f"a press at {at} s must be released later, not at {release} s")
        if self.presses and at <= self.presses[-1][1]:
            raise ValueError(f"presses must come in time order, one after the other (a press at {at} s)")
        if self._stim is not None:
            raise RuntimeError("press the button before the run starts")
        self.presses.append((float(at), float(release)))

    def driven_pins(self) -> tuple:
        return (self.pin,)

    def connect(self, port) -> None:
        super().connect(port)
        rng = random.Random(self.seed)
        bit = 1 << self.pin
        rest = 0 if self.active else bit
        changes = []
        width = int(round(self.bounce * self.clock_hz))
        for at, release in self.presses:
            for t, pressed in ((at, True), (release, False)):
                c = int(round(t * self.clock_hz))
                level = (bit if pressed else 0) if self.active else (0 if pressed else bit)
                flips = sorted(rng.randrange(1, width) for _ in range(self.bounce_edges)) if width > 1 else []
                changes.append((c, bit, level))
                for k, dt in enumerate(flips):
                    changes.append((c + dt, bit, level ^ bit if k % 2 == 0 else level))
        self._stim = PinStimulus(changes, initial=rest)

    def levels(self, cycle: int) -> int:
        return self._stim.levels(cycle)

    def next_change(self, cycle: int) -> Optional[int]:
        return self._stim.next_change(cycle)

    def pressed_at(self, seconds: float) -> bool:
        """Held down at ``seconds`` (bounce aside)."""
        return any(a <= seconds < b for a, b in self.presses)

    def finish(self, end_cycle: int) -> None:
        self._seen = end_cycle

    def summary(self) -> str:
        end = self._now() / self.clock_hz if self.clock_hz else 0.0
        n = sum(1 for at, _ in self.presses if at < end)
        later = len(self.presses) - n
        b = f", bouncing {self.bounce * 1e3:g} ms" if self.bounce else ""
        rest = f" ({later} more after the end of the run)" if later else ""
        return f"{self.name}: pressed {n} time{'s' if n != 1 else ''}{b}{rest}"

    def view(self) -> str:
        return "pressed" if self._stim and (self._stim.levels(self._now()) >> self.pin & 1) == self.active else "up"

    def _now(self) -> int:
        return getattr(self, "_seen", 0)

    def on_pins(self, changes, upto, present) -> None:
        if upto < 1 << 62:
            self._seen = upto
