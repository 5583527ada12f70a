"""AccelStepper.spin on the column's wiring (L293D enable on P0, coils P1..P4), beside the
column's own fixed-speed driver, through the bench's motor model."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from spinemu import Chip, compile_spin, decode_steps
from spinemu.bench.stepper_motor import motor_from_trace

ROOT = Path(__file__).resolve().parents[2]
HZ = 80_000_000
COILS = dict(coils=[1, 2, 3, 4], enable=0)


@pytest.fixture(scope="module")
def ramped():
    result = Chip(compile_spin(ROOT / "spin_src" / "accel" / "coils_demo.spin").binary).run(max_cycles=30 * HZ)
    assert result.reason == "all cogs stopped"
    return result.trace


@pytest.fixture(scope="module")
def column():
    """The column's corrected demo, its first revolution forward and back (fixed 5 ms steps)."""
    prog = compile_spin(ROOT / "spin_src" / "corrected" / "stepper_demo.spin")
    return Chip(prog.binary).run(max_cycles=int(0.8 * HZ)).trace


def test_the_ramped_demo_moves_like_the_columns(ramped):
    seq = decode_steps(ramped, [1, 2, 3, 4])
    assert seq.mode == "full-step (two-coil)"
    motion = motor_from_trace(ramped, **COILS)
    assert len(motion.steps) == 10 * 48 + 2 * 5 * 96 and motion.position == 0
    # five revolutions forward and back, each one ramp up to 200 steps/s and down
    moves = [s.position for s in motion.steps[:480]]
    assert [moves[i] for i in range(47, 480, 48)] == [48, 0] * 5
    assert motion.top_speed() == pytest.approx(200, rel=1e-4)
    first = motion.steps[1].time - motion.steps[0].time
    assert first == pytest.approx(0.676 * math.sqrt(2 / 1_600) * 0.6, rel=1e-3)   # c1 = c0 (1 - 2/5)


def test_the_free_run_is_96_steps_per_second_the_columns_half_second_per_revolution(ramped):
    motion = motor_from_trace(ramped, **COILS)
    free = motion.steps[480:]
    for a, b in zip(free[1:480], free[2:480]):
        assert b.time - a.time == pytest.approx(1 / 96, rel=1e-4)
    assert [s.delta for s in free] == [1.0] * 480 + [-1.0] * 480


def test_disable_outputs_switches_the_coils_and_the_enable_pin_off(ramped):
    (_, d, o), (_, d_end, _) = ramped.changes[-2:]      # the last state the program set, then its cog stops
    assert d & 0b11111 == 0b11111 and o & 0b11111 == 0 and d_end == 0


def test_a_ramp_keeps_a_motor_in_step_that_the_columns_fixed_speed_start_stalls(ramped, column):
    # a motor that follows at most 150 steps/s from a standstill (its pull-in rate)
    ramp = motor_from_trace(ramped, pull_in=150, **COILS)
    assert not ramp.missed and ramp.position == 0
    fixed = motor_from_trace(column, pull_in=150, **COILS)
    # the column's first pattern only energises the coils: 47 steps forward, 48 back
    assert [s.delta for s in fixed.steps] == [1.0] * 47 + [-1.0] * 48
    # the first step is followed, the second comes at 200 steps/s: the rotor stalls and
    # stays stalled while the drive goes on at that rate; after the 200 ms pause the same
    assert [s.followed for s in fixed.steps[:3]] == [True, False, False]
    assert [s.followed for s in fixed.steps[47:50]] == [True, False, False]
    assert len(fixed.missed) == 93 and fixed.position == 0 and fixed.commanded == -1


def test_the_readme_commands_run_the_demo_and_judge_it(tmp_path):
    import io

    from spinemu.cli import main

    log = tmp_path / "coils.log"
    out, err = io.StringIO(), io.StringIO()
    assert main(["run", str(ROOT / "spin_src" / "accel" / "coils_demo.spin"), "--trace", str(log)], out, err) == 0
    out = io.StringIO()
    assert main(["trace", "steps", str(log), "--pins", "1..4", "--pull-in", "150"], out, err) == 0
    text = out.getvalue()
    assert "(full-step (two-coil)), net +0 full steps" in text
    assert "motor: 1440 steps asked for, 0 missed" in text
