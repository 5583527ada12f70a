"""The steady-state skip (spinemu/chip/steady.py) changes nothing: the same runs with and without it.

Every comparison runs a program with ``steady_skip=False`` (the reference)
and with ``steady_skip=True`` and requires everything a run produces to be
identical (``schedule_compare.run_outcome``: pin trace, hub RAM, end cycle
and reason, bytecodes per cog, cog events, runtime warnings).  The runs must also really skip, or the comparison proves nothing.
"""
from __future__ import annotations

import os
import random

import pytest

from spinemu.chip import Chip
from spinemu.chip.pasm_affine import N
from spinemu.chip.steady import INFINITE, MAX_SKIP, Reject, SteadySkip, _compare, _signed_range
from spinemu.compiler.program import compile_source

from chip_helpers import ARTICLE, read_bytes
from schedule_compare import run_outcome
from steady_programs import pasm_program, program

M = 0xFFFFFFFF


def outcome(image: bytes, skip: bool, cycles: int, **kw):
    chip = Chip(image, steady_skip=skip, **kw)
    return run_outcome(chip, cycles), chip


def assert_same(image: bytes, cycles: int, **kw):
    want, _ = outcome(image, False, cycles, **kw)
    got, chip = outcome(image, True, cycles, **kw)
    assert isinstance(got, dict), got           # (these programs run without a fault)
    assert got == want
    return chip


BLINK = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long stack[32], count
PUB main | t
  cognew(pwm, @stack)
  dira[0]~~
  t := cnt
  repeat 3_000
    !outa[0]
    count++
    waitcnt(t += clkfreq / 1000)
PRI pwm | t, i
  dira[1]~~
  t := cnt
  repeat
    repeat i from 0 to 9
      outa[1] := i < 3
      waitcnt(t += 8000)
"""


def test_a_blinking_led_and_a_pwm_cog_run_the_same_skipping_their_periods():
    image = compile_source(BLINK, "blink.spin").binary
    chip = assert_same(image, 400_000_000)
    assert chip._steady.periods > 500
    assert chip.result().stats["steady_periods_skipped"] == chip._steady.periods


# a second cog driving a 1 kHz PWM with 30 % duty on P1 (10 kHz steps)
PWM_1KHZ = """PRI pwm | t, i
  dira[1]~~
  t := cnt
  repeat
    repeat i from 0 to 9
      outa[1] := i < 3
      waitcnt(t += clkfreq / 10_000)
"""

SLOW_AND_FAST = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long stack[32]
PUB main | t
  cognew(pwm, @stack)
  dira[0]~~
  t := cnt
  repeat
    !outa[0]
    waitcnt(t += clkfreq / 4)
""" + PWM_1KHZ


def test_a_fast_cog_is_skipped_while_a_slow_one_sleeps_and_the_slow_one_still_wakes_on_time():
    image = compile_source(SLOW_AND_FAST, "slow_and_fast.spin").binary
    chip = assert_same(image, 400_000_000)
    steady = chip._steady
    assert steady.skips >= 10                  # one or two per quarter second of the slow cog
    assert steady.periods * 80_000 > 200_000_000   # more than half of the run skipped


def test_a_state_that_lasts_for_ever_is_skipped_a_bounded_stretch_at_a_time(monkeypatch):
    # no cycle limit: the skip's only bound is its own, and the run goes on skipping
    image = compile_source(SLOW_AND_FAST.replace("clkfreq / 4", "clkfreq / 1000"), "endless.spin").binary
    apply = SteadySkip._apply

    def bounded(self, chip, m, P, *rest):
        assert m * P <= MAX_SKIP
        apply(self, chip, m, P, *rest)
    monkeypatch.setattr(SteadySkip, "_apply", bounded)

    class Enough(Exception):
        pass

    def progress(t):
        if t > 3 * MAX_SKIP:
            raise Enough
    chip = Chip(image)
    with pytest.raises(Enough):
        chip.run(progress=progress)
    assert chip._steady.skips >= 3


def test_the_corrected_demo_runs_the_same_skipping_its_free_run():
    chip = assert_same(read_bytes(os.path.join(ARTICLE, "corrected_stepper_demo.binary")), 1_600_000_000,
                       compat="spinsim")
    assert chip._steady.periods > 100


def test_the_skip_is_on_by_default_and_off_without_fast_forward():
    image = compile_source(BLINK, "blink.spin").binary
    assert Chip(image)._steady is not None
    assert Chip(image, steady_skip=False)._steady is None
    assert Chip(image, fast_forward=False)._steady is None


@pytest.mark.parametrize("seed", range(0, 16))
def test_random_clock_paced_programs_run_the_same_with_the_skip(seed):
    image = compile_source(program(seed), f"steady{seed}.spin").binary
    assert_same(image, 250_000_000)


def test_the_random_programs_do_skip():
    skipped = 0
    for seed in range(0, 16):
        image = compile_source(program(seed), f"steady{seed}.spin").binary
        _, chip = outcome(image, True, 250_000_000)
        skipped += chip._steady.skips > 0
    assert skipped >= 3


# ---------------------------------------------------------------------- the proof's arithmetic
def _signed(v):
    return v - N if v & 0x80000000 else v


