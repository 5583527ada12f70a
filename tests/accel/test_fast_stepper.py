"""FastStepper.spin (PASM step generator + Spin ramp planner) judged from its pin trace.

The demo's trace on spinemu is compared with the reference simulator's run of
spin_src/accel/fast_demo.spin (tests/data/accel/fast_demo.trace.gz: spinsim 0.99 -p,
cycle-exact cogs, see tests/data/README.md), and both are read with the bench's motor model:
the ramp to 50,000 steps/s, the pulse timing, auto-enable and a starved queue.  A second
program stops and turns the motor round in the middle of moves.
"""
from __future__ import annotations

import gzip
import math
from pathlib import Path

import pytest

from spinemu import Chip, compile_spin
from spinemu.analysis.compare import compare_traces
from spinemu.bench.stepper_motor import motor_from_trace
from spinemu.trace import read_log

ROOT = Path(__file__).resolve().parents[2]
ACCEL = ROOT / "spin_src" / "accel"
DATA = ROOT / "tests" / "data" / "accel"
HZ = 80_000_000
A = 500_000                    # steps/s^2, the demo's acceleration
RAMP = 2_500                   # steps: 50,000^2 / (2 * 500,000)
RUN = 31_000_000               # cycles: the recorded run, past the demo's last pin change


@pytest.fixture(scope="module")
def reference():
    with gzip.open(DATA / "fast_demo.trace.gz", "rt") as f:
        return read_log(f.read())


@pytest.fixture(scope="module")
def emulated():
    result = Chip((DATA / "fast_demo.binary").read_bytes()).run(max_cycles=RUN)
    return result.trace


@pytest.fixture(scope="module", params=["reference", "emulated"])
def trace(request):
    return request.getfixturevalue(request.param)


@pytest.fixture(scope="module")
def motion(trace):
    # an A4988: ~ENABLE active low; pulses of at least 2 us, DIR steady 5 us before a step
    return motor_from_trace(trace, step=0, dir=1, enable=2, enable_level=0, min_pulse=2e-6, dir_setup=5e-6)


def intervals(steps):
    return [b.cycle - a.cycle for a, b in zip(steps, steps[1:])]


def test_the_demo_compiles_to_openspins_image():
    assert compile_spin(ROOT / "spin_src" / "accel" / "fast_demo.spin").binary == \
        (DATA / "fast_demo.binary").read_bytes()


def test_ten_thousand_steps_forward_and_five_hundred_back(motion):
    assert [s.delta for s in motion.steps] == [1.0] * 10_000 + [-1.0] * 500
    assert motion.glitches == motion.ignored == motion.dir_setup_violations == 0


def test_the_ramp_reaches_50000_steps_per_second_on_the_clock_tick(motion):
    cruise = intervals(motion.steps[RAMP - 1:10_000 - RAMP])
    assert set(cruise) == {1_600}                          # 80 MHz / 50,000
    assert motion.top_speed() == pytest.approx(50_000)


def test_the_ramp_is_clean_and_has_the_acceleration_asked_for(motion):
    up = intervals(motion.steps[:RAMP])
    down = intervals(motion.steps[10_000 - RAMP - 1:10_000])
    # each command is one interval (the hub window moves a step by 4 cycles at most) and
    # every command is faster than the one before on the way up, slower on the way down
    assert all(b <= a + 8 for a, b in zip(up, up[1:])) and up[0] > 20 * up[-1]
    assert all(b >= a - 8 for a, b in zip(down, down[1:])) and down[-1] > 20 * down[0]
    # from step 1 to step 2,500 at a = 500,000 steps/s^2: sqrt(2 * 2500 / a) - sqrt(2 / a)
    steps = motion.steps
    assert steps[RAMP - 1].time - steps[0].time == pytest.approx(math.sqrt(2 * RAMP / A) - math.sqrt(2 / A), rel=1e-3)
    assert steps[9_999].time - steps[10_000 - RAMP - 1].time == pytest.approx(math.sqrt(2 * RAMP / A), rel=1e-3)


