"""A stepper motor with its driver on the pins: the steps the program made, run by run, and where the shaft went.

:class:`Stepper` is the bench's part for the stepper motor model
(:class:`spinemu.bench.stepper_motor.StepperMotor`): four coil pins in the
drive table's order (an L293D or a ULN2003 in front of the motor), or the
STEP and DIR pins of a driver (A4988, DRV8825), with an optional enable pin.
The motor model is fed the pins as the run goes and gives the shaft's
position, and, with a pull-in rate, the steps it missed.  At the end the
steps are also split into *runs* by the stepper decoder
(:mod:`spinemu.analysis.stepper`, as ``spinemu trace steps`` does): the
stretches of steps in one direction at one speed between pauses, so a demo
that turns one revolution forward and one back five times shows ten runs of
its step count.
"""
from __future__ import annotations

from typing import Optional, Sequence

from ..trace import PinTrace
from .part import Part, check_pin
from .stepper_motor import StepperMotor

__all__ = ["Stepper"]


class Stepper(Part):
    """A stepper motor on coil pins or on a step/dir driver (see the module docstring).

    Args:
        coils: the four coil pins, in table order; or
        step, dir: the driver's STEP and DIR pins.
        enable: the driver's enable pin (``None``: always enabled).
        enable_level: the level that enables (1: an L293D's EN; 0: an A4988's ~EN).
        pull_in: the motor's pull-in rate in steps/s (``None``: it follows every step).
        min_pulse, dir_setup: the step/dir driver's shortest STEP pulse and DIR set-up time (seconds).

    Attributes:
        motion: the motor model's :class:`~spinemu.bench.stepper_motor.Motion` (after the run).

    Raises:
        ValueError: for a bad pin, not four coil pins, or neither coils nor step and dir.
    """

    kind = "stepper"
    pin_parameters = ("coils", "step", "dir", "enable")

    def __init__(self, *, coils: Optional[Sequence[int]] = None, step: Optional[int] = None,
                 dir: Optional[int] = None, enable: Optional[int] = None, enable_level: int = 1,
                 pull_in: Optional[float] = None, min_pulse: float = 1e-6, dir_setup: float = 200e-9,
                 name: Optional[str] = None):
        super().__init__(name=name)
        if (coils is None) == (step is None):
            raise ValueError("a stepper needs either four coil pins (coils) or a step and a dir pin")
        if coils is not None:
            self.coils = tuple(check_pin(p, "coil pin") for p in coils)
            if len(self.coils) != 4 or len(set(self.coils)) != 4:
                raise ValueError(f"a stepper needs four different coil pins, not {list(coils)}")
            self.step_pin = self.dir_pin = None
        else:
            if dir is None:
                raise ValueError("a step/dir driver needs a dir pin")
            self.coils = None
            self.step_pin, self.dir_pin = check_pin(step, "step"), check_pin(dir, "dir")
        self.enable = None if enable is None else check_pin(enable, "enable")
        if pull_in is not None and pull_in <= 0:
            raise ValueError("pull_in must be above 0 steps/s")
        self._options = dict(coils=self.coils, step=self.step_pin, dir=self.dir_pin, enable=self.enable,
                             enable_level=enable_level, pull_in=pull_in, min_pulse=min_pulse, dir_setup=dir_setup)
        self._mask = sum(1 << p for p in self.watched_pins())
        self._changes: list = [(0, 0, 0)]
        self.motor: Optional[StepperMotor] = None
        self.motion = None
        self._steps = None

    @property
    def name(self) -> str:
        if self._name:
            return self._name
        if self.coils is not None:
            return f"stepper P{min(self.coils)}-P{max(self.coils)}"
        return f"stepper P{self.step_pin}/P{self.dir_pin}"

    def watched_pins(self) -> tuple:
        pins = self.coils if self.coils is not None else (self.step_pin, self.dir_pin)
        return pins + ((self.enable,) if self.enable is not None else ())

    def connect(self, port) -> None:
        super().connect(port)
        self.motor = StepperMotor(clock_hz=port.clock_hz, **self._options)

    def on_pins(self, changes, upto, present) -> None:
        mask = self._mask
        last = self._changes[-1]
        motor = self.motor
        for c, d, o in changes:
            d, o = d & mask, o & mask
            if (d, o) != last[1:]:
                last = (c, d, o)
                self._changes.append(last)
                motor.on_pins(c, d, o)
        self._steps = None

    def finish(self, end_cycle: int) -> None:
        self.motion = self.motor.finish(end_cycle)

    def steps(self):
        """The decoded steps (:class:`spinemu.analysis.stepper.StepSequence`; coils: with the enable pin low
        the coils count as off)."""
        if self._steps is None:
            from ..analysis.stepper import decode_step_dir, decode_steps
            changes = self._changes
            if self.enable is not None and self.coils is not None:
                bit = 1 << self.enable
                changes = [(c, d if d & o & bit else 0, o if d & o & bit else 0) for c, d, o in changes]
            trace = PinTrace(self.clock_hz, list(changes), changes[-1][0])
            if self.coils is not None:
                self._steps = decode_steps(trace, list(self.coils))
            else:
                self._steps = decode_step_dir(trace, self.step_pin, self.dir_pin)
        return self._steps

    def runs(self) -> list[int]:
        """Signed step counts of the runs (positive forward)."""
        return [(-1 if seg.direction == -1 else 1) * seg.count for seg in self.steps().segments()]

    def summary(self) -> str:
        seq = self.steps()
        if not len(seq):
            return f"{self.name}: no steps"
        runs = self.runs()
        shown = " ".join(f"{r:+d}" for r in runs[:12]) + (f" ... ({len(runs)} runs)" if len(runs) > 12 else "")
        text = f"{self.name}: {len(seq)} steps ({seq.mode}); steps per run: {shown}"
        m = self.motion
        if m is not None:
            text += f"; shaft at {m.position:+g} {m.unit}"
            if m.missed:
                text += (f", {len(m.missed)} steps missed (the first at {m.missed[0].time:.6f} s, "
                         f"{m.missed[0].rate:.0f} steps/s)")
        return text

    def view(self) -> str:
        if self.motor is None:
            return ""
        position = self.motor.motion.position
        return f"{len(self.motor.motion.steps)} steps, shaft at {position:+g}"
