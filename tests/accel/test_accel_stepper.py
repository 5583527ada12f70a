"""AccelStepper.spin on the emulator, judged from its pin trace by the bench's motor model.

The manual's table ("AccelStepper: the missing manual", maxSpeed 200, acceleration 50),
stop() and retargeting come out of spin_src/accel/accel_demo.spin; every step of it, and of
generated programs with other speeds, accelerations and units, is checked against a
floating-point model of AccelStepper's algorithm (tests/accel/accel_model.py).  The
reference simulator's run of the demo's first 6.5 s (tests/data/accel/accel_demo.trace.gz)
is the same trace to the cycle.
"""
from __future__ import annotations

import gzip
import math
from pathlib import Path
from types import SimpleNamespace

import pytest

from spinemu import Chip, compile_spin
from spinemu.analysis.compare import compare_traces
from spinemu.bench.stepper_motor import motor_from_trace
from spinemu.trace import read_log
from tests.accel.accel_model import AccelModel

ROOT = Path(__file__).resolve().parents[2]
ACCEL = ROOT / "spin_src" / "accel"
DATA = ROOT / "tests" / "data" / "accel"
HZ = 80_000_000

#: second -> (speed in whole steps/s, steps moved), the manual's table.
MANUAL_TABLE = {1: (53, 28), 2: (103, 106), 3: (153, 235), 4: (200, 413), 5: (200, 613), 6: (200, 813)}


def run_program(path, seconds: float = 60.0):
    prog = compile_spin(path, [ACCEL])
    result = Chip(prog.binary).run(max_cycles=int(seconds * HZ))
    assert result.reason == "all cogs stopped"
    return prog, result


def relative_errors(motion, model, skip=()):
    """Step interval by step interval: |emulated - model| / model."""
    got = [b.time - a.time for a, b in zip(motion.steps, motion.steps[1:])]
    want = model.intervals()
    assert len(got) == len(want)
    return [abs(g - w) / w for i, (g, w) in enumerate(zip(got, want)) if i not in skip]


@pytest.fixture(scope="module")
def demo():
    prog, result = run_program(ACCEL / "accel_demo.spin")
    motion = motor_from_trace(result.trace, step=0, dir=1, min_pulse=2e-6, dir_setup=0.1)
    trigger = next(c for c, v in result.trace.pin_levels(16) if v == "1") / HZ
    return SimpleNamespace(prog=prog, result=result, motion=motion, t0=trigger)


@pytest.fixture(scope="module")
def demo_model():
    """The demo's moves on the floating-point model, time 0 = the first moveTo."""
    m = AccelModel(200, 50)
    m.move_to(1_000_000)
    m.run_until(7.0)
    m.stop()
    m.run_to_position()
    m.move_to(0)
    while m.pos > 600:
        m.run_until(m.last + m.interval)
    m.move_to(1_500)
    m.run_to_position()
    return m


def test_the_demos_compile_to_openspins_images():
    for name in ("accel_demo", "coils_demo"):
        assert compile_spin(ACCEL / f"{name}.spin").binary == (DATA / f"{name}.binary").read_bytes(), name


def test_the_reference_simulator_runs_the_demo_to_the_same_cycle(demo):
    # spinsim 0.99 -p (Parallax's ROM interpreter on cycle-exact cogs), the first 6.5 s
    with gzip.open(DATA / "accel_demo.trace.gz", "rt") as f:
        reference = read_log(f.read())
    result = compare_traces(reference, demo.result.trace, until=520_000_000)
    assert result.passed and "largest offset 0 cycles" in result.render()
    motion = motor_from_trace(reference, step=0, dir=1)
    t0 = next(c for c, v in reference.pin_levels(16) if v == "1") / HZ
    assert [motion.position_at(t0 + s) for s in sorted(MANUAL_TABLE)] == [d for _, d in MANUAL_TABLE.values()]


@pytest.mark.parametrize("second", sorted(MANUAL_TABLE))
def test_the_manuals_table_comes_out_of_the_trace(demo, second):
    speed, distance = MANUAL_TABLE[second]
    t = demo.t0 + second
    assert demo.motion.position_at(t) == distance
    assert int(demo.motion.speed_at(t)) == speed       # the manual prints whole steps/s


