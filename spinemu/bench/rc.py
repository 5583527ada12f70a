"""An RC circuit on a pin, and a potentiometer in one: what RCTIME and a counter's POS detector measure.

The circuit (BASIC Stamp manual, RCTIME; Parallax AN001 "Propeller
Counters", RC decay): the pin reaches a capacitor ``c`` through a series
resistor ``series``; a resistor ``r`` (a sensor, a potentiometer) goes from
the capacitor to ground (``to="ground"``) or to the supply (``to="vdd"``).
The program charges the capacitor by driving the pin (high for a circuit to
ground, low for one to the supply), then lets go of it: the capacitor
decays through ``r`` and the pin reads the old level until the voltage
crosses the input threshold.  That time is ``r * c * ln(V0 - Vrest) /
(Vth - Vrest))``: ``r * c * ln 2`` for a full charge and the Propeller's
threshold of half the supply.

The voltage is followed exactly: while the pin is driven it moves towards
the driven level through ``series`` (and ``r``), with time constant
``c * series * r / (series + r)``, so a short charge leaves it partly
charged; while the pin is free it moves towards the rest level through
``r``.  The pin reads 1 while the voltage is above ``threshold``.  A
:class:`Potentiometer` is the same circuit whose resistance is set by a
knob position that may change during the run.  The defaults are the
Propeller's 3.3 V and 1.65 V threshold; a BASIC Stamp is ``vdd=5,
threshold=1.4``.
"""
from __future__ import annotations

import math
from typing import Optional

from .part import ReactivePart, check_pin

__all__ = ["RcCircuit", "Potentiometer"]


class RcCircuit(ReactivePart):
    """An RC circuit (see the module docstring).

    Args:
        pin: its pin.
        r: the resistor from the capacitor to ``to`` (ohms).
        c: the capacitor (farads).
        to: ``"ground"`` or ``"vdd"``: where ``r`` goes (the rest level).
        series: the resistor between the pin and the capacitor (ohms).
        vdd: the supply (volts).
        threshold: the input threshold (volts; default half of ``vdd``).

    Attributes:
        decays: ``(release cycle, crossing cycle or None)`` each time the
            program let go of the pin (``None``: driven again before the
            voltage crossed the threshold).

    Raises:
        ValueError: for a bad pin or a value that is not positive.
    """

    kind = "rc"

    def __init__(self, *, pin: int, r: float = 10e3, c: float = 0.1e-6, to: str = "ground", series: float = 220.0,
                 vdd: float = 3.3, threshold: Optional[float] = None, name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        for what, v in (("r", r), ("c", c), ("vdd", vdd)):
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"{what} must be a number above 0, not {v!r}")
        if not (isinstance(series, (int, float)) and math.isfinite(series) and series >= 0):
            raise ValueError(f"series must be a number of ohms >= 0, not {series!r}")
        if to not in ("ground", "vdd"):
            raise ValueError(f"to must be 'ground' or 'vdd', not {to!r}")
        self.r, self.c, self.series, self.vdd = float(r), float(c), float(series), float(vdd)
        self.to = to
        self.threshold = vdd / 2 if threshold is None else float(threshold)
        if not 0 < self.threshold < vdd:
            raise ValueError(f"threshold must be between 0 and vdd ({vdd} V), not {threshold!r}")
        self.decays: list = []

    @property
    def name(self) -> str:
        return self._name or f"RC P{self.pin}"

    def driven_pins(self) -> tuple:
        return (self.pin,)

    def watched_pins(self) -> tuple:
        return (self.pin,)

    # ------------------------------------------------------------------ resistance over time
    def resistance_steps(self) -> list:
        """``(cycle, ohms)`` from each cycle on (a fixed resistor: one step)."""
        return [(0, self.r)]

    def _r_at(self, cycle: float) -> tuple:
        """The resistance at ``cycle`` and the cycle it next changes (or None)."""
        steps = self._steps
        r, nxt = steps[0][1], None
        for k, (c, ohms) in enumerate(steps):
            if c <= cycle:
                r = ohms
                nxt = steps[k + 1][0] if k + 1 < len(steps) else None
        return r, nxt

    # ------------------------------------------------------------------ the circuit
    def reset(self) -> None:
        self._steps = self.resistance_steps()
        rest = 0.0 if self.to == "ground" else self.vdd
        self.s = (0, rest, None)                # (since cycle, volts then, driven level or None)

    def initial_levels(self) -> int:
        return (1 << self.pin) if self.s[1] > self.threshold else 0

    def save(self):
        return self.s, len(self.decays)

    def restore(self, state) -> None:
        self.s, n = state
        del self.decays[n:]

    def _target(self, r: float, driven: Optional[int]) -> tuple:
        """(volts it moves towards, time constant in cycles)."""
        rest = 0.0 if self.to == "ground" else self.vdd
        if driven is None:
            return rest, r * self.c * self.clock_hz
        vd = self.vdd if driven else 0.0
        rs = self.series
        if rs == 0:
            return vd, 0.0
        return (vd * r + rest * rs) / (r + rs), self.c * rs * r / (r + rs) * self.clock_hz

    def volts_at(self, cycle: int) -> float:
        """The capacitor's voltage at ``cycle`` (for the drives worked through so far)."""
        since, v, driven = self.s
        return self._follow(since, v, driven, cycle)[0]

    def _follow(self, a: int, v: float, driven: Optional[int], b: int, stop_at: Optional[float] = None):
        """The voltage at ``b`` starting from ``v`` at ``a``; with ``stop_at``, the first cycle the voltage
        passes it instead (``(volts, cycle or None)``)."""
        t = a
        while True:
            r, nxt = self._r_at(t)
            end = b if nxt is None or nxt > b else nxt
            target, tau = self._target(r, driven)
            if stop_at is not None and (v - stop_at) * (target - stop_at) < 0:
                dt = 0.0 if tau == 0 else tau * math.log((v - target) / (stop_at - target))
                cross = t + math.floor(dt) + 1
                if cross <= end:
                    return stop_at, cross
            v = target if tau == 0 else target + (v - target) * math.exp(-(end - t) / tau)
            t = end
            if t >= b:
                return v, None

    def on_drive(self, cycle: int, d: int, o: int) -> None:
        bit = 1 << self.pin
        driven = ((o >> self.pin) & 1) if d & bit else None
        since, v, was = self.s
        v = self._follow(since, v, was, cycle)[0]
        if was is None and self.decays and self.decays[-1][1] is None:
            self._close_decay(since, cycle)
        self.s = (cycle, v, driven)
        if driven is None:
            self.decays.append((cycle, None))
        high = v > self.threshold
        self.output(cycle + 1, bit if high else 0)
        horizon = cycle + int(3600 * self.clock_hz)             # an hour: nothing slower is of interest
        _, cross = self._follow(cycle, v, driven, horizon, stop_at=self.threshold)
        if cross is not None:
            self.output(cross, 0 if high else bit)

    def _close_decay(self, release: int, until: int) -> None:
        _, v, _ = self.s
        _, cross = self._follow(release, v, None, until, stop_at=self.threshold)
        self.decays[-1] = (release, cross)

    def finish(self, end_cycle: int) -> None:
        super().finish(end_cycle)
        since, v, driven = self.s
        if driven is None and self.decays and self.decays[-1][1] is None:
            self._close_decay(since, end_cycle)

    # ------------------------------------------------------------------ reports
    def decay_seconds(self) -> list:
        """The measured decays: seconds from release to the threshold crossing."""
        return [(c - r) / self.clock_hz for r, c in self.decays if c is not None]

    def summary(self) -> str:
        times = self.decay_seconds()
        n = len(self.decays)
        last = f", the last {times[-1] * 1e6:.1f} us to the threshold" if times else ""
        return f"{self.name} ({_ohms(self.r)}, {_farads(self.c)}): released {n} time{'s' if n != 1 else ''}{last}"

    def view(self) -> str:
        since, v, driven = self.s
        state = "driven" if driven is not None else "free"
        return f"{v:5.2f} V ({state})"


