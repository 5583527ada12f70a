"""A hobby servo on a pin: pulse widths to a shaft angle, at the speed a real servo turns.

A hobby servo reads a high pulse about every 20 ms; the width sets the
angle it turns to: ``pulse_range`` (default 1.0-2.0 ms) maps to
``angle_range`` (default 0-180 degrees), linearly, and wider or narrower
pulses inside ``limits`` push it to the end of its range.  A pulse outside
``limits`` (default 0.5-2.5 ms) is a protocol violation: the servo ignores
it and the part reports it at its cycle.  The shaft does not jump: it turns
towards the latest angle asked at ``speed`` degrees per second (default
60 degrees in 0.19 s, a standard servo's datasheet figure at 4.8 V).  It
starts at ``start_angle``.
"""
from __future__ import annotations

from typing import Optional

from .part import Part, check_pin
from .pwm import Pulse, PulseDecoder

__all__ = ["Servo"]


class Servo(Part):
    """A hobby servo (see the module docstring).

    Args:
        pin: its signal pin.
        pulse_range: the pulse widths (seconds) of the two ends of ``angle_range``.
        angle_range: the angles (degrees) those widths turn it to.
        limits: the narrowest and widest pulse it accepts (seconds).
        speed: degrees per second it turns.
        start_angle: its angle before the first pulse.

    Attributes:
        pulses: every pulse seen (:class:`~spinemu.bench.pwm.Pulse`, cycles).
        moves: ``(cycle, angle there, target)`` each time a pulse set a new target.

    Raises:
        ValueError: for a bad pin or ranges.
    """

    kind = "servo"

    def __init__(self, *, pin: int, pulse_range=(1.0e-3, 2.0e-3), angle_range=(0.0, 180.0),
                 limits=(0.5e-3, 2.5e-3), speed: float = 60 / 0.19, start_angle: Optional[float] = None,
                 name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        self.pulse_range = tuple(float(x) for x in pulse_range)
        self.angle_range = tuple(float(x) for x in angle_range)
        self.limits = tuple(float(x) for x in limits)
        if not (0 < self.pulse_range[0] < self.pulse_range[1]) or not (0 < self.limits[0] < self.limits[1]):
            raise ValueError("pulse_range and limits must be two increasing widths in seconds")
        if speed <= 0:
            raise ValueError("speed must be above 0 degrees per second")
        self.speed = float(speed)
        a0, a1 = self.angle_range
        self.start_angle = (a0 + a1) / 2 if start_angle is None else float(start_angle)
        self.pulses: list[Pulse] = []
        self.moves: list = []
        self.ignored = 0
        self._level = 0
        self.now = 0

    @property
    def name(self) -> str:
        return self._name or f"servo P{self.pin}"

    def watched_pins(self) -> tuple:
        return (self.pin,)

    def connect(self, port) -> None:
        super().connect(port)
        self._decoder = PulseDecoder(1, on_pulse=self._pulse)

    def angle_for(self, width_seconds: float) -> float:
        """The angle a pulse of this width asks for (clamped to the range)."""
        (w0, w1), (a0, a1) = self.pulse_range, self.angle_range
        f = min(1.0, max(0.0, (width_seconds - w0) / (w1 - w0)))
        return a0 + f * (a1 - a0)

    def on_pins(self, changes, upto, present) -> None:
        pin = self.pin
        for c, d, o in changes:
            level = (o >> pin) & 1 if (d >> pin) & 1 else 0
            if level != self._level:
                self._level = level
                self._decoder.feed(c, level)
        if upto < 1 << 62:
            self.now = max(self.now, upto)

    def finish(self, end_cycle: int) -> None:
        self.now = end_cycle
        self.pulses = list(self._decoder.pulses)

    def _pulse(self, p: Pulse) -> None:
        w = p.width / self.clock_hz
        lo, hi = self.limits
        if not lo <= w <= hi:
            self.ignored += 1
            self.warn(p.start, f"pulse of {w * 1e3:.3f} ms is outside the servo's {lo * 1e3:g}-{hi * 1e3:g} ms: ignored")
            return
        target = self.angle_for(w)
        here = self.angle_at_cycle(p.end)
        if not self.moves or self.moves[-1][2] != target:
            self.moves.append((p.end, here, target))

    def angle_at_cycle(self, cycle: float) -> float:
        """The shaft's angle at ``cycle``."""
        angle, since, target = self.start_angle, 0, self.start_angle
        for c, a, t in self.moves:
            if c > cycle:
                break
            angle, since, target = a, c, t
        dt = (cycle - since) / self.clock_hz
        step = self.speed * dt
        if abs(target - angle) <= step:
            return target
        return angle + step if target > angle else angle - step

    def angle_at(self, seconds: float) -> float:
        """The shaft's angle at ``seconds`` of the run."""
        return self.angle_at_cycle(seconds * self.clock_hz)

    @property
    def angle(self) -> float:
        """The angle now (at the end, after the run)."""
        return self.angle_at_cycle(self.now)

    @property
    def target(self) -> float:
        return self.moves[-1][2] if self.moves else self.start_angle

    def summary(self) -> str:
        pulses = self._decoder.pulses if self.port else []
        if not pulses:
            return f"{self.name}: no pulses, at {self.angle:.1f}°"
        widths = [p.width / self.clock_hz * 1e3 for p in pulses]
        bad = f", {self.ignored} out of range" if self.ignored else ""
        return (f"{self.name}: {len(pulses)} pulses {min(widths):.3f}-{max(widths):.3f} ms{bad}; "
                f"at {self.angle:.1f}° (asked {self.target:.1f}°)")

    def view(self) -> str:
        a0, a1 = self.angle_range
        f = (self.angle - a0) / (a1 - a0) if a1 != a0 else 0
        pos = int(round(f * 20))
        return "[" + "-" * pos + "|" + "-" * (20 - pos) + f"] {self.angle:6.1f}°"
