"""Unit tests of the column's corrected stepper object (spin_src/corrected/stepper.spin),
driven from Python with spinemu.testing: the way to test Propeller objects without hardware.

The first tests use the API (``spinemu.testing.load``), the others the pytest
fixture ``spin`` from spinemu's plugin; both drive the same object the same way.
Pins as in the column's demo: enable on P0, the coils on P1..P4.
"""
from pathlib import Path

import pytest

import spinemu.testing
from spinemu.analysis.stepper import decode_steps

STEPPER = Path(__file__).parent.parent.parent / "spin_src" / "corrected" / "stepper.spin"
EN, COILS = 0, [1, 2, 3, 4]
M_ENABLED, M_RUN, M_STEPS, M_REV = 0b0001, 0b0010, 0b0100, 0b1000
RUN_FWD, RUN_REV = 0, 1


def steps_since(motor, cycle):
    """The coil pattern changes after ``cycle``, one per step: [(cycle, direction)].

    The direction is +1/-1 from the pattern before; ``None`` for the first
    pattern after the coils were all off.
    """
    return [(s.cycle, s.direction) for s in decode_steps(motor.trace, COILS).steps if s.cycle > cycle]


def directions(steps):
    return {d for _, d in steps if d is not None}


@pytest.fixture
def motor():
    """The object started the way the demo starts it (enable on P0, 5 ms minimum step time)."""
    m = spinemu.testing.load(STEPPER)
    assert m.call("start", EN, 5) == -1
    return m


# ----------------------------------------------------------------------------- the API
def test_start_launches_the_stepper_cog_and_leaves_the_driver_disabled():
    m = spinemu.testing.load(STEPPER)
    assert m.call("start", EN, 5) == -1                     # TRUE: a cog was free
    assert m.var("cogon") == -1 and m.var("cog") == 1
    assert m.chip.cogs[1].state == "running"
    assert m.call("getMode") == 0 and m.call("getSteps") == 0
    assert m.call("getStepTmr") == 5
    direction, out = m.outputs
    assert direction & 0b11111 == 0b11111                   # EN and the four coils are outputs...
    assert out & 0b11111 == 0                                # ...all low: the L293 is disabled


def test_set_mode_keeps_four_bits_and_drives_the_enable_pin(motor):
    motor.call("setMode", 0b1_0011)
    assert motor.call("getMode") == M_ENABLED | M_RUN
    assert motor.pin(EN) == 1
    motor.call("setMode", M_RUN)
    assert motor.call("getMode") == M_RUN and motor.pin(EN) == 0


def test_enable_run_direction_and_step_mode_are_bits_of_the_mode(motor):
    motor.call("enable", True)
    motor.call("setRun", True)
    motor.call("stepRun")
    motor.call("setDir", RUN_REV)
    assert motor.call("getMode") == M_ENABLED | M_RUN | M_STEPS | M_REV
    motor.call("freeRun")
    motor.call("setDir", RUN_FWD)
    motor.call("setRun", False)
    motor.call("enable", False)
    assert motor.call("getMode") == 0


def test_set_steps_takes_the_sign_as_the_direction(motor):
    motor.call("setSteps", -7)
    assert motor.call("getSteps") == 7 and motor.call("getMode") & M_REV
    motor.call("setSteps", 7)
    assert motor.call("getSteps") == 7 and not motor.call("getMode") & M_REV


def test_the_step_time_never_goes_below_the_minimum(motor):
    motor.call("setStepTmr", 2)
    assert motor.call("getStepTmr") == 5
    motor.call("setStepTmr", 20)
    assert motor.call("getStepTmr") == 20


def test_counted_steps_forward_then_reverse(motor):
    for call, arg in (("enable", True), ("setRun", True), ("stepRun", None)):
        motor.call(call) if arg is None else motor.call(call, arg)
    t0 = motor.now
    motor.call("setSteps", 12)
    motor.run(ms=100)
    fwd = steps_since(motor, t0)
    assert len(fwd) == 12 and directions(fwd) == {1}        # twelve full steps forward, then it holds
    gaps = {b - a for (a, _), (b, _) in zip(fwd, fwd[1:])}
    assert gaps == {5 * 80_000}                              # one step every 5 ms
    assert motor.var("stpIdx") == 12 % 4
    t1 = motor.now
    motor.call("setSteps", -6)
    motor.run(ms=60)
    back = steps_since(motor, t1)
    assert len(back) == 6 and directions(back) == {-1}


def test_no_step_happens_while_the_driver_is_disabled(motor):
    motor.call("setRun", True)
    motor.call("stepRun")
    motor.call("setSteps", 10)
    t0 = motor.now
    motor.run(ms=80)
    assert steps_since(motor, t0) == [] and motor.call("getSteps") == 10


def test_free_run_steps_until_the_run_bit_is_cleared(motor):
    motor.call("enable", True)
    motor.call("freeRun")
    motor.call("setStepTmr", 10)
    t0 = motor.now
    motor.call("setRun", True)
    motor.run(ms=100)
    running = steps_since(motor, t0)
    assert len(running) == 10 and directions(running) == {1}
    motor.call("setRun", False)
    t1 = motor.now
    motor.run(ms=50)
    assert steps_since(motor, t1) == []


def test_stop_unloads_the_cog_and_lets_the_pins_float(motor):
    motor.call("enable", True)
    motor.call("stop")
    assert motor.var("cogon") == 0
    assert motor.chip.cogs[1].state == "stopped"
    direction, _ = motor.outputs
    assert direction & 0b11111 == 0                          # EN released by cog 0, coils by the stopped cog
    motor.call("stop")                                       # a second stop does nothing
    assert motor.chip.cogs[1].state == "stopped"


# ----------------------------------------------------------------------------- the pytest fixture
def test_the_fixture_loads_the_object_and_counts_steps(spin):
    m = spin.load(STEPPER)
    assert m.call("start", EN, 5)
    m.call("setMode", M_ENABLED | M_RUN | M_STEPS)
    m.call("setSteps", 4)
    t0 = m.now
    m.run(ms=40)
    assert len(steps_since(m, t0)) == 4


def test_the_fixture_free_runs_in_reverse(spin):
    m = spin.load(STEPPER)
    m.call("start", EN, 5)
    m.call("setMode", M_ENABLED | M_RUN | M_REV)             # free run (no M_STEPS), reverse
    t0 = m.now
    m.run(ms=50)
    back = steps_since(m, t0)
    assert len(back) == 10 and directions(back) == {-1}
    m.call("stop")
    assert m.chip.cogs[1].state == "stopped"
