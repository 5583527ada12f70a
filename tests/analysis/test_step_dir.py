"""Step/direction traces: the decoder (built on the bench's motor model) and the motion plot."""
from __future__ import annotations

import pytest

from spinemu.analysis.stepper import decode_step_dir, render_steps
from spinemu.bench.stepper_motor import motor_from_trace
from spinemu.trace import PinTrace


def pulses(intervals_us, back_from=None, pins=(3, 5)):
    """Steps on STEP=pins[0], DIR=pins[1] (high = forward) at 1 MHz; backward from step ``back_from`` on."""
    step, d = pins
    mask = 1 << step | 1 << d
    t = PinTrace(1_000_000, [(0, mask, 1 << d)])
    now = 1000
    for i, gap in enumerate(intervals_us):
        now += gap
        level = 0 if back_from is not None and i >= back_from else 1 << d
        if t.changes[-1][2] & (1 << d) != level:
            t.record(now - 100, mask, level)
        t.record(now, mask, level | 1 << step)
        t.record(now + 3, mask, level)
    t.end_cycle = now + 1000
    return t


def test_step_dir_pulses_become_a_step_sequence_with_segments():
    seq = decode_step_dir(pulses([10_000] * 10 + [5_000] * 10, back_from=15), 3, 5)
    assert seq.mode == "step/dir" and len(seq) == 20 and seq.net_half_steps == 2 * (15 - 5)
    assert [s.text for s in seq.steps[13:17]] == ["DIR=1", "DIR=1", "DIR=0", "DIR=0"]
    segs = seq.segments()
    # a step belongs with the interval after it (as for coil patterns: write, then wait)
    assert [(g.direction, g.count) for g in segs] == [(1, 9), (1, 6), (-1, 5)]
    assert segs[1].speed == pytest.approx(200)
    text = render_steps(seq, limit=3)
    assert "20 steps on P3 (step), P5 (dir) (step/dir), net +10 steps" in text
    assert "DIR=1     +1" in text and "... 17 more steps" in text


def test_the_decoder_takes_a_time_window_and_ignores_narrow_pulses():
    t = pulses([10_000] * 10)
    assert [s.time for s in decode_step_dir(t, 3, 5, start=0.031, end=0.061).steps] == [0.031, 0.041, 0.051, 0.061]
    assert len(decode_step_dir(t, 3, 5, min_pulse=5e-6)) == 0


def test_segments_beyond_the_limit_are_summarised():
    seq = decode_step_dir(pulses([20_000 - 1000 * i for i in range(15)]), 3, 5)
    text = seq.summary("ramp", max_segments=2)
    assert text.count("forward") == 2 and "more segments" in text


def test_plot_motion_draws_position_speed_and_acceleration(tmp_path):
    pytest.importorskip("matplotlib")
    from spinemu.analysis.plot import plot_motion

    ramp = motor_from_trace(pulses([20_000 - 1000 * i for i in range(15)]), step=3, dir=5)
    stalled = motor_from_trace(pulses([20_000 - 1000 * i for i in range(15)]), step=3, dir=5, pull_in=10)
    out = tmp_path / "m.png"
    fig = plot_motion({"ramp": ramp, "pull-in 10/s": stalled}, path=str(out), title="t")
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert [a.get_ylabel() for a in fig.axes] == ["position (steps)", "speed (steps/s)", "acceleration (steps/s²)"]
    labels = fig.axes[0].get_legend_handles_labels()[1]
    assert "pull-in 10/s: missed" in labels
    fig = plot_motion(ramp, panels=["speed"], start=0.05, end=0.2)
    assert len(fig.axes) == 1 and fig.axes[0].get_xlim() == (0.05, 0.2)
    with pytest.raises(ValueError, match="panels"):
        plot_motion(ramp, panels=["torque"])
