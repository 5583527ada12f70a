"""Pins one cog writes and another reads: when a write shows, and a stop in the middle of a bytecode.

A Spin bytecode that writes OUTA/DIRA runs, in the scheduler's order, at its
access (where it reads), and writes the register later in its path.  Another
cog reading INA in between sees the pins as they were, as on the reference
interpreter; the conformance programs ``pins_*.spin`` (tests/data/chip/programs)
compare every phase of such reads with spinsim.  This file checks what a
stop inside such a bytecode leaves on the pins.
"""
from spinemu.chip import Chip
from spinemu.compiler.program import compile_source
from spinemu.chip.pinfold import PinFold

TOGGLER = """
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long stack[24]
PUB main | w
  w := cognew(toggler, @stack)
  waitcnt(cnt + {delay})
  cogstop(w)
PRI toggler
  dira[17] := 1
  repeat
    !outa[17]
"""


def _run(delay):
    chip = Chip(compile_source(TOGGLER.format(delay=delay), "toggler.spin").binary)
    result = chip.run(max_cycles=2_000_000)
    stop = next(t for t, cog, what, _ in result.cog_events if cog == 1 and what == "stop")
    return chip, result, stop


def test_a_cog_stopped_inside_a_bytecode_that_writes_its_pins_later_never_drives_them_again():
    caught = 0
    for delay in range(20_000, 20_900, 50):     # one toggle loop is 896 cycles: stops at every phase
        chip, result, stop = _run(delay)
        late = [(t, d) for t, d, o in result.trace.changes if t > stop and d & (1 << 17)]
        assert not late, f"delay {delay}: P17 driven after cog 1 stopped at {stop}: {late}"
        h = chip.cogs[1].pin_hist
        caught += any(when > stop for when, *_ in h)
    assert caught, "no stop landed between a bytecode's access and its write"


def test_changes_on_one_cycle_are_in_cog_order_as_spinsim_steps_its_cogs():
    # two PASM cogs write their pins on the same cycle: the trace lists the lower cog's change
    # first, whichever cog spinemu ran first (the Parallax library's ADC Max1270 demo does this)
    chip = Chip(compile_source("PUB main\n", "nothing.spin").binary)     # (the records are made here)
    chip.pin_events[:] = [(100, 1, 3, 1 << 10, 1 << 10, True), (100, 2, 1, 1 << 30, 1 << 30, True),
                          (200, 3, 3, 1 << 10, 0, True), (200, 4, 1, 1 << 30, 0, True)]
    fold = PinFold(chip)
    fold.advance(300)
    assert fold.changes == [(100, 1 << 30, 1 << 30), (100, 1 << 30 | 1 << 10, 1 << 30 | 1 << 10),
                            (200, 1 << 30 | 1 << 10, 1 << 10), (200, 1 << 30 | 1 << 10, 0)]
