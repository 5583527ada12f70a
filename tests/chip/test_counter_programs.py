"""Spin programs using the counters' PLL, detector, feedback and LOGIC modes, checked by the manual's formulas.

spinsim has no counters, so each expected value is computed here from the
counter table (Propeller Manual v1.2, "CTRA, CTRB"; AN001 "Propeller
Counters") and from what the run itself records (the pin trace, the cycle
of a register access): a POS detector adds FRQ for every clock its pin was
high one clock earlier, an edge detector once per edge, a feedback mode
drives BPIN with APIN inverted one clock later, a PLL output runs at
``FRQ * clkfreq / 2**32 * 16 / 2**(7 - PLLDIV)``.
"""
from __future__ import annotations

import os
import struct

import pytest

from spinemu.chip import Chip
from spinemu.chip.inputs import PinStimulus
from spinemu.chip.timing import load_timing
from spinemu.compiler import compile_file

from chip_helpers import ROOT

CLOCK = 80_000_000
PROGRAMS = os.path.join(ROOT, "tests", "data", "chip", "counters")


def build(name: str) -> bytes:
    return compile_file(os.path.join(PROGRAMS, name + ".spin")).binary


def run(name: str, *, inputs=None, cycles=3_000_000, recorder=False, **kw):
    """Run ``tests/data/chip/counters/NAME.spin``; returns ``(result, chip, its first 40 VAR longs)``."""
    image = build(name)
    chip = Chip(image, compat="chip", inputs=inputs, **kw)
    if recorder:
        chip.recorder = []
    result = chip.run(max_cycles=cycles)
    vbase = struct.unpack_from("<H", image, 8)[0]
    return result, chip, struct.unpack_from("<40I", result.hub, vbase)


def phs_moments(chip, cog: int = 0, reg: int = 0x1C):
    """From the recorder: the cycles at which ``cog``'s REG bytecodes on PHSA (``reg`` $1C; PHSB $1D)
    wrote it and read it (the timing table's write and read offsets from the fetch)."""
    T = load_timing()
    writes, reads = [], []
    for rec in chip.recorder:
        if rec[0] == cog and rec[2] == 0x3F and chip.mem[rec[1] + 1] & 0x1F == reg:
            access = (chip.mem[rec[1] + 1] >> 5) & 3
            if access == 1:
                writes.append(rec[4] + T.reg[(0x3F, 1)] - 4)
            elif access == 0:
                reads.append(rec[4] + T.reg_read_at[(0x3F, 0)])
    return writes, reads


def pin_level(trace, pin: int, cycle: int) -> int:
    return (trace.state_at(cycle)[1] >> pin) & 1


def pin_changes(trace, pin: int) -> list:
    """``(cycle, level)`` each time ``pin``'s driven level changes in the trace."""
    out, last = [], 0
    for cycle, d, o in trace.changes:
        level = (o >> pin) & 1 if (d >> pin) & 1 else None
        if level is not None and level != last:
            out.append((cycle, level))
            last = level
    return out


# ----------------------------------------------------------------------------- detectors
PULSES = [(100_000, 777), (140_000, 1), (180_000, 2_500), (250_000, 40)]   # (start, clocks high)


def pulses(pin: int, spans, idle: int = 0) -> list:
    """Stimulus changes: ``pin`` leaves its idle level for each ``(start, clocks)``."""
    bit = 1 << pin
    out = []
    for start, width in spans:
        out += [(start, bit, 0 if idle else bit), (start + width, bit, bit if idle else 0)]
    return out


def test_pos_and_edge_detectors_count_the_clocks_and_edges_of_a_stimulus():
    second = [(start + 400_000, width) for start, width in PULSES]
    stim = PinStimulus(pulses(3, PULSES + second) + pulses(4, second, idle=1), initial=1 << 4)
    r, _, (pos, neg, posedge, negedge, *_) = run("detectors", inputs=stim)
    assert not r.warnings
    assert pos == sum(width for _, width in PULSES)             # every high clock, once
    assert posedge == len(PULSES)
    assert neg == sum(width for _, width in second)             # P4 is low only in its pulses
    assert negedge == len(second)


