"""An LED on a pin: when it is lit, how often it was turned on, its duty.

The LED lights while the pin is driven to its active level: high for an LED
to ground through a resistor (``active="high"``, the usual wiring on the
Propeller demo board and the Board of Education), low for one to the supply
(``active="low"``).  An undriven pin leaves it dark.  A pin switched faster
than the eye follows (PWM from a counter, say) shows as its duty: the
fraction of the time the LED was lit.
"""
from __future__ import annotations

from typing import Optional

from .part import Part, check_pin

__all__ = ["Led"]


class Led(Part):
    """An LED (see the module docstring).

    Args:
        pin: its pin.
        active: ``"high"`` (lit when driven high) or ``"low"``.

    Attributes:
        changes: ``(cycle, lit)`` each time it went on or off, from ``(0, False)``.
        turned_on: how many times it went on.

    Raises:
        ValueError: for a bad pin or ``active``.
    """

    kind = "led"

    def __init__(self, *, pin: int, active: str = "high", name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        if active not in ("high", "low"):
            raise ValueError(f"active must be 'high' or 'low', not {active!r}")
        self.active = 1 if active == "high" else 0
        self.changes: list = [(0, False)]
        self.turned_on = 0
        self.lit_cycles = 0
        self.now = 0
        self.end_cycle: Optional[int] = None

    @property
    def name(self) -> str:
        return self._name or f"LED P{self.pin}"

    def watched_pins(self) -> tuple:
        return (self.pin,)

    @property
    def lit(self) -> bool:
        """Lit at the latest cycle seen."""
        return self.changes[-1][1]

    def on_pins(self, changes, upto, present) -> None:
        pin, active = self.pin, self.active
        for c, d, o in changes:
            lit = bool((d >> pin) & 1) and ((o >> pin) & 1) == active
            if lit != self.changes[-1][1]:
                if not lit:
                    self.lit_cycles += c - self.changes[-1][0]
                else:
                    self.turned_on += 1
                self.changes.append((c, lit))
        if upto < 1 << 62:
            self.now = max(self.now, upto)

    def finish(self, end_cycle: int) -> None:
        self.end_cycle = end_cycle
        self.now = end_cycle

    def lit_at(self, seconds: float) -> bool:
        cycle = seconds * self.clock_hz
        lit = False
        for c, on in self.changes:
            if c > cycle:
                break
            lit = on
        return lit

    @property
    def duty(self) -> float:
        """The fraction of the run (so far) the LED was lit."""
        end = self.now
        if end <= 0:
            return 0.0
        lit = self.lit_cycles
        if self.changes[-1][1]:
            lit += end - self.changes[-1][0]
        return lit / end

    def summary(self) -> str:
        if not self.turned_on:
            return f"{self.name}: never lit"
        state = "on" if self.lit else "off"
        return (f"{self.name}: turned on {self.turned_on} time{'s' if self.turned_on != 1 else ''}, "
                f"lit {100 * self.duty:.1f} % of the time, {state} at the end")

    def view(self) -> str:
        return ("\u25cf on " if self.lit else "\u25cb off") + f"  ({100 * self.duty:.0f} % lit so far)"
