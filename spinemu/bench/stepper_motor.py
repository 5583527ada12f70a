"""A stepper motor on the pins: shaft position, speed and acceleration over time.

The motor hangs on one of two kinds of drive:

* **four coil pins** (a bipolar motor behind an L293D, a unipolar one behind a
  ULN2003).  The *pattern* is the 4-bit value ``bit i = level of coils[i]``;
  patterns sit on the 8 positions of the half-step cycle (:data:`PHASE`)::

      0001 0011 0010 0110 0100 1100 1000 1001
       0    1    2    3    4    5    6    7

  A move of +2 positions is a forward full step (two-coil ``0011 -> 0110`` or
  wave ``0001 -> 0010``), +1 a forward half step, negative moves go backward.
  A move of 4 (the opposite pattern) or a pattern off the cycle (``0000``,
  ``0101``) is not a step: the rotor's way is undecided, it is counted in
  :attr:`Motion.irregular` and the shaft does not move.  The first pattern after
  the coils were off (or undriven) only energises the motor.  Positions are in
  full steps (a half step is 0.5).
* **a step/direction driver** (A4988, DRV8825, TB6600): a high pulse on STEP
  at least ``min_pulse`` seconds wide moves one step, forward when DIR is high
  at the rising edge (an undriven pin reads low).  Shorter pulses are counted
  in :attr:`Motion.glitches`; a DIR change less than ``dir_setup`` seconds
  before a rising edge in :attr:`Motion.dir_setup_violations`.  With an enable
  pin, pulses while the driver is disabled are not steps (:attr:`Motion.ignored`).
  Positions are in steps of the driver.

The mechanics are a counting model, not a magnetic one.  The shaft moves at the
instant of the step.  Each step has a *rate*: its move divided by the time since
the previous step (0 for the first).  Without a pull-in limit every step is
followed.  With ``pull_in`` (steps/s, the datasheet's pull-in rate: the fastest
stepping a motor at rest follows at once) a step is missed when its rate is above
the limit and either exceeds the rate the rotor is running at by more than the
limit, or reverses it.  A missed step leaves the shaft where it was and stalls the
rotor (its rate drops to 0): a motor whose step rate jumps too far stays stalled
until the rate falls back under the limit, as real ones do.  Slowing down is
always followed.  A stalled motor on coil pins can only lose whole electrical
cycles (4 full steps); this model counts the steps it missed instead.

The part consumes pin changes in time order (:meth:`StepperMotor.on_pins`, the
interface a live bench drives), or a recorded trace (:meth:`StepperMotor.feed`,
:func:`motor_from_trace`).  It imports nothing from the engines.

>>> from spinemu.trace import PinTrace
>>> t = PinTrace(1_000_000, [(0, 3, 2), (1000, 3, 3), (1010, 3, 2), (3000, 3, 3), (3010, 3, 2)], 4000)
>>> m = motor_from_trace(t, step=0, dir=1)
>>> m.position, [round(s.time, 3) for s in m.steps], m.speed_at(0.002)
(2.0, [0.001, 0.003], 500.0)
"""
from __future__ import annotations

import bisect
from dataclasses import dataclass, field
from typing import Iterable, Optional, Sequence

__all__ = ["PHASE", "coil_delta", "MotorStep", "Motion", "StepperMotor", "motor_from_trace"]

#: Position of each coil pattern on the 8-step half-step cycle.
PHASE = {0b0001: 0, 0b0011: 1, 0b0010: 2, 0b0110: 3, 0b0100: 4, 0b1100: 5, 0b1000: 6, 0b1001: 7}


def coil_delta(previous: Optional[int], pattern: Optional[int]) -> Optional[int]:
    """Half steps moved from one coil pattern to the next (+2 = one forward full step).

    None when it is not a step: either pattern off the half-step cycle (or None),
    or the opposite pattern (4 half steps, direction undecided).

    >>> coil_delta(0b0011, 0b0110), coil_delta(0b0011, 0b1001), coil_delta(0b0001, 0b0011)
    (2, -2, 1)
    >>> coil_delta(0b0011, 0b1100) is None, coil_delta(None, 0b0011) is None
    (True, True)
    """
    if previous not in PHASE or pattern not in PHASE:
        return None
    d = (PHASE[pattern] - PHASE[previous]) % 8
    if d == 4:
        return None
    return d - 8 if d > 4 else d