def test_step_pulses_are_2_5_us_wide(trace):
    levels = trace.pin_levels(0)
    widths = {b[0] - a[0] for a, b in zip(levels, levels[1:]) if a[1] == "1"}
    assert widths == {208}                                  # 2.5 us + the PASM instruction that reads CNT


def test_the_driver_is_enabled_100_us_before_the_first_step_and_disabled_10_ms_after_the_last(trace, motion):
    enable = [(c, v) for c, v in trace.pin_levels(2)[1:]]
    assert [v for _, v in enable] == ["1", "0", "1", "0", "1"]   # off, on, off, on (back), off
    moves = (motion.steps[0], motion.steps[9_999]), (motion.steps[10_000], motion.steps[-1])
    for (first, last), (on, _), (off, _) in zip(moves, enable[1::2], enable[2::2]):
        assert first.cycle - on == pytest.approx(100e-6 * HZ, abs=40)
        assert off - last.cycle == pytest.approx(10e-3 * HZ, abs=40)


def test_a_queue_that_runs_dry_mid_move_is_an_underrun(trace, motion):
    back = motion.steps[10_000:]
    assert set(intervals(back)) <= {3_200, 3_204, 3_196}   # 25,000 steps/s, queued by hand
    # the demo shows the generator's counters on P16..P19 (underruns) and P20..P23 (late steps)
    _, driven, out = trace.changes[-1]
    assert driven >> 16 & 0xFF == 0xFF and out >> 16 & 0xFF == 0x01


def test_spinemu_runs_the_demo_as_the_reference_simulator_does(reference, emulated):
    result = compare_traces(reference, emulated, until=RUN)
    assert result.passed and result.render().count("largest offset 0 cycles") == 1


MOVES = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long results[4]
OBJ
  fast : "FastStepper"
PUB main
  fast.start(0, 1, -1, false)
  fast.setSpeedInHz(20_000)
  fast.setAcceleration(400_000)
  fast.moveTo(5_000)
  repeat while fast.getCurrentPosition < 1_500
  fast.stopMove
  repeat while fast.isRunning
  results[0] := fast.getCurrentPosition
  fast.moveTo(0)
  repeat while fast.getCurrentPosition > 1_000
  fast.moveTo(1_500)
  repeat while fast.isRunning
  results[1] := fast.getCurrentPosition
  results[2] := fast.underruns
  results[3] := fast.lateSteps
"""


def test_stop_move_and_a_new_target_while_moving(tmp_path):
    src = tmp_path / "moves.spin"
    src.write_text(MOVES)
    prog = compile_spin(src, [ACCEL])
    result = Chip(prog.binary).run(max_cycles=HZ // 2)
    vbase = int.from_bytes(prog.binary[8:10], "little")
    stopped, final, underruns, late = (int.from_bytes(result.hub[vbase + 4 * i: vbase + 4 * i + 4], "little")
                                       for i in range(4))
    m = motor_from_trace(result.trace, step=0, dir=1, min_pulse=2e-6, dir_setup=5e-6)
    assert (final, underruns, late) == (1_500, 0, 0) and m.position == 1_500
    assert not m.glitches and not m.dir_setup_violations
    # stopMove at full speed (20,000 steps/s, 4,000 ticks a step): after the last full-speed
    # step the planner ramps down in exactly 20,000^2 / (2 * 400,000) = 500 steps
    gaps = intervals(m.steps)
    first_back = next(i for i, s in enumerate(m.steps) if s.delta < 0)
    last_cruise = max(i for i, g in enumerate(gaps[:first_back]) if g == 4_000)
    assert stopped - m.steps[last_cruise + 1].position == 500
    # moveTo(1500) while going back at full speed: 500 steps to slow down, then forward
    turn = next(i for i in range(first_back, len(m.steps)) if m.steps[i].delta > 0)
    back = gaps[first_back:turn - 1]
    assert 4_000 in back and m.steps[turn - 1].position < 1_000 - 500
    assert all(s.delta > 0 for s in m.steps[turn:])
