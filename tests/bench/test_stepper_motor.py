"""The bench's stepper motor on generated pin changes: step/dir and coil drives, speed and
acceleration, the pull-in limit, the driver's pulse and setup rules, the live interface."""
from __future__ import annotations

import doctest
import math
import random

import pytest

from spinemu.bench import stepper_motor
from spinemu.bench.stepper_motor import PHASE, StepperMotor, coil_delta, motor_from_trace
from spinemu.trace import PinTrace

HZ = 1_000_000            # 1 cycle = 1 us
STEP, DIR, EN = 0, 1, 2
FULL = [0b0011, 0b0110, 0b1100, 0b1001]
HALF = [0b0001, 0b0011, 0b0010, 0b0110, 0b0100, 0b1100, 0b1000, 0b1001]


def step_dir_trace(steps, width=5, setup=50, enable=None, end=None):
    """``steps``: (time in us, +1/-1) in time order; DIR moves ``setup`` us before its pulse.

    ``enable``: level driven on pin EN (None: EN not driven).
    """
    t = PinTrace(HZ, pin_count=8)
    mask = (1 << STEP) | (1 << DIR) | ((1 << EN) if enable is not None else 0)
    en = (enable << EN) if enable else 0
    dir_level = 0
    t.record(0, mask, en)
    for when, d in steps:
        want = 1 if d > 0 else 0
        if want != dir_level:
            dir_level = want
            t.record(when - setup, mask, en | dir_level << DIR)
        t.record(when, mask, en | dir_level << DIR | 1 << STEP)
        t.record(when + width, mask, en | dir_level << DIR)
    t.end_cycle = end if end is not None else (steps[-1][0] + 1000 if steps else 1000)
    return t


def coil_trace(patterns, period=1000, enable=None):
    """Patterns on coils P4..P7, one every ``period`` us; ``enable``: per-pattern level of EN (or None)."""
    t = PinTrace(HZ, pin_count=8)
    t.record(0, 0, 0)
    for i, p in enumerate(patterns):
        en_mask = 1 << EN if enable is not None else 0
        en = (enable[i] << EN) if enable is not None else 0
        t.record((i + 1) * period, 0xF0 | en_mask, (p << 4) | en)
    t.end_cycle = (len(patterns) + 1) * period
    return t


def ramp_steps(rates, start=1000):
    """Forward steps, step i 1/rates[i] s after step i-1 (rates[0] is not used: the first step starts from rest)."""
    t, out = start, []
    for i, r in enumerate(rates):
        if i:
            t += 1e6 / r
        out.append((round(t), 1))
    return out


def test_the_module_examples_run():
    assert doctest.testmod(stepper_motor).failed == 0


def test_random_step_dir_pulses_move_the_shaft_one_step_each():
    rng = random.Random(14)
    t, steps = 1000, []
    for _ in range(300):
        t += rng.randint(200, 20_000)
        steps.append((t, rng.choice((1, 1, -1))))
    m = motor_from_trace(step_dir_trace(steps), step=STEP, dir=DIR)
    assert [s.cycle for s in m.steps] == [w for w, _ in steps]
    assert [s.position for s in m.steps] == [sum(d for _, d in steps[:i + 1]) for i in range(len(steps))]
    assert [s.rate for s in m.steps[1:]] == pytest.approx(
        [d / ((b - a) / HZ) for (a, _), (b, d) in zip(steps, steps[1:])])
    assert not m.missed and m.glitches == m.ignored == m.dir_setup_violations == 0


def test_position_and_speed_at_a_time():
    m = motor_from_trace(step_dir_trace([(1000, 1), (3000, 1), (4000, 1), (8000, -1)]), step=STEP, dir=DIR)
    assert [m.position_at(x) for x in (0.0009, 0.001, 0.0035, 0.0041, 0.009)] == [0, 1, 2, 3, 2]
    assert m.speed_at(0.002) == pytest.approx(500)       # the interval 1..3 ms: one step in 2 ms
    assert m.speed_at(0.005) == pytest.approx(-250)      # 4..8 ms, backward
    assert m.speed_at(0.0005) == 0 and m.speed_at(0.01) == 0
    assert m.commanded_at(0.0045) == 3


