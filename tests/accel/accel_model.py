"""AccelStepper's way of moving a motor, in floating point: the reference for AccelStepper.spin.

Written from "AccelStepper: the missing manual" (run() = runSpeed() then, after a
step, computeNewSpeed(); stop() = move to the point where the motor comes to rest)
and D. Austin's equations (Embedded Systems Programming, Jan 2005): the interval
before step n+1 is c(n+1) = c(n) - 2 c(n) / (4 n + 1), c0 = 0.676 sqrt(2 / a), never
below 1 / maxSpeed; deceleration starts when speed^2 / (2 a) steps are left.

Time is continuous (seconds) and every step is made exactly when it is due, which is
what the Spin object does on the Propeller (it waits for the step's clock tick): a
motor at rest that is given a target makes its first step c0 after that call, and each
later step one interval after the previous one.
"""
from __future__ import annotations

import math


class AccelModel:
    """One motor: positions in steps, time in seconds."""

    def __init__(self, max_speed: float = 1.0, acceleration: float = 1.0):
        self.pos = 0
        self.target = 0
        self.speed = 0.0
        self.n = 0
        self.cn = 0.0
        self.interval = 0.0
        self.forward = False
        self.last = 0.0
        self.now = 0.0
        self.max_speed = 0.0
        self.acceleration = 0.0
        self.c0 = 0.0
        self.cmin = 1.0
        self.steps: list[tuple[float, int]] = []      # (time, position after the step)
        self.set_max_speed(max_speed)
        self.set_acceleration(acceleration)

    # ------------------------------------------------------------------ setup
    def set_max_speed(self, v: float) -> None:
        v = abs(v)
        if v != self.max_speed:
            self.max_speed = v
            self.cmin = 1.0 / v
            if self.n > 0:
                self.n = self.steps_to_stop()
                self.compute_new_speed()

    def set_acceleration(self, a: float) -> None:
        a = abs(a)
        if a and a != self.acceleration:
            if self.acceleration:
                self.n = int(self.n * (self.acceleration / a))
            self.acceleration = a
            self.c0 = 0.676 * math.sqrt(2.0 / a)
            self.compute_new_speed()

    def move_to(self, position: int) -> None:
        if position != self.target:
            self.target = position
            self.compute_new_speed()

    def move(self, relative: int) -> None:
        self.move_to(self.pos + relative)

    def stop(self) -> None:
        if self.speed:
            s = self.steps_to_stop() + 1
            self.move(s if self.speed > 0 else -s)

    def steps_to_stop(self) -> int:
        return int(self.speed * self.speed / (2.0 * self.acceleration))

    # ------------------------------------------------------------------ the algorithm
    def compute_new_speed(self) -> None:
        distance = self.target - self.pos
        to_stop = self.steps_to_stop()
        if distance == 0 and to_stop <= 1:
            self.interval = self.speed = 0.0
            self.n = 0
            return
        if distance > 0:
            if self.n > 0 and (to_stop >= distance or not self.forward):
                self.n = -to_stop
            elif self.n < 0 and to_stop < distance and self.forward:
                self.n = -self.n
        elif distance < 0:
            if self.n > 0 and (to_stop >= -distance or self.forward):
                self.n = -to_stop
            elif self.n < 0 and to_stop < -distance and not self.forward:
                self.n = -self.n
        if self.n == 0:
            self.cn = self.c0
            self.forward = distance > 0
        else:
            self.cn = max(self.cn - 2.0 * self.cn / (4.0 * self.n + 1), self.cmin)
        self.n += 1
        if self.interval == 0:
            self.last = self.now
        self.interval = self.cn
        self.speed = (1.0 if self.forward else -1.0) / self.cn

    # ------------------------------------------------------------------ running
    def run_until(self, t_end: float) -> None:
        """Call run() continually until ``t_end`` (or until the motor stands still at its target)."""
        while self.interval and self.last + self.interval <= t_end:
            self.now = self.last + self.interval
            self.last = self.now
            self.pos += 1 if self.forward else -1
            self.steps.append((self.now, self.pos))
            self.compute_new_speed()
        self.now = max(self.now, t_end)

    def run_to_position(self) -> None:
        while self.interval:
            self.run_until(self.last + self.interval)

    def intervals(self) -> list[float]:
        return [b[0] - a[0] for a, b in zip(self.steps, self.steps[1:])]