# ----------------------------------------------------------------------------- LOGIC on two pins
def test_logic_a_and_not_b_counts_where_a_stimulus_is_high_and_another_cogs_pin_is_low():
    a_on, a_off = 150_000, 500_000                    # P5 high from the stimulus
    r, _, (count, *_) = run("logic_a_and_not_b", inputs=PinStimulus([(a_on, 1 << 5, ~0), (a_off, 1 << 5, 0)]))
    (b_on, _), (b_off, _) = pin_changes(r.trace, 6)   # the driver cog's P6, as the trace recorded it
    assert a_on < b_on < b_off < a_off
    assert count == 3 * ((b_on - a_on) + (a_off - b_off))


# ----------------------------------------------------------------------------- reading at the right moment
def test_a_phs_read_counts_another_cogs_pin_up_to_the_moment_it_reads():
    """The POS count equals the trace's high clocks between the PHS write and each read's read cycle.

    The other cog toggles the pin every few hundred clocks, so a read that
    ran before the other cog had caught up with it would miss a change.
    """
    r, chip, longs = run("phs_read_order", recorder=True, cycles=200_000, fast_forward=False)
    (w,), reads = phs_moments(chip)                      # PHSA := 0, then 40 reads
    assert len(reads) == 40
    assert len(pin_changes(r.trace, 7)) > 100

    high = bytearray(max(reads) + 1)                      # P7's level at each cycle, from the trace
    for (t0, _, o), (t1, _, _) in zip(r.trace.changes, r.trace.changes[1:] + [(len(high), 0, 0)]):
        high[t0:t1] = bytes([(o >> 7) & 1]) * max(0, min(t1, len(high)) - t0)
    # POS: one count for each clock u in (w, t] with P7 high at u - 1
    assert list(longs[:40]) == [sum(high[w:t]) for t in reads]


# ----------------------------------------------------------------------------- feedback
def test_feedback_mode_drives_bpin_with_apin_inverted_one_clock_later():
    edges = [200_000, 200_500, 201_000, 201_003, 260_000]
    stim = PinStimulus([(t, 1 << 8, ~0 if i % 2 == 0 else 0) for i, t in enumerate(edges)])
    r, _, _ = run("feedback", inputs=stim, cycles=700_000)
    fb = pin_changes(r.trace, 9)
    # the first change is BPIN going high when the counter starts (APIN is low); then each input edge + 1
    assert [t for t, _ in fb[1:]] == [t + 1 for t in edges]
    assert all(level == 1 - ((stim.levels(t - 1) >> 8) & 1) for t, level in fb)


def test_a_feedback_adc_with_only_digital_inputs_reads_full_scale_or_zero():
    """Without an RC on the pins nothing integrates BPIN: PHS gains FRQ for every clock APIN is high.

    Between the reads PHS grows by exactly the clocks CNT grew by while APIN
    is high (both are read by the same bytecode at the same offset), and not
    at all while it is low.
    """
    stim = PinStimulus([(250_000, 1 << 8, ~0)])
    r, _, longs = run("feedback", inputs=stim, cycles=800_000)
    c1, p1, c2, p2, c3, p3, c4, p4 = longs[:8]
    assert c2 < 250_000 < c3 < c4
    assert p2 == p1 == 0                                  # APIN low: nothing
    assert p4 - p3 == c4 - c3                             # APIN high: full scale, FRQ per clock
    assert 0 <= (p3 - p2) - (c3 - 250_000) < 1000         # from the rise on (the PHS read follows the CNT read)
    assert pin_level(r.trace, 9, c2) == 1 and pin_level(r.trace, 9, c4) == 0


