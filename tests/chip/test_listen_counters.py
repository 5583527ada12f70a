"""Live pin listeners on programs whose counters drive pins: they see exactly the trace, as the run goes.

The trace and the listeners read one fold of the pin record and the
counters' marks (``spinemu.chip.pinfold``); a run without listeners folds
once at the end, a run with one folds a stretch at every call.  So each
program runs twice, and the listener's changes must be the plain run's trace
(the same list), every change handed over by the first call whose ``upto``
is past it.  The programs are spinemu's own (``tests/data/chip/counters``,
``tests/data/bench/nco_serial.spin``); their images were checked identical to
OpenSpin's.
"""
from __future__ import annotations

import os

import pytest

from spinemu.chip import Chip
from spinemu.chip.countermarks import CounterMarks
from spinemu.chip.inputs import PinStimulus
from spinemu.compiler import compile_file
from spinemu.trace import PinTrace

from chip_helpers import ROOT

CLOCK = 80_000_000
COUNTERS = os.path.join(ROOT, "tests", "data", "chip", "counters")
NCO_SERIAL = os.path.join(ROOT, "tests", "data", "bench", "nco_serial.spin")


def image(name: str) -> bytes:
    path = NCO_SERIAL if name == "nco_serial" else os.path.join(COUNTERS, name + ".spin")
    return compile_file(path).binary


def feedback_stimulus():
    edges = [200_000, 200_500, 201_000, 201_003, 260_000]
    return PinStimulus([(t, 1 << 8, ~0 if i % 2 == 0 else 0) for i, t in enumerate(edges)])


#: (program, input model maker, cycles): NCO, PLL (traced and too fast to trace), DUTY, feedback outputs
PROGRAMS = [
    ("wait_nco", None, 2_000_000),                      # NCO on P2 that WAITPEQ/WAITPNE wait on
    ("pll", None, 200_000),                             # PLL 625 kHz on P5/P6 (traced), 80 MHz on P4 (not)
    ("feedback", feedback_stimulus, 700_000),           # POS detector with feedback: P9 = !P8
    ("wait_feedback", lambda: PinStimulus([(150_000, 1, 1)]), 300_000),
    ("duty_dac", None, 400_000),                        # DUTY ramp, DUTY differential under DIRA switching
    ("all_modes", None, 200_000),                       # every mode in turn
    ("nco_serial", None, 7_000_000),                    # serial from an NCO's PHSA[31]; a 1 kHz NCO
    # input modes: the PHS they read from the pin history is the same under a listener (hub RAM compared)
    ("phs_read_order", None, 300_000),
    ("logic_a_and_not_b", lambda: PinStimulus([(100_000, 1 << 5, 1 << 5), (400_000, 1 << 5, 0)]), 700_000),
]


def run_twice(name, make_inputs, cycles, interval, limit=None):
    """The program without and with a recording listener: (plain result, listened result, calls, chip).

    ``calls`` holds ``(upto, changes)`` per listener call.
    """
    def chip():
        c = Chip(image(name), compat="chip", inputs=make_inputs() if make_inputs else None)
        if limit is not None:
            c.pin_fold.marks.limit = limit
        return c

    plain = chip().run(max_cycles=cycles)
    listened_chip = chip()
    calls = []

    def listener(changes, upto, present):
        assert all(c < upto <= present or upto == 1 << 62 for c, _, _ in changes)
        calls.append((upto, list(changes)))

    listened_chip.add_pin_listener(listener, interval_cycles=interval)
    listened = listened_chip.run(max_cycles=cycles)
    return plain, listened, calls, listened_chip


def assert_listener_saw_the_trace(plain, listened, calls, chip):
    assert listened.trace.changes == plain.trace.changes
    assert (listened.end_cycle, listened.hub, listened.reason) == (plain.end_cycle, plain.hub, plain.reason)
    seen = [change for _, changes in calls for change in changes]
    rebuilt = PinTrace(CLOCK, [(0, 0, 0)])
    for change in seen:
        rebuilt.record(*change)
    assert rebuilt.changes == plain.trace.changes
    assert [(0, 0, 0)] + seen == plain.trace.changes            # the same list: no repeated state
    # promptly: after each call the listener has every change before its upto, and nothing later
    expected = plain.trace.changes[1:]
    n = 0
    for upto, changes in calls:
        n += len(changes)
        assert n == sum(1 for c, _, _ in expected if c < upto)
    assert chip.late_pin_events == 0