@dataclass(frozen=True)
class MotorStep:
    """One step the drive asked for.

    Attributes:
        cycle: when (the rising edge of STEP, or the new coil pattern), in trace cycles.
        time: the same in seconds.
        delta: the move asked for (+1 a forward step; coils: full steps, so half steps are 0.5).
        rate: delta divided by the time since the previous step asked for (steps/s; 0 for the first).
        followed: False if the motor missed it (see the module docstring).
        position: the shaft's position after it.
        commanded: where the drive has asked the shaft to be, after it.
    """

    cycle: int
    time: float
    delta: float
    rate: float
    followed: bool
    position: float
    commanded: float


@dataclass
class Motion:
    """What the shaft did: every step asked for, followed or missed.

    Attributes:
        clock_hz: cycles per second of the trace.
        steps: the steps asked for, in time order.
        unit: ``"full steps"`` (coil drive) or ``"steps"`` (step/dir driver).
        irregular: coil changes that were not steps (opposite or off-cycle patterns).
        glitches: STEP pulses narrower than the driver's minimum.
        ignored: STEP pulses while the driver was disabled.
        dir_setup_violations: DIR changed too close before a STEP rising edge.
    """

    clock_hz: int
    steps: list = field(default_factory=list)
    unit: str = "steps"
    irregular: int = 0
    glitches: int = 0
    ignored: int = 0
    dir_setup_violations: int = 0

    # ----------------------------------------------------------------- positions
    @property
    def position(self) -> float:
        """The shaft's position at the end."""
        return self.steps[-1].position if self.steps else 0.0

    @property
    def commanded(self) -> float:
        """Where the drive asked the shaft to be at the end."""
        return self.steps[-1].commanded if self.steps else 0.0

    @property
    def missed(self) -> list:
        """The steps the motor did not follow."""
        return [s for s in self.steps if not s.followed]

    def _moves(self) -> list:
        return [s for s in self.steps if s.followed]

    def position_at(self, time: float) -> float:
        """The shaft's position at ``time`` (seconds): after every step up to and including it."""
        i = bisect.bisect_right([s.time for s in self.steps], time)
        return self.steps[i - 1].position if i else 0.0

    def commanded_at(self, time: float) -> float:
        """Where the drive had asked the shaft to be at ``time``."""
        i = bisect.bisect_right([s.time for s in self.steps], time)
        return self.steps[i - 1].commanded if i else 0.0

    # ----------------------------------------------------------------- speed
    def speed_at(self, time: float) -> float:
        """The shaft's speed at ``time``: the move of the next step over the interval that contains ``time``.

        This is the speed AccelStepper reports between two steps (the one it
        computed for the coming interval).  0 before the first move and after
        the last.
        """
        moves = self._moves()
        i = bisect.bisect_right([s.time for s in moves], time)
        if i == 0 or i >= len(moves):
            return 0.0
        return moves[i].delta / (moves[i].time - moves[i - 1].time)

    def speeds(self, rest_after: Optional[float] = None) -> list:
        """The speed of each interval between two moves of the shaft: ``(start, end, steps/s)``.

        Args:
            rest_after: an interval longer than this (seconds) is a standstill: speed 0.
        """
        moves = self._moves()
        out = []
        for a, b in zip(moves, moves[1:]):
            dt = b.time - a.time
            v = 0.0 if (rest_after is not None and dt > rest_after) or dt <= 0 else b.delta / dt
            out.append((a.time, b.time, v))
        return out

    def accelerations(self, rest_after: Optional[float] = None) -> list:
        """``(time, steps/s^2)`` at each move between two intervals: the change of speed over the
        time between the intervals' midpoints."""
        sp = self.speeds(rest_after)
        out = []
        for (a0, a1, va), (b0, b1, vb) in zip(sp, sp[1:]):
            dt = (b0 + b1) / 2 - (a0 + a1) / 2
            if dt > 0:
                out.append((a1, (vb - va) / dt))
        return out

    def top_speed(self) -> float:
        """The largest speed (magnitude) of any interval."""
        return max((abs(v) for _, _, v in self.speeds()), default=0.0)

    def summary(self) -> str:
        """A few lines for reports."""
        moves = self._moves()
        span = f"{moves[0].time:.6f}-{moves[-1].time:.6f} s" if moves else "no moves"
        lines = [f"motor: {len(self.steps)} steps asked for, {len(self.missed)} missed; "
                 f"shaft at {self.position:+g} {self.unit} ({span})",
                 f"  top speed {self.top_speed():.2f} {self.unit}/s"]
        if self.missed:
            first = self.missed[0]
            lines.append(f"  first missed step at {first.time:.6f} s (rate {first.rate:.1f}/s); "
                         f"the drive asked for {self.commanded:+g}")
        for name, n in (("irregular coil changes", self.irregular), ("STEP pulses too short", self.glitches),
                        ("STEP pulses while disabled", self.ignored),
                        ("DIR changes too close to STEP", self.dir_setup_violations)):
            if n:
                lines.append(f"  {name}: {n}")
        return "\n".join(lines)