def test_the_ramp_runs_67_ms_ahead_of_an_exact_one_which_makes_53_and_not_50(demo):
    # the first step comes c0 = 0.676 sqrt(2/a) = 135.2 ms after the move starts (plus the
    # Spin code of moveTo), not sqrt(2/a) = 200 ms; every later step keeps that lead
    first = demo.motion.steps[0].time - demo.t0
    assert 0.1352 < first < 0.1362
    for second, n in ((1, 28), (2, 106), (3, 235)):
        step = demo.motion.steps[n - 1].time - demo.t0
        lead = math.sqrt(2 * n / 50) - step
        assert 0.066 < lead < 0.068
        assert int(demo.motion.speed_at(demo.t0 + second)) == int(50 * (second + lead))


def test_every_step_of_the_demo_is_where_the_floating_point_algorithm_puts_it(demo, demo_model):
    assert [s.position for s in demo.motion.steps] == [p for _, p in demo_model.steps]
    # the first step after a standstill also waits for the Spin code that starts the move
    from_rest = {i for i, (a, b) in enumerate(zip(demo_model.steps, demo_model.steps[1:]))
                 if b[0] - a[0] > 0.13}
    assert max(relative_errors(demo.motion, demo_model, skip=from_rest)) < 1e-3


def test_step_pulses_are_wide_enough_and_dir_is_set_long_before_them(demo):
    m = demo.motion
    assert m.glitches == 0 and m.dir_setup_violations == 0   # >= 2 us pulses, DIR steady >= 100 ms
    assert not m.missed and m.position == 1_500


def test_stop_decelerates_with_more_steps_in_the_direction_of_motion(demo):
    m = demo.motion
    at_stop = m.position_at(demo.t0 + 7.0)
    first_back = next(i for i, s in enumerate(m.steps) if s.delta < 0)
    forward_after_stop = [s for s in m.steps[:first_back] if s.time > demo.t0 + 7.0]
    # stop() at 200 steps/s: 200^2 / (2 * 50) + 1 more steps, all forward, each interval longer
    assert len(forward_after_stop) == 401
    assert m.steps[first_back - 1].position == at_stop + 401
    gaps = [b.time - a.time for a, b in zip(forward_after_stop, forward_after_stop[1:])]
    assert all(g2 > g1 for g1, g2 in zip(gaps, gaps[1:]))
    slope = (1 / gaps[-1] - 1 / gaps[0]) / (forward_after_stop[-1].time - forward_after_stop[0].time)
    assert slope == pytest.approx(-50, rel=0.03)


def test_moveto_during_a_move_turns_the_motor_round(demo):
    m = demo.motion
    backwards = [i for i, s in enumerate(m.steps) if s.delta < 0]
    first, last = backwards[0], backwards[-1]
    retarget = next(i for i in range(first, last + 1) if m.steps[i].position == 600)
    speed = abs(m.steps[retarget].rate)                    # going back at full speed when told 1,500
    assert speed == pytest.approx(200, rel=1e-3)
    turn = m.steps[last].position
    assert turn == 600 - int(speed ** 2 / 100) - 1 or turn == 600 - int(speed ** 2 / 100)
    assert all(s.delta > 0 for s in m.steps[last + 1:]) and m.steps[-1].position == 1_500


PROGRAM = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
OBJ
  motor : "AccelStepper"
PUB main
  motor.startStepDir(0, 1)
  motor.{max_speed}
  motor.{acceleration}
  motor.moveTo({target})
  motor.runToPosition
