"""The example programs in spin_src/bs2/ run and do what their headers say."""
from pathlib import Path

import pytest

from spinemu.analysis.stepper import decode_steps
from spinemu.pbasic import run_file

BS2 = Path(__file__).resolve().parents[2] / "spin_src" / "bs2"


def test_blink_toggles_p15_every_quarter_second():
    res = run_file(BS2 / "blink.bs2", seconds=1.2)
    assert res.trace.pin_levels(15) == [(0, "z"), (0, "1"), (250_000, "0"), (500_000, "1"),
                                       (750_000, "0"), (1_000_000, "1")]
    assert res.trace.pin_names == {15: "Led"}


def test_stepper_half_steps_a_revolution_each_way():
    res = run_file(BS2 / "stepper_half.bs2", seconds=2.5)
    seq = decode_steps(res.trace, [4, 5, 6, 7])
    assert seq.mode == "half-step"
    segs = seq.segments()
    assert [(s.direction_text, s.count) for s in segs[:2]] == [("forward", 96), ("reverse", 96)]
    assert segs[0].period == pytest.approx(0.008)


def test_serial_counter_sends_and_shows_each_value():
    res = run_file(BS2 / "serial_counter.bs2", seconds=2)
    assert res.reason == "end"
    assert res.serial_output == {0: b"count=0\rcount=250\rcount=500\rcount=750\rcount=1000\r"}
    lines = res.debug_output.splitlines()
    assert lines[1] == "count=0250 hex=$00FA bin=11111010"
    assert res.trace.driven_pins() == [0]


def test_button_counter_counts_debounced_presses():
    presses = [(0, 1), (0.100, 0), (0.103, 1), (0.104, 0), (0.300, 1), (0.500, 0), (0.700, 1)]
    res = run_file(BS2 / "button_counter.bs2", seconds=1, inputs={3: presses})
    assert res.var("presses") == 2
    assert res.debug_screen() == ["Press the button on P3", "presses: 1", "presses: 2"]
    assert [v for _, v in res.trace.pin_levels(10)] == ["z", "1", "0"]