class Potentiometer(RcCircuit):
    """A potentiometer read as an RC circuit: ``r = r_min + position * r_max``.

    Args:
        position: the knob, 0.0-1.0, or ``[(seconds, position), ...]`` (it
            turns at those times); the rest as :class:`RcCircuit`
            (``r_max`` instead of ``r``).

    Raises:
        ValueError: for a position outside 0-1 or times not in order.
    """

    kind = "pot"

    def __init__(self, *, pin: int, r_max: float = 10e3, r_min: float = 0.0, position=0.5, c: float = 0.1e-6,
                 to: str = "ground", series: float = 220.0, vdd: float = 3.3, threshold: Optional[float] = None,
                 name: Optional[str] = None):
        steps = list(position) if isinstance(position, (list, tuple)) else [(0.0, position)]
        times = [float(t) for t, _ in steps]
        if times != sorted(times) or any(not 0.0 <= float(p) <= 1.0 for _, p in steps):
            raise ValueError("position must be 0.0-1.0, or (seconds, position) pairs in time order")
        self.positions = [(float(t), float(p)) for t, p in steps]
        self.r_max, self.r_min = float(r_max), float(r_min)
        first = self.positions[0][1] if self.positions[0][0] == 0 else 0.5
        super().__init__(pin=pin, r=max(1.0, r_min + first * r_max), c=c, to=to, series=series, vdd=vdd,
                         threshold=threshold, name=name)

    @property
    def name(self) -> str:
        return self._name or f"pot P{self.pin}"

    def resistance_steps(self) -> list:
        steps = [(0, self.r)]
        for t, p in self.positions:
            c = int(round(t * self.clock_hz))
            ohms = max(1.0, self.r_min + p * self.r_max)
            if c == 0:
                steps[0] = (0, ohms)
            else:
                steps.append((c, ohms))
        return steps

    def summary(self) -> str:
        return super().summary().replace(f"({_ohms(self.r)}, ", f"({_ohms(self.r_max)} pot, ", 1)


def _ohms(r: float) -> str:
    return f"{r / 1e6:g} MΩ" if r >= 1e6 else f"{r / 1e3:g} kΩ" if r >= 1e3 else f"{r:g} Ω"


def _farads(c: float) -> str:
    for unit, f in (("µF", 1e-6), ("nF", 1e-9), ("pF", 1e-12)):
        if c >= f:
            return f"{c / f:g} {unit}"
    return f"{c:g} F"
