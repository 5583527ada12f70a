"""Stepper decoding and the side-by-side comparison of the column's two programs.

The Spin side is the reference trace of the as-printed simple_stepper.spin
(tests/data/article/as_printed_simple_stepper.trace, spinsim 0.99 with
Parallax's ROM interpreter, 80 MHz); the BS2 side is spinemu's run of
spin_src/bs2/stepper_bs2.bs2.  The column kept the coil sequence and changed
the timing: 5 ms steps instead of 15, and a reverse loop that slows down by
25 % per revolution.
"""
from pathlib import Path

import pytest

from spinemu.analysis.stepper import (compare_step_sequences, compare_stepper_traces,
                                      decode_steps, parse_pins, pattern_text)
from spinemu.pbasic import run_file
from spinemu.trace import PinTrace, read_log

ROOT = Path(__file__).resolve().parents[2]
SPIN_TRACE = ROOT / "tests" / "data" / "article" / "as_printed_simple_stepper.trace"
BS2_DEMO = ROOT / "spin_src" / "bs2" / "stepper_bs2.bs2"

FULL = [0b0011, 0b0110, 0b1100, 0b1001]
WAVE = [0b0001, 0b0010, 0b0100, 0b1000]
HALF = [0b0001, 0b0011, 0b0010, 0b0110, 0b0100, 0b1100, 0b1000, 0b1001]
BACK = [0b1100, 0b0110, 0b0011, 0b1001]          # reverse, continuing from 1001


def synthetic(patterns, period=1000, pins=(0, 1, 2, 3), clock=1_000_000, start=0, gaps=None):
    """A trace driving ``patterns`` on four pins, one every ``period`` cycles."""
    t = PinTrace(clock, pin_count=16)
    t.record(0, 0, 0)
    mask = sum(1 << p for p in pins)
    cycle = start
    for i, p in enumerate(patterns):
        out = sum(((p >> k) & 1) << pin for k, pin in enumerate(pins))
        t.record(cycle, mask, out)
        cycle += (gaps or {}).get(i, period)
    t.end_cycle = cycle
    return t


def test_full_step_forward_and_reverse():
    seq = decode_steps(synthetic(FULL * 3 + BACK * 2), [0, 1, 2, 3])
    assert seq.mode == "full-step (two-coil)"
    deltas = [s.delta for s in seq.steps]
    assert deltas[0] is None                       # 0011 from undriven: no previous pattern
    assert deltas[1:12] == [2] * 11
    assert deltas[12:] == [-2] * 8
    assert seq.net_half_steps == 2 * 11 - 2 * 8


def test_direction_change_step_is_a_repeat_only_when_the_pattern_repeats():
    seq = decode_steps(synthetic([0b0011, 0b0110, 0b1100, 0b0110, 0b0011]), [0, 1, 2, 3])
    assert [s.direction for s in seq.steps] == [None, 1, 1, -1, -1]
    assert [pattern_text(s.pattern) for s in seq.steps] == ["0011", "0110", "1100", "0110", "0011"]


def test_wave_and_half_step_tables():
    assert decode_steps(synthetic(WAVE * 2), [0, 1, 2, 3]).mode == "wave"
    half = decode_steps(synthetic(HALF * 2), [0, 1, 2, 3])
    assert half.mode == "half-step"
    assert {s.delta for s in half.steps[1:]} == {1}
    assert half.net_half_steps == 15


def test_opposite_or_off_cycle_patterns_are_not_steps():
    seq = decode_steps(synthetic([0b0000, 0b0011, 0b1100, 0b0101, 0b0011]), [0, 1, 2, 3])
    assert seq.initial == 0b0000
    assert [s.delta for s in seq.steps] == [None, None, None, None]
    assert seq.mode == "irregular"


def test_pin_mapping_picks_the_coils_out_of_a_wider_trace():
    t = synthetic(FULL * 2, pins=(4, 5, 6, 7))
    assert decode_steps(t, [4, 5, 6, 7]).patterns == FULL * 2
    rev = decode_steps(t, [7, 6, 5, 4])
    assert all(s.direction in (None, -1) for s in rev.steps)


def test_min_dwell_drops_intermediate_patterns_of_pin_by_pin_updates():
    t = PinTrace(1_000_000, pin_count=16)
    t.record(0, 0xF, 0b0011)
    t.record(1000, 0xF, 0b0010)       # LOW 0 ...
    t.record(1140, 0xF, 0b0110)       # ... HIGH 2, 140 us later
    t.record(2000, 0xF, 0b0100)
    t.record(2140, 0xF, 0b1100)
    assert decode_steps(t, [0, 1, 2, 3]).mode == "half-step"
    seq = decode_steps(t, [0, 1, 2, 3], min_dwell=0.0005)
    assert seq.patterns == [0b0011, 0b0110, 0b1100] and seq.mode == "full-step (two-coil)"


def test_segments_split_on_direction_pause_and_speed():
    pats = FULL * 2 + BACK * 4
    gaps = {7: 50_000}                             # a pause after the 8th step
    gaps.update({i: 2000 for i in range(16, 24)})  # last 8 steps twice as slow
    seq = decode_steps(synthetic(pats, gaps=gaps), [0, 1, 2, 3])
    segs = seq.segments()
    assert [(s.first, s.last, s.direction) for s in segs] == [(0, 7, 1), (8, 15, -1), (16, 23, -1)]
    assert [s.period for s in segs] == pytest.approx([0.001, 0.001, 0.002])
    assert segs[2].speed == pytest.approx(500)