class StepperMotor:
    """A stepper motor part: give it the pin changes, read its :class:`Motion`.

    Args:
        coils: four coil pins in table order (pattern bit i = coils[i]); or
        step, dir: the step and direction pins of a driver;
        enable: the driver's enable pin (coils are off, pulses ignored, while it is not at ``enable_level``).
        enable_level: the level that enables (1: the L293D's EN; 0: the A4988's ~EN).
        clock_hz: cycles per second of the pin changes.
        pull_in: pull-in rate in steps/s (None: the motor follows every step).
        min_pulse: shortest STEP pulse the driver takes (seconds).
        dir_setup: how long DIR must be steady before a STEP rising edge (seconds).

    Raises:
        ValueError: for a drive that is neither four coil pins nor a step and a dir pin.
    """

    def __init__(self, *, coils: Optional[Sequence[int]] = None, step: Optional[int] = None,
                 dir: Optional[int] = None, enable: Optional[int] = None, enable_level: int = 1,
                 clock_hz: int = 80_000_000, pull_in: Optional[float] = None,
                 min_pulse: float = 1e-6, dir_setup: float = 200e-9):
        if (coils is None) == (step is None):
            raise ValueError("a stepper motor needs either four coil pins or a step and a dir pin")
        if coils is not None and len(coils) != 4:
            raise ValueError("a stepper motor needs four coil pins")
        if step is not None and dir is None:
            raise ValueError("a step/dir driver needs a dir pin")
        if pull_in is not None and pull_in <= 0:
            raise ValueError("the pull-in rate must be above 0 steps/s")
        self.coils = tuple(coils) if coils is not None else None
        self.step_pin, self.dir_pin, self.enable_pin = step, dir, enable
        self.enable_level = 1 if enable_level else 0
        self.clock_hz = clock_hz
        self.pull_in = pull_in
        self._min_pulse = int(round(min_pulse * clock_hz))
        self._dir_setup = int(round(dir_setup * clock_hz))
        self.motion = Motion(clock_hz, unit="full steps" if coils is not None else "steps")
        self._pending: Optional[tuple] = None
        self._pattern: Optional[int] = None
        self._step_high = False
        self._rise: Optional[tuple] = None       # (cycle, forward, enabled) of a pulse in progress
        self._dir_level: Optional[int] = None
        self._dir_changed = -(1 << 62)
        self._last_time: Optional[float] = None
        self._rotor_rate = 0.0
        self._position = 0.0
        self._commanded = 0.0

    # ----------------------------------------------------------------- input
    def on_pins(self, cycle: int, dir_mask: int, out_mask: int) -> None:
        """The pins are ``(dir_mask, out_mask)`` from ``cycle`` on (calls in time order).

        Several states at one cycle count as the last of them: a rotor does not
        see a pattern that lasts no time.
        """
        pending = self._pending
        if pending is not None and pending[0] != cycle:
            self._apply(*pending)
        self._pending = (cycle, dir_mask, out_mask)

    def finish(self, end_cycle: Optional[int] = None) -> Motion:
        """No more changes: settle the last state (a STEP pulse still high at ``end_cycle`` counts if wide enough)."""
        if self._pending is not None:
            self._apply(*self._pending)
            self._pending = None
        if self._rise is not None and end_cycle is not None and end_cycle - self._rise[0] >= self._min_pulse:
            self._pulse(*self._rise)
            self._rise = None
        return self.motion

    def feed(self, changes: Iterable, end_cycle: Optional[int] = None) -> Motion:
        """Every ``(cycle, dir_mask, out_mask)`` of a trace, then :meth:`finish`."""
        for cycle, d, o in changes:
            self.on_pins(cycle, d, o)
        return self.finish(end_cycle)

    # ----------------------------------------------------------------- drives
    def _level(self, pin: int, d: int, o: int) -> int:
        return (d & o) >> pin & 1            # undriven reads low

    def _enabled(self, d: int, o: int) -> bool:
        return self.enable_pin is None or self._level(self.enable_pin, d, o) == self.enable_level

    def _apply(self, cycle: int, d: int, o: int) -> None:
        if self.coils is not None:
            self._apply_coils(cycle, d, o)
        else:
            self._apply_step_dir(cycle, d, o)

    def _apply_coils(self, cycle: int, d: int, o: int) -> None:
        mask = sum(1 << p for p in self.coils)
        if (d & mask) != mask or not self._enabled(d, o):
            pattern = None
        else:
            pattern = sum((o >> p & 1) << i for i, p in enumerate(self.coils))
            if pattern == 0:
                pattern = None                # all coils off: the rotor is free
        previous = self._pattern
        if pattern == previous:
            return
        self._pattern = pattern
        if pattern is None or previous is None:
            return                            # off, or energising: no step
        delta = coil_delta(previous, pattern)
        if delta is None:
            self.motion.irregular += 1
            return
        self._command(cycle, delta / 2)

    def _apply_step_dir(self, cycle: int, d: int, o: int) -> None:
        level = self._level(self.dir_pin, d, o)
        if level != self._dir_level:
            if self._dir_level is not None:
                self._dir_changed = cycle
            self._dir_level = level
        high = bool(self._level(self.step_pin, d, o))
        if high and not self._step_high:
            if cycle - self._dir_changed < self._dir_setup:
                self.motion.dir_setup_violations += 1
            self._rise = (cycle, level == 1, self._enabled(d, o))
        elif not high and self._step_high and self._rise is not None:
            if cycle - self._rise[0] >= self._min_pulse:
                self._pulse(*self._rise)
            else:
                self.motion.glitches += 1
            self._rise = None
        self._step_high = high

    def _pulse(self, cycle: int, forward: bool, enabled: bool) -> None:
        if enabled:
            self._command(cycle, 1.0 if forward else -1.0)
        else:
            self.motion.ignored += 1

    # ----------------------------------------------------------------- mechanics
    def _command(self, cycle: int, delta: float) -> None:
        t = cycle / self.clock_hz
        last = self._last_time
        rate = 0.0 if last is None or t <= last else delta / (t - last)
        self._last_time = t
        v, limit = self._rotor_rate, self.pull_in
        followed = (limit is None or abs(rate) <= limit
                    or (rate * v > 0 and abs(rate) - abs(v) <= limit))
        self._commanded += delta
        if followed:
            self._position += delta
            self._rotor_rate = rate
        else:
            self._rotor_rate = 0.0            # stalled
        self.motion.steps.append(MotorStep(cycle, t, delta, rate, followed, self._position, self._commanded))


def motor_from_trace(trace, **options) -> Motion:
    """Run a recorded :class:`~spinemu.trace.PinTrace` through a :class:`StepperMotor`.

    Args:
        trace: the trace (its clock is used).
        options: the drive and the motor, as for :class:`StepperMotor`
            (``coils=[1, 2, 3, 4]`` or ``step=0, dir=1``; ``pull_in=...``).

    Returns:
        The :class:`Motion`.
    """
    motor = StepperMotor(clock_hz=trace.clock_hz, **options)
    return motor.feed(trace.changes, trace.end_cycle)