@pytest.mark.parametrize("interval", [CLOCK // 1000, 777])
@pytest.mark.parametrize("name, make_inputs, cycles", PROGRAMS, ids=[p[0] for p in PROGRAMS])
def test_a_listener_sees_the_counters_outputs_exactly_as_the_trace_has_them(name, make_inputs, cycles, interval):
    plain, listened, calls, chip = run_twice(name, make_inputs, cycles, interval)
    assert_listener_saw_the_trace(plain, listened, calls, chip)
    if len(plain.trace.changes) > 2:                    # told as the run went, not only at the end
        assert any(changes for _, changes in calls[:-1])


def test_the_counter_edges_a_listener_is_handed_are_the_traces_up_to_the_same_cap(monkeypatch):
    uncapped = Chip(image("duty_dac"), compat="chip").run(max_cycles=400_000)
    made = []
    original = CounterMarks._piece

    def piece(self, a, b):
        marks = original(self, a, b)
        made.append(len(marks))
        return marks

    monkeypatch.setattr(CounterMarks, "_piece", piece)
    plain, listened, calls, chip = run_twice("duty_dac", None, 400_000, 5_000, limit=5_000)
    assert_listener_saw_the_trace(plain, listened, calls, chip)
    for r in (plain, listened):
        assert sum("counter output edges exceed 5,000" in w for w in r.warnings) == 1
    assert len(plain.trace.changes) < 6_000 < 100_000 < len(uncapped.trace.changes)
    assert chip.counters.edges_recorded == 5_000
    # neither run made the marks past the cap: the plain run's one long interval is walked in pieces
    assert sum(made) < len(uncapped.trace.changes) // 2


def test_the_programs_counters_do_drive_the_pins_the_listener_watches():
    """Not vacuous: P2 (wait_nco), P5/P6 (pll), P9 (feedback), P6/P7/P8 (duty_dac), P30 and P4 (nco_serial)
    change many times in the trace, only through counter outputs."""
    def changes_of(trace, pin):
        return sum(1 for (_, d0, o0), (_, d1, o1) in zip(trace.changes, trace.changes[1:])
                   if (o0 ^ o1) >> pin & 1)

    expect = {"wait_nco": {2: 20}, "pll": {5: 1000, 6: 1000}, "feedback": {9: 5}, "duty_dac": {6: 1000, 7: 100},
              "nco_serial": {30: 50, 4: 80}}
    for name, make_inputs, cycles in PROGRAMS:
        if name not in expect:
            continue
        trace = Chip(image(name), compat="chip", inputs=make_inputs() if make_inputs else None).run(
            max_cycles=cycles).trace
        for pin, at_least in expect[name].items():
            assert changes_of(trace, pin) >= at_least, (name, pin)


def test_marks_are_made_once_each_however_often_a_listener_asks(monkeypatch):
    """A 1 kHz NCO for a simulated second and a listener about every millisecond: each call walks only the
    new stretch of time (the work grows with the calls, not with the calls times the run so far)."""
    walked = []
    original = CounterMarks._stretch

    def counting(self, cur, seg, start, a, b, out):
        walked.append((cur.cog, cur.ab, a, b))
        return original(self, cur, seg, start, a, b, out)

    plain = Chip(image("nco_blink"), compat="chip").run(max_cycles=CLOCK)
    chip = Chip(image("nco_blink"), compat="chip")
    calls = []
    chip.add_pin_listener(lambda changes, upto, present: calls.append((upto, list(changes))),
                          interval_cycles=CLOCK // 1000)
    monkeypatch.setattr(CounterMarks, "_stretch", counting)
    listened = chip.run(max_cycles=CLOCK)
    assert_listener_saw_the_trace(plain, listened, calls, chip)
    assert len(calls) >= 900 and len(plain.trace.changes) > 2900
    segments = sum(len(unit.segs) for units in chip.counters.units for unit in units)
    assert len(walked) <= len(calls) + 1 + segments     # per call, the output counter's one stretch
    for counter in {(cog, ab) for cog, ab, _, _ in walked}:
        spans = [(a, b) for cog, ab, a, b in walked if (cog, ab) == counter]
        assert all(b0 < a1 for (_, b0), (a1, _) in zip(spans, spans[1:])), counter   # no cycle walked twice
    assert max(b for _, _, _, b in walked) == CLOCK


def test_a_pin_event_recorded_after_its_cycle_was_folded_is_folded_at_once_and_counted():
    from spinemu.chip.cog import RUNNING
    from spinemu.compiler import compile_source

    chip = Chip(compile_source("PUB main\n").binary, compat="chip")
    chip._boot()
    cog = chip.cogs[1]
    cog.state = RUNNING
    cog.dira, cog.outa = 1, 1
    chip.note_pins(cog, 10)
    fold = chip.pin_fold
    fold.advance(100)
    assert fold.changes == [(10, 1, 1)] and fold.late == 0
    cog.outa = 0
    chip.note_pins(cog, 50)                             # too late: cycle 50 was handed over already
    cog.outa = 1
    chip.note_pins(cog, 120)
    fold.advance(200)
    assert fold.changes == [(10, 1, 1), (100, 1, 0), (120, 1, 1)] and fold.late == 1
    assert chip.late_pin_events == 1
    assert [ev[0] for ev in chip.pin_events[-3:]] == [10, 50, 120]     # the record itself is left as written
