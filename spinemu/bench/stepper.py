"""A stepper motor's coils on the pins: the steps the program made, run by run.

:class:`Stepper` watches four coil pins (in the drive table's order, as
``spinemu trace steps --pins`` takes them) and, at the end of the run,
decodes the coil patterns into steps with the stepper decoder
(:func:`spinemu.analysis.stepper.decode_steps`): how many steps, which way,
and the *runs* -- the stretches of steps in one direction at one speed
between pauses -- so a demo that turns one revolution forward and one back
five times shows ten runs of its step count.  An enable pin, if given, must
be high for the coils to count as driven.
"""
from __future__ import annotations

from typing import Optional, Sequence

from ..trace import PinTrace
from .part import Part, check_pin

__all__ = ["Stepper"]


class Stepper(Part):
    """Stepper motor coils (see the module docstring).

    Args:
        coils: the four coil pins, in table order.
        enable: the driver's enable pin (``None``: always enabled).

    Raises:
        ValueError: for a bad pin or not four coil pins.
    """

    kind = "stepper"
    pin_parameters = ("coils", "enable")

    def __init__(self, *, coils: Sequence[int], enable: Optional[int] = None, name: Optional[str] = None):
        super().__init__(name=name)
        self.coils = tuple(check_pin(p, "coil pin") for p in coils)
        if len(self.coils) != 4 or len(set(self.coils)) != 4:
            raise ValueError(f"a stepper needs four different coil pins, not {list(coils)}")
        self.enable = None if enable is None else check_pin(enable, "enable")
        self._mask = sum(1 << p for p in self.coils) | ((1 << self.enable) if self.enable is not None else 0)
        self._changes: list = [(0, 0, 0)]
        self._steps = None

    @property
    def name(self) -> str:
        return self._name or f"stepper P{min(self.coils)}-P{max(self.coils)}"

    def watched_pins(self) -> tuple:
        return self.coils + ((self.enable,) if self.enable is not None else ())

    def on_pins(self, changes, upto, present) -> None:
        mask = self._mask
        last = self._changes[-1]
        en = self.enable
        for c, d, o in changes:
            d, o = d & mask, o & mask
            if en is not None and not ((d >> en) & (o >> en) & 1):
                d = o = 0                       # disabled: the coils are off
            if (d, o) != last[1:]:
                last = (c, d, o)
                self._changes.append(last)
        self._steps = None

    def steps(self):
        """The decoded steps (:class:`spinemu.analysis.stepper.StepSequence`)."""
        if self._steps is None:
            from ..analysis.stepper import decode_steps
            trace = PinTrace(self.clock_hz, list(self._changes), self._changes[-1][0])
            self._steps = decode_steps(trace, list(self.coils))
        return self._steps

    def runs(self) -> list[int]:
        """Signed step counts of the runs (positive forward)."""
        out = []
        for seg in self.steps().segments():
            sign = -1 if seg.direction == -1 else 1
            out.append(sign * seg.count)
        return out

    def summary(self) -> str:
        seq = self.steps()
        if not len(seq):
            return f"{self.name}: no steps"
        runs = self.runs()
        shown = " ".join(f"{r:+d}" for r in runs[:12]) + (f" ... ({len(runs)} runs)" if len(runs) > 12 else "")
        return (f"{self.name}: {len(seq)} steps ({seq.mode}), net {seq.net_half_steps / 2:+g} full steps; "
                f"steps per run: {shown}")

    def view(self) -> str:
        return f"{len(self.steps())} steps"
