"""The column's BS2 stepper demo (spin_src/bs2/stepper_bs2.bs2): pins, timing, RAM.

Expected values come from the reference notes on the demo (README sections
6.1-6.3 of the BS2 semantics reference): the pattern sequence on P4..P7,
15 ms per step in exact timing, 16.7-17.3 ms in realistic timing.
"""
from pathlib import Path

import pytest

from spinemu.pbasic import compile_file, run_file

DEMO = Path(__file__).resolve().parents[2] / "spin_src" / "bs2" / "stepper_bs2.bs2"
FORWARD = [0b0110, 0b1100, 0b1001, 0b0011]
REVERSE = [0b1001, 0b1100, 0b0110, 0b0011]
COILS = 0xF0                     # P4..P7


def patterns(res):
    """(time in us, OUTB) every time P4..P7 change, after DIRB = %1111."""
    out = []
    for cycle, d, o in res.trace.changes:
        if d & COILS != COILS:
            continue
        p = (o & COILS) >> 4
        if not out or out[-1][1] != p:
            out.append((cycle, p))
    return out


@pytest.fixture(scope="module")
def exact():
    return run_file(DEMO, seconds=3)


@pytest.fixture(scope="module")
def realistic():
    return run_file(DEMO, seconds=3, timing="realistic")


def test_demo_allocates_ram_like_the_tokenizer():
    prog = compile_file(DEMO)
    where = {name: (byte, bit, width) for name, byte, bit, width, *_ in prog.variables()}
    assert where["idx"] == (6, 0, 8)            # B0
    assert where["stpDelay"] == (7, 0, 8)       # B1
    assert where["stpIdx"] == (8, 0, 4)         # low nibble of B2
    assert where["Phase"] == (2, 4, 4)          # OUTB
    assert prog.eeprom[:4] == bytes([3, 6, 12, 9])


def test_first_forward_revolution_is_the_full_step_sequence(exact):
    seq = patterns(exact)
    assert seq[0] == (0, 0b0000)                # DIRB = %1111 drives P4..P7 low
    steps = [p for _, p in seq[1:]]
    assert steps[:48] == FORWARD * 12
    assert steps[48:96] == REVERSE * 12
    second = steps[96:]                         # second pass of Main, up to 3 s
    assert len(second) == 38 and second == (FORWARD * 12)[:38]


def test_every_step_changes_exactly_two_coils(exact):
    seq = [p for _, p in patterns(exact)[1:]]
    assert all(bin(a ^ b).count("1") == 2 for a, b in zip(seq, seq[1:]))


def test_exact_timing_is_15_ms_per_step_with_half_second_pauses(exact):
    times = [t for t, _ in patterns(exact)[1:]]
    assert times[0] == 0                        # F1 at t = 0 (README 6.3)
    assert times[47] == 705_000                 # F48
    assert times[48] == 1_220_000               # R1 after 15 + 500 ms
    assert times[95] == 1_925_000               # R48
    assert times[96] == 2_440_000               # F1 of the second pass
    gaps = {b - a for a, b in zip(times[:48], times[1:48])}
    assert gaps == {15_000}


def test_demo_runs_three_seconds_and_stops_on_the_budget(exact):
    assert exact.reason == "time"
    assert exact.end_cycle == 3_000_000
    assert exact.trace.clock_hz == 1_000_000 and exact.trace.pin_count == 16
    assert exact.trace.driven_pins() == [4, 5, 6, 7]
    assert exact.warnings == []
    assert exact.debug_output == ""


def test_realistic_step_period_is_in_the_published_window(realistic):
    times = [t for t, _ in patterns(realistic)[1:]]
    gaps = [b - a for a, b in zip(times[:48], times[1:48])]
    period = sum(gaps) / len(gaps)
    assert 16_700 <= period <= 17_300
    assert len(set(gaps)) == 1                  # the same 7 instructions every step
    assert period == 16_840                     # 15 ms + 1840 us of instructions
    # a Main pass: 2.61-2.67 s in realistic timing (README 6.3)
    f1_second_pass = times[96]
    assert 2_600_000 <= f1_second_pass - times[0] <= 2_670_000


def test_pins_change_at_the_end_of_the_instruction_in_realistic_timing(realistic):
    changes = realistic.trace.changes
    # DIRB = %1111 is the first instruction: 250 us, then the pins are outputs.
    assert changes[1] == (250, 0xF0, 0)


def test_final_state_after_a_forward_pass_matches_the_reference():
    # F48 at 705 ms; stop inside the PAUSE 500 that follows
    res = run_file(DEMO, seconds=1.0)
    assert res.var("idx") == 49                 # FOR leaves the first out-of-range value
    assert res.var("stpIdx") == 0
    assert res.var("Phase") == 0b0011
    assert res.var("stpDelay") == 15
    assert res.ram[4:6] == bytes([0xF0, 0])     # DIRS: P4..P7 outputs only


def test_run_is_deterministic_and_fast_enough_for_the_default_suite():
    a = run_file(DEMO, seconds=3)
    b = run_file(DEMO, seconds=3)
    assert a.trace.changes == b.trace.changes
    assert a.instructions == b.instructions == 943