# ----------------------------------------------------------------------------- an RC measurement
@pytest.mark.parametrize("n", [5_000, 12_345])
def test_an_rctime_style_loop_measures_a_pulse_that_goes_high_after_n_clocks(n):
    start = 200_000
    stim = PinStimulus([(start, 1 << 12, ~0), (start + n, 1 << 12, 0),
                        (600_000, 1 << 12, ~0), (600_000 + n, 1 << 12, 0)])
    r, chip, (width, width2, *_) = run("rctime", inputs=stim, cycles=1_000_000, recorder=True, fast_forward=False)
    assert r.reason == "all cogs stopped"
    assert width2 == n                                     # the whole pulse, counted by CTRB
    (write,), _ = phs_moments(chip)                       # PHSA := 0 came a little after the pulse began:
    assert start < write < start + n and width == start + n - write     # it counts the rest of it


class RcDecay:
    """A capacitor on ``pin`` that reads high for ``n`` clocks after the cogs stop driving the pin high.

    It is a part on the pins written against the pin history, the way a
    model of an RC network plugs into the chip: the input model asks the
    history when the pin was released.
    """

    def __init__(self, pin: int, n: int):
        self.pin, self.n, self.chip = pin, n, None

    def release(self, t: int):
        hist = self.chip.counters.history
        bit = 1 << self.pin
        times = sorted({x for cog in range(8) for x in hist.drive_times(cog, -1, t)}, reverse=True)
        for x in times:
            d, o = hist.driven(x)
            if d & bit:
                return None
            before = hist.driven(x - 1)
            if before[0] & bit and before[1] & bit:
                return x
        return None

    def levels(self, t: int) -> int:
        r = self.release(t)
        return 1 << self.pin if r is not None and t < r + self.n else 0

    def next_change(self, t: int):
        r = self.release(t)
        return r + self.n if r is not None and t < r + self.n else None


def test_an_rc_decay_part_is_measured_by_the_pos_detector_as_an001_does():
    values = []
    for n in (3_000, 7_500):
        part = RcDecay(2, n)
        image = build("rc_decay")
        chip = Chip(image, compat="chip", inputs=part)
        part.chip = chip
        r = chip.run(max_cycles=500_000)
        vbase = struct.unpack_from("<H", image, 8)[0]
        values.append(struct.unpack_from("<I", r.hub, vbase)[0])
        assert [level for _, level in pin_changes(r.trace, 2)] == [1]    # charged once, then let go
    # the same program and overhead both times: the count grows by the decay time exactly
    assert values[1] - values[0] == 7_500 - 3_000
    assert 3_000 < values[0] < 3_000 + 2_000                # plus the Spin overhead between PHSA~ and DIRA~