def test_parse_pins():
    assert parse_pins("P4..P7") == [4, 5, 6, 7]
    assert parse_pins("4-7") == [4, 5, 6, 7]
    assert parse_pins("P4..P1") == [4, 3, 2, 1]
    assert parse_pins("1, 2, 3, 4") == [1, 2, 3, 4]


def test_decode_needs_four_pins():
    with pytest.raises(ValueError):
        decode_steps(synthetic(FULL), [0, 1, 2])


# ------------------------------------------------------------------ the column
@pytest.fixture(scope="module")
def column():
    bs2 = run_file(BS2_DEMO, seconds=3)
    spin = read_log(SPIN_TRACE.read_text(), clock_hz=80_000_000)
    a = decode_steps(bs2.trace, parse_pins("P4..P7"))
    b = decode_steps(spin, parse_pins("P1..P4"))
    return a, b


def test_bs2_and_spin_make_the_same_forward_revolution(column):
    a, b = column
    cmp = compare_step_sequences(a, b, steps=48, names=("BS2", "Spin"))
    assert cmp.agree and cmp.first_difference is None and cmp.compared == 48
    assert a.patterns[:48] == [0b0110, 0b1100, 0b1001, 0b0011] * 12
    assert all(s.direction in (None, 1) for s in a.steps[:48] + b.steps[:48])


def test_coil_sequences_agree_until_the_spin_reverse_loop_goes_on(column):
    a, b = column
    cmp = compare_step_sequences(a, b, names=("BS2", "Spin"))
    assert not cmp.agree
    assert cmp.first_difference == 96            # step 97: BS2 forward again, Spin still reversing
    assert a.steps[96].direction == 1 and b.steps[96].direction == -1


def test_step_timing_differs_as_the_translation_intended(column):
    a, b = column
    sa, sb = a.segments(), b.segments()
    assert [s.count for s in sa[:2]] == [48, 48] and sa[0].period == pytest.approx(0.015)
    # Spin: 5 ms steps (plus the interpreter's ~75 us), BS2 15 ms: about 2.96 times slower
    assert sb[0].period == pytest.approx(0.005073, abs=2e-6)
    cmp = compare_step_sequences(a, b, names=("BS2", "Spin"))
    ta, tb = cmp.timing(0, 47)
    assert ta / tb == pytest.approx(2.957, abs=0.002)
    # after the first reverse revolution the Spin version slows down by ~25 % each time
    rev = [s for s in sb if s.direction == -1][:8]
    delays_ms = [round(s.period * 1000) for s in rev]
    assert delays_ms == [5, 6, 7, 8, 10, 12, 15, 18]
    assert all(s.count == 48 for s in rev)


def test_comparison_report_tells_the_story(column):
    a, b = column
    text = compare_step_sequences(a, b, names=("BS2", "Spin")).render()
    assert "coil patterns agree for the first 96 steps" in text
    assert "first difference at step 97" in text
    assert "BS2/Spin = 2.957" in text
    assert "after step 96, Spin goes on:\n    reverse 48 steps at 6.075 ms/step" in text


def test_compare_stepper_traces_in_one_call():
    bs2 = run_file(BS2_DEMO, seconds=1)
    spin = read_log(SPIN_TRACE.read_text(), clock_hz=80_000_000)
    cmp = compare_stepper_traces(bs2.trace, [4, 5, 6, 7], spin, [1, 2, 3, 4], steps=48)
    assert cmp.agree


def test_compare_accepts_traces_and_pins_as_the_cli_calls_it():
    bs2 = run_file(BS2_DEMO, seconds=3)
    spin = read_log(SPIN_TRACE.read_text(), clock_hz=80_000_000)
    cmp = compare_step_sequences(bs2.trace, [4, 5, 6, 7], spin, [1, 2, 3, 4])
    assert cmp.first_difference == 96 and cmp.same_sequence is False


def test_render_steps_lists_the_first_steps():
    from spinemu.analysis.stepper import render_steps
    seq = decode_steps(run_file(BS2_DEMO, seconds=0.1).trace, [4, 5, 6, 7])
    text = render_steps(seq, 1_000_000, limit=3)
    assert "    1           0   0.000000 s   0110      ?" in text
    assert "    2       15000   0.015000 s   1100     +1    15.000 ms" in text
    assert "... 4 more steps" in text


def test_spinemu_chip_run_of_the_spin_translation_tells_the_same_story():
    """The same comparison with the Spin side run on spinemu's own chip model."""
    from spinemu.chip import Chip
    from spinemu.compiler import compile_file

    spin = Chip(compile_file(str(ROOT / "spin_src" / "simple_stepper.spin")).binary)
    spin_trace = spin.run(max_cycles=80_000_000).trace          # 1 s at 80 MHz
    bs2 = run_file(BS2_DEMO, seconds=3)
    cmp = compare_step_sequences(bs2.trace, [4, 5, 6, 7], spin_trace, [1, 2, 3, 4])
    assert cmp.first_difference == 96
    ta, tb = cmp.timing(0, 47)
    assert ta / tb == pytest.approx(2.957, abs=0.002)