"""


@pytest.mark.parametrize("max_speed, acceleration, target, v, a, tolerance", [
    ("setMaxSpeedF(37.5)", "setAccelerationF(12.25)", -150, 37.5, 12.25, 1e-4),
    ("setMaxSpeedFx($19_4000)", "setAccelerationFx($3_8000)", 60, 25.25, 3.5, 1e-4),
    ("setMaxSpeed(800)", "setAcceleration(3_000)", 1_000, 800, 3_000, 1e-3),
    ("setMaxSpeed(1_500)", "setAcceleration(6_000)", 700, 1_500, 6_000, 2e-3),
], ids=["float", "fixed", "whole", "fast"])
def test_ramps_follow_the_floating_point_algorithm(tmp_path, max_speed, acceleration, target, v, a, tolerance):
    src = tmp_path / "ramp.spin"
    src.write_text(PROGRAM.format(max_speed=max_speed, acceleration=acceleration, target=target))
    _, result = run_program(src, seconds=20)
    motion = motor_from_trace(result.trace, step=0, dir=1)
    model = AccelModel(v, a)
    model.move_to(target)
    model.run_to_position()
    assert [s.position for s in motion.steps] == [p for _, p in model.steps]
    assert max(relative_errors(motion, model)) < tolerance


def test_constant_speed_and_half_steps_on_coil_pins(tmp_path):
    src = tmp_path / "half.spin"
    src.write_text("""CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
OBJ
  motor : "AccelStepper"
PUB main
  motor.startHalfSteps(4)
  motor.setMaxSpeed(500)
  motor.setSpeedF(-62.5)
  motor.moveTo(-20)
  motor.setSpeedF(-62.5)
  repeat while motor.distanceToGo
    motor.runSpeedToPosition
""")
    _, result = run_program(src, seconds=5)
    motion = motor_from_trace(result.trace, coils=[4, 5, 6, 7])
    assert [s.delta for s in motion.steps] == [-0.5] * 20 and motion.position == -10
    for a, b in zip(motion.steps, motion.steps[1:]):
        assert b.time - a.time == pytest.approx(1 / 62.5, rel=1e-4)


READBACK = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long results[32]
OBJ
  motor : "AccelStepper"
PUB main | i
  motor.startStepDir(0, 1)
  motor.setMaxSpeed(200)
  motor.setAcceleration(50)
  results[0] := motor.speed
  results[1] := motor.run                              ' nowhere to go
  motor.moveTo(100)
  results[2] := motor.distanceToGo
  results[3] := motor.targetPosition
  results[4] := motor.run                              ' on its way
  repeat while motor.currentPosition < 28
    motor.run
  results[5] := motor.speed
  results[6] := motor.speedFx
  motor.setCurrentPosition(500)
  results[7] := motor.currentPosition
  results[8] := motor.speed
  results[9] := motor.distanceToGo
  results[10] := motor.isRunning
  motor.setSpeedF(-2.5)
  results[11] := motor.speedFx
  results[12] := motor.stepInterval
  motor.setAccelerationF(0.25)
  results[13] := motor.accelerationFx
  motor.move(-7)
  results[14] := motor.targetPosition
{floats}
"""


def test_what_the_object_reports(tmp_path):
    # whole, float and 16.16 arguments read back; speed() truncates toward zero
    floats = [0.01, 0.5, 12.5, 37.75, 1000.125, 32767.0, 1.0e6, -3.25]
    lines = "".join(f"  motor.setMaxSpeedF({v!r})\n  results[{16 + i}] := motor.maxSpeedFx\n"
                    for i, v in enumerate(floats))
    src = tmp_path / "readback.spin"
    src.write_text(READBACK.replace("{floats}", lines))
    prog, result = run_program(src, seconds=5)
    vbase = int.from_bytes(prog.binary[8:10], "little")
    got = [int.from_bytes(result.hub[vbase + 4 * i: vbase + 4 * i + 4], "little", signed=True) for i in range(32)]
    assert got[:5] == [0, 0, 100, 100, -1]
    assert got[5] == 53 and got[6] / 65536 == pytest.approx(53.38, abs=0.01)
    assert got[7:11] == [500, 0, 0, 0]
    assert got[11] == -163_840 and got[12] == 32_000_000          # -2.5 steps/s: 0.4 s = 32M ticks
    assert got[13] == 16_384 and got[14] == 493
    want = [min(int(abs(v) * 65536), 0x7FFF_0000) for v in floats]
    assert got[16:16 + len(floats)] == want