def test_a_constant_acceleration_ramp_reads_back_its_acceleration():
    a = 400.0                                            # steps/s^2: step n at sqrt(2 n / a)
    steps = [(1000 + round(1e6 * math.sqrt(2 * n / a)), 1) for n in range(1, 400)]
    m = motor_from_trace(step_dir_trace(steps), step=STEP, dir=DIR)
    accs = [x for t, x in m.accelerations() if t > 0.5]
    assert sum(accs) / len(accs) == pytest.approx(a, rel=0.01)
    assert m.top_speed() == pytest.approx(math.sqrt(2 * a * 399), rel=0.01)


def test_rest_after_turns_a_long_pause_into_a_standstill():
    m = motor_from_trace(step_dir_trace([(1000, 1), (2000, 1), (500_000, 1), (501_000, 1)]), step=STEP, dir=DIR)
    assert [round(v) for _, _, v in m.speeds()] == [1000, 2, 1000]
    assert [round(v) for _, _, v in m.speeds(rest_after=0.1)] == [1000, 0, 1000]


@pytest.mark.parametrize("rate, missed", [(140, 0), (150, 0), (160, 19)])
def test_a_motor_at_rest_follows_steps_up_to_its_pull_in_rate_and_stalls_above(rate, missed):
    m = motor_from_trace(step_dir_trace(ramp_steps([rate] * 20)), step=STEP, dir=DIR, pull_in=150)
    assert len(m.missed) == missed
    assert m.position == 20 - missed and m.commanded == 20


def test_a_gentle_ramp_goes_far_beyond_the_pull_in_rate_and_a_jump_stalls_until_the_rate_falls():
    up = [50 + 20 * i for i in range(60)]                # to 1,230 steps/s in steps of 20
    jump = [3000] * 10                                   # +1,770 steps/s at once: beyond 150
    down = [140] * 5                                     # under the pull-in rate again
    m = motor_from_trace(step_dir_trace(ramp_steps(up + jump + down)), step=STEP, dir=DIR, pull_in=150)
    followed = [s.followed for s in m.steps]
    assert followed == [True] * 60 + [False] * 10 + [True] * 5
    assert m.position == 65 and m.commanded == 75
    assert "10 missed" in m.summary() and "first missed step" in m.summary()


def test_reversing_at_speed_is_missed_but_reversing_slowly_is_followed():
    fast = ramp_steps([100 + 40 * i for i in range(10)])     # up to 460 steps/s
    back = [(fast[-1][0] + 2000, -1)]                        # backward 2 ms later: 500 steps/s the other way
    m = motor_from_trace(step_dir_trace(fast + back, setup=100), step=STEP, dir=DIR, pull_in=150)
    assert [s.followed for s in m.steps] == [True] * 10 + [False]
    slow = [(fast[-1][0] + 20_000, -1)]                      # 50 steps/s the other way
    m = motor_from_trace(step_dir_trace(fast + slow), step=STEP, dir=DIR, pull_in=150)
    assert all(s.followed for s in m.steps) and m.position == 9


def test_slowing_down_at_once_is_always_followed():
    m = motor_from_trace(step_dir_trace(ramp_steps([100 + 40 * i for i in range(20)] + [5] * 3)),
                         step=STEP, dir=DIR, pull_in=150)
    assert not m.missed


def test_short_pulses_are_glitches_and_a_late_dir_change_is_counted():
    m = motor_from_trace(step_dir_trace([(1000, 1), (2000, 1)], width=1), step=STEP, dir=DIR, min_pulse=2e-6)
    assert m.steps == [] and m.glitches == 2
    m = motor_from_trace(step_dir_trace([(1000, -1), (2000, 1)], setup=1), step=STEP, dir=DIR, dir_setup=5e-6)
    assert m.dir_setup_violations == 1 and m.position == 0