def _answers(kind, x, y):
    a, b = _signed(x & M), _signed(y & M)
    return {"lt": a < b, "le": a <= b, "gt": a > b, "ge": a >= b, "eq": a == b, "ne": a != b}[kind]


@pytest.mark.parametrize("seed", range(6))
def test_a_comparison_keeps_its_answer_for_at_least_the_periods_the_bound_says(seed):
    rng = random.Random(seed)
    for _ in range(300):
        kind = rng.choice(["lt", "le", "gt", "ge", "eq", "ne"])
        x = rng.choice([rng.randrange(N), rng.randrange(-300, 300) & M, (1 << 31) - 5])
        y = rng.randrange(-300, 300) & M
        dx = rng.choice([1, 3, -1, -7, 1 << 20]) & M
        dy = 0
        if rng.random() < 0.3:
            x, y, dx, dy = y, x, dy, dx
        try:
            k = _compare(kind, (x, dx), (y, dy))
        except Reject:
            continue
        first = _answers(kind, x, y)                # (a lower bound: the answer may last longer)
        for p in range(min(k, 400)):
            assert _answers(kind, x + p * dx, y + p * dy) == first


def test_a_repeat_counter_stays_inside_its_bounds_for_the_periods_the_bound_says():
    for v, d, lo, hi in [(5, 1, 0, 9), ((-3) & M, 1, -5, 5), (100, (-4) & M, 0, 200), (7, 0, 0, 9)]:
        k = _signed_range(v, d, lo, hi)
        if d == 0:
            assert k == INFINITE
            continue
        inside = lo <= _signed(v) <= hi
        for p in range(k):
            assert (lo <= _signed((v + p * d) & M) <= hi) == inside
        assert (lo <= _signed((v + k * d) & M) <= hi) != inside     # (steps of 1 or 4 leave exactly)


# a local read before it is assigned: the runtime checks wrap the handlers at its sites
CHECKED_BLINK = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main | t, n
  dira[0]~~
  t := cnt
  repeat
    repeat 500
      waitcnt(t += clkfreq / 1000)
      !outa[0]
    n++
"""


def test_a_program_whose_locals_are_checked_skips_and_warns_as_without_the_skip():
    prog = compile_source(CHECKED_BLINK, "checked.spin")
    want, _ = outcome(prog.binary, False, 400_000_000, debug_info=prog.debug_info())
    got, chip = outcome(prog.binary, True, 400_000_000, debug_info=prog.debug_info())
    assert got == want
    assert chip._handlers_wrapped                       # (the uninitialized-local check is on)
    assert chip._steady.periods > 0
    assert [w[0] for w in got["warnings"]] == ["uninitialized"]


def test_a_proof_too_short_to_pay_records_again_at_the_next_inner_loop():
    # each 500-iteration loop is found calm late in its life: the proof shows its state changes soon
    # (its REPEAT count ends), too soon to pay.  Rather than recording ever longer periods for
    # nothing, the chip runs on to the next inner loop and records there, where the period pays
    prog = compile_source(CHECKED_BLINK, "checked.spin")
    chip = Chip(prog.binary, debug_info=prog.debug_info())
    chip.run(max_cycles=400_000_000)
    steady = chip._steady
    assert steady.retries >= 2 and steady.skips >= steady.attempts - 1
    assert steady.recorded < 150 * steady.attempts                 # (short recordings only)
    assert steady.periods * 160_000 > 100_000_000                   # (2 ms periods: a quarter of the run)


# a PASM cog polling a hub mailbox (an idle loop, parked by pasm_idle.py) while Spin cogs blink and
# drive a PWM; the main cog posts to the mailbox once, after two seconds, and the PASM cog answers on P2
IDLE_PASM = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long mailbox, stack[32]
PUB main | t, n
  cognew(@poll, @mailbox)
  cognew(pwm, @stack)
  dira[0]~~
  t := cnt
  repeat
    !outa[0]
    waitcnt(t += clkfreq / 2)
    if ++n == 4
      mailbox := 1
""" + PWM_1KHZ + """DAT
        org     0
poll    rdlong  x, par wz
  if_z  jmp     #poll
        or      dira, pin
        or      outa, pin
wait    jmp     #wait
pin     long    |< 2
x       res     1
"""


def test_a_pasm_cog_idle_in_its_loop_sleeps_through_the_skipped_periods_and_wakes_on_time():
    image = compile_source(IDLE_PASM, "idle_pasm.spin").binary
    chip = assert_same(image, 400_000_000)
    assert chip.pasm is not None and chip._steady.skips >= 2
    assert chip._steady.periods * 80_000 > 100_000_000          # (a quarter of the run and more)
    assert chip.result().trace.state_at(400_000_000)[0] & 0b100  # (the PASM cog answered: P2 driven)


@pytest.mark.parametrize("seed", [0, 5, 9, 12])
def test_generated_programs_with_an_idle_pasm_cog_run_the_same(seed):
    # (steady_campaign.py --pasm runs any range: seeds 0-199 all the same, 44 with skips)
    image = compile_source(pasm_program(seed), f"steady_pasm{seed}.spin").binary
    chip = assert_same(image, 200_000_000)
    assert chip._steady.skips >= 1