# ----------------------------------------------------------------------------- PLL
def test_pll_output_frequency_is_reported_and_slow_ones_are_traced():
    r, chip, _ = run("pll", cycles=200_000)
    pll = {p["counter"]: p for p in r.stats["pll"]}
    for ab, plldiv in (("A", 0), ("B", 7)):
        assert pll[ab]["vco_hz"] == 16 * 0x1000_0000 * CLOCK / 2**32
        assert pll[ab]["frequency_hz"] == pll[ab]["vco_hz"] / 2 ** (7 - plldiv)
    assert pll["A"]["pins"] == (5, 6) and pll["A"]["traced"]
    assert pll["B"]["pins"] == (4,) and not pll["B"]["traced"]
    p5 = pin_changes(r.trace, 5)
    half = {b[0] - a[0] for a, b in zip(p5[1:], p5[2:])}
    assert half == {2 ** (35 - 0) // 0x1000_0000 // 2}    # 64 clocks: 625 kHz at 80 MHz
    assert all(pin_level(r.trace, 6, t) != level for t, level in p5[1:])
    assert pin_changes(r.trace, 4) == []                  # 80 MHz: held low in the trace, and said so
    assert any("80.000000 MHz" in w and "P4" in w for w in r.warnings)
    assert not any("P5" in w for w in r.warnings)


def test_a_pll_whose_vco_would_not_lock_is_warned_about():
    r, _, _ = run("pll_internal", cycles=100_000)
    (p,) = r.stats["pll"]
    assert p["mode"] == "PLL internal" and p["pins"] == () and p["vco_hz"] == 20_000_000
    assert p["frequency_hz"] == 20_000_000 / 16
    assert any("outside 64-128 MHz" in w for w in r.warnings)


def test_no_counter_mode_is_reported_as_not_modelled():
    r, _, _ = run("all_modes", cycles=200_000)
    assert r.reason == "all cogs stopped" and not any("not model" in w for w in r.warnings)


# ----------------------------------------------------------------------------- waits
def test_waitpne_wakes_on_a_feedback_edge_exactly_as_on_an_input_edge_at_that_cycle():
    rise = 150_000
    r1, _, _ = run("wait_feedback", inputs=PinStimulus([(rise, 1, 1)]), cycles=300_000)
    r2, _, _ = run("wait_input", inputs=PinStimulus([(rise + 1, 2, 0)], initial=2), cycles=300_000)
    assert pin_changes(r1.trace, 1)[-1] == (rise + 1, 0)
    assert pin_changes(r1.trace, 2) == pin_changes(r2.trace, 2) != []


def test_waitpeq_and_waitpne_wake_on_nco_edges_as_on_input_edges_at_the_same_cycles():
    r, _, _ = run("wait_nco", cycles=2_000_000)
    p2, p3 = pin_changes(r.trace, 2), pin_changes(r.trace, 3)
    assert len(p3) == 20 and [level for _, level in p3] == [1, 0] * 10
    twin, _, _ = run("wait_edges", cycles=2_000_000, inputs=PinStimulus([(t, 1 << 2, level << 2) for t, level in p2]))
    assert pin_changes(twin.trace, 3) == p3


def test_reads_pins_says_which_counter_modes_make_a_phs_read_depend_on_the_pins():
    chip = Chip(build("all_modes"), compat="chip")
    chip._boot()
    cog = chip.cogs[0]
    expect = {m: 8 <= m <= 15 or 17 <= m <= 30 for m in range(32)}
    got = {}
    for m in range(32):
        chip.counters.write(cog, 1, m << 26, 100 + m)       # CTRB
        got[m] = chip.counters.reads_pins(cog)
    assert got == expect


def test_a_counter_on_a_pin_no_waiter_watches_wakes_nobody(monkeypatch):
    """A PASM WAITPEQ on P0 while its own NCO toggles P7 at 1 MHz: the waiter is checked at
    the changes of P0, not at each of the NCO's 20,000 edges (a library CAN driver ran 12x
    slower that way), and wakes at the same cycle."""
    from spinemu.compiler import compile_source
    source = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long woke
PUB main
  cognew(@waiter, @woke)
  waitcnt(cnt + 800_000)
  dira[0] := 1
  outa[0] := 1
  repeat while woke == 0
DAT
        org 0
waiter  mov ctra, nco                             ' NCO on P7: 1 MHz at 80 MHz
        mov frqa, freq
        mov dira, pin7
        waitpeq pin0, pin0                        ' P0, which the Spin cog sets
        mov t, cnt
        wrlong t, par
        cogid t
        cogstop t
nco     long %00100 << 26 | 7
freq    long $8000_0000 / 40
pin0    long 1
pin7    long 1 << 7
t       res 1
"""
    image = compile_source(source).binary
    checks = []
    wake = Chip._wake_pin_waiters

    def counted(chip, t, *a, **kw):
        checks.append(t)
        return wake(chip, t, *a, **kw)

    monkeypatch.setattr(Chip, "_wake_pin_waiters", counted)
    chip = Chip(image, compat="chip")
    result = chip.run(max_cycles=1_200_000)
    assert len(checks) < 50, f"{len(checks)} wake-up checks"
    vbase = struct.unpack_from("<H", image, 8)[0]
    woke = struct.unpack_from("<I", result.hub, vbase)[0]
    assert 800_000 < woke < 900_000
    assert result.trace.edge_counts().get(7, 0) > 15_000