def test_an_a4988_ignores_pulses_while_its_active_low_enable_is_high():
    steps = [(1000, 1), (2000, 1)]
    on = motor_from_trace(step_dir_trace(steps, enable=0), step=STEP, dir=DIR, enable=EN, enable_level=0)
    off = motor_from_trace(step_dir_trace(steps, enable=1), step=STEP, dir=DIR, enable=EN, enable_level=0)
    assert on.position == 2 and off.position == 0 and off.ignored == 2


def test_a_pulse_still_high_when_the_trace_ends_counts_if_wide_enough():
    t = step_dir_trace([(1000, 1)], end=1000)
    t.changes.pop()                                      # the falling edge never comes
    t.end_cycle = 1003
    assert motor_from_trace(t, step=STEP, dir=DIR, min_pulse=2e-6).position == 1
    assert motor_from_trace(t, step=STEP, dir=DIR, min_pulse=5e-6).position == 0


@pytest.mark.parametrize("table, delta", [(FULL, 1.0), (HALF, 0.5)])
def test_coil_patterns_move_full_and_half_steps_both_ways(table, delta):
    forward = table * 3
    back = list(reversed(forward))[1:]
    m = motor_from_trace(coil_trace(forward + back), coils=[4, 5, 6, 7])
    n = len(forward) - 1                                 # the first pattern only energises
    assert [s.delta for s in m.steps] == [delta] * n + [-delta] * n
    assert m.position == 0 and m.unit == "full steps"


def test_coil_changes_that_are_not_steps():
    m = motor_from_trace(coil_trace([0b0011, 0b1100, 0b0101, 0b0011, 0b0110, 0b0000, 0b1100, 0b1001]),
                         coils=[4, 5, 6, 7])
    # 0011->1100 opposite, ->0101 off the cycle, ->0011 from off the cycle; 0110 a step;
    # 0000 coils off, 1100 energises again, 1001 a step
    assert m.irregular == 3 and [s.delta for s in m.steps] == [1.0, 1.0]


def test_coils_do_not_move_the_shaft_while_the_driver_is_disabled():
    m = motor_from_trace(coil_trace(FULL * 2, enable=[1, 1, 0, 0, 1, 1, 1, 1]), coils=[4, 5, 6, 7], enable=EN)
    assert [s.delta for s in m.steps] == [1.0, 1.0, 1.0, 1.0]   # 0011->0110; re-enabled at 0011: 0110 1100 1001


def test_several_states_at_one_cycle_count_as_the_last_and_live_feeding_equals_a_trace():
    t = coil_trace(FULL * 2)
    t.changes.insert(3, (t.changes[3][0], 0xF0, 0b1111 << 4))    # a glitch at the instant of a step
    whole = motor_from_trace(t, coils=[4, 5, 6, 7])
    assert whole.irregular == 0 and len(whole.steps) == 7
    live = StepperMotor(coils=[4, 5, 6, 7], clock_hz=HZ)
    for change in t.changes:
        live.on_pins(*change)
    assert live.finish(t.end_cycle).steps == whole.steps


def test_coil_delta_agrees_with_the_phase_table():
    for a in PHASE:
        for b in PHASE:
            d = (PHASE[b] - PHASE[a]) % 8
            want = None if d == 4 else (d - 8 if d > 4 else d)
            assert coil_delta(a, b) == want
    assert coil_delta(0b0101, 0b0011) is None and coil_delta(0b0011, None) is None


@pytest.mark.parametrize("options, message", [
    (dict(), "either four coil pins or a step and a dir pin"),
    (dict(coils=[1, 2, 3], step=None), "four coil pins"),
    (dict(step=0), "a dir pin"),
    (dict(step=0, dir=1, pull_in=0), "pull-in rate"),
])
def test_a_drive_that_makes_no_sense_is_refused(options, message):
    with pytest.raises(ValueError, match=message):
        StepperMotor(**options)
