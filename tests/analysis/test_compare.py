"""Trace comparison: the project's measure of 'same behaviour as the reference'."""
from pathlib import Path

from spinemu.analysis.compare import compare_traces, state_changes
from spinemu.trace import PinTrace, read_log

DATA = Path(__file__).parent.parent / "data" / "article"


def _trace(rows, clock=80_000_000):
    return PinTrace(clock, list(rows), rows[-1][0] if rows else 0)


def test_a_reference_trace_matches_itself_exactly():
    t = read_log((DATA / "corrected_stepper_demo.trace").read_text())
    r = compare_traces(t, t)
    assert r.identical and r.passed
    assert r.worst_error == 0 and r.largest_offset == 0
    assert r.reference_changes == 1485


def test_idle_start_state_and_repeated_states_are_not_changes():
    t = _trace([(0, 0, 0), (4, 0, 0), (10, 1, 0), (20, 1, 0), (30, 1, 1)])
    assert state_changes(t) == [(10, 1, 0), (30, 1, 1)]


def test_timing_error_is_relative_to_reference_time_after_slack():
    ref = _trace([(0, 0, 0), (1_000_000, 1, 1), (2_000_000, 1, 0)])
    cand = _trace([(0, 0, 0), (1_030_000, 1, 1), (2_016_000, 1, 0)])
    r = compare_traces(ref, cand, slack=16_000)
    assert r.identical
    assert r.worst_error == (30_000 - 16_000) / 1_000_000
    assert r.largest_offset == 30_000
    assert not compare_traces(ref, cand, slack=16_000, tolerance=0.01).passed
    assert compare_traces(ref, cand, slack=16_000, tolerance=0.02).passed


def test_changes_in_the_first_millisecond_are_not_timed():
    ref = _trace([(0, 0, 0), (1_000, 1, 1)])
    cand = _trace([(0, 0, 0), (60_000, 1, 1)])
    r = compare_traces(ref, cand, slack=0)
    assert r.matched == 0 and r.worst_error == 0 and r.largest_offset == 59_000


def test_first_difference_names_both_states():
    ref = _trace([(0, 0, 0), (100_000, 1, 1), (200_000, 1, 0)])
    cand = _trace([(0, 0, 0), (100_000, 1, 1), (200_000, 3, 0)])
    r = compare_traces(ref, cand)
    assert not r.identical and r.first_difference == 1
    assert "first difference at change #1" in r.render()
    assert "candidate cycle 200000 dir 00000003" in r.render()
    assert r.render().splitlines()[-1].startswith("FAIL")


def test_a_candidate_that_stops_early_differs():
    ref = _trace([(0, 0, 0), (100_000, 1, 1), (200_000, 1, 0)])
    cand = _trace([(0, 0, 0), (100_000, 1, 1)])
    r = compare_traces(ref, cand)
    assert not r.identical and r.first_difference is None
    assert "candidate stops early after 1 matching changes" in r.render()


def test_until_ignores_later_changes():
    ref = _trace([(0, 0, 0), (100_000, 1, 1), (200_000, 1, 0)])
    cand = _trace([(0, 0, 0), (100_000, 1, 1), (200_000, 3, 0)])
    assert compare_traces(ref, cand, until=150_000).identical
