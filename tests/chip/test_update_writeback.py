"""An update (``x++``, ``x += n``) reads its hub variable and writes it back with its last instruction.

The scheduler runs the bytecode at its read; the write-back lands 4 cycles
before the next bytecode starts, and waits for that moment when another cog's
access comes in between (``Scheduler.defer_write``).  These tests pin the
write-back moment down from the outside: the variable's value as hub RAM holds
it at every cycle limit around an update, against the bytecode's own times
from the recorder.  ``race_lost_updates`` in the conformance suite checks the
lost updates against spinsim's hub RAM.
"""
from __future__ import annotations

import pytest

from spinemu.chip import Chip
from spinemu.compiler import compile_source

UPDATES = {
    "x++": 0x2E,            # POST_INC_LONG (USING_VAR_0 $42)
    "x += 5": 0x4C,         # MATH_ADD
    "x *= 3": 0x54,         # MATH_MUL (the write-back waits for the multiply)
    "x /= 7": 0x56,         # MATH_DIV (its length depends on the divisor)
}


def _program(update: str) -> bytes:
    src = f"""
VAR
  long x, n

PUB main
  x := 1_000_001
  repeat 3
    {update}
    n++
"""
    return compile_source(src, "update.spin").binary


def _first_update(image: bytes, sub: int):
    """``(start, fetch, next start)`` of the first update bytecode of ``x`` (recorded run)."""
    chip = Chip(image, fast_forward=False)
    chip.recorder = []
    chip.run(max_cycles=200_000)
    for cog, pc, op, t, tf, t_next, *_ in chip.recorder:
        if op == 0x42 and chip.mem[pc + 1] & 0x7F == sub & 0x7F:
            return t, tf, t_next
    raise AssertionError("no update of x recorded")


def _x_at(image: bytes, cycle: int, **kw) -> int:
    chip = Chip(image, fast_forward=False, **kw)
    chip.run(max_cycles=cycle)
    return chip.mem_longs[chip.header.vbase >> 2]


@pytest.mark.parametrize("update", UPDATES, ids=list(UPDATES))
def test_hub_ram_holds_the_old_value_until_the_last_instruction_of_the_update(update):
    image = _program(update)
    start, fetched, next_start = _first_update(image, UPDATES[update])
    write = next_start - 4                      # the write-back completes here
    old = _x_at(image, start)
    new = _x_at(image, next_start + 1)
    assert old == 1_000_001 and new != old
    for kw in ({}, {"compile_blocks": False}, {"run_ahead": False}):
        # the bytecode has read x (fetch + 192) but not written it back: a run stopped there shows the old value
        assert _x_at(image, fetched + 200, **kw) == old
        assert _x_at(image, write, **kw) == old
        assert _x_at(image, write + 1, **kw) == new


def test_a_run_continued_past_the_write_back_gets_it():
    image = _program("x += 5")
    start, fetched, next_start = _first_update(image, UPDATES["x += 5"])
    chip = Chip(image)
    chip.advance(fetched + 200)                 # stopped between the read and the write-back
    vbase = chip.header.vbase
    assert chip.mem_longs[vbase >> 2] == 1_000_001
    chip.advance(next_start + 1)
    assert chip.mem_longs[vbase >> 2] == 1_000_006


def test_stepping_an_update_writes_it_back():
    image = _program("x++")
    start, fetched, next_start = _first_update(image, UPDATES["x++"])
    chip = Chip(image, fast_forward=False)
    chip.advance(start)                         # the next bytecode of cog 0 is the update
    vbase = chip.header.vbase
    assert chip.mem_longs[vbase >> 2] == 1_000_001
    chip.step(0)
    assert chip.mem_longs[vbase >> 2] == 1_000_002


RACE = """
VAR
  long x, stack[16], done

PUB main | k
  cognew(worker, @stack)
  repeat k from 1 to 300
    x += 2
  repeat until done
  done := x

PRI worker | k
  repeat k from 1 to 300
    x -= 1
  done := 1
"""


def test_two_cogs_racing_lose_the_same_updates_with_and_without_running_ahead_and_blocks():
    image = compile_source(RACE, "race.spin").binary
    ends = set()
    for kw in ({}, {"compile_blocks": False}, {"run_ahead": False, "fast_forward": False}):
        chip = Chip(image, **kw)
        r = chip.run(max_cycles=20_000_000)
        assert r.reason == "all cogs stopped"
        ends.add((chip.mem_longs[(chip.header.vbase >> 2) + 17], r.end_cycle))
    assert len(ends) == 1
    (total, _), = ends
    assert total != 300                         # 300 without a lost update: the cogs overlap, and some are lost


def test_peek_between_bytecodes_shows_an_update_whose_write_back_waits():
    image = compile_source(RACE, "race.spin").binary
    chip = Chip(image, run_ahead=False, fast_forward=False)
    vbase = chip.header.vbase
    seen = 0
    for limit in range(150_000, 400_000, 997):      # stop the run at many moments of the race
        chip.advance(limit)
        # write-backs of x (the raced variable) on their way: the last one is what x becomes
        waiting = [value for _key, _id, _cog, size, addr, value, _t in chip._pend if size == 2 and addr == vbase]
        if waiting and waiting[-1] != chip.mem_longs[vbase >> 2]:
            assert chip.peek(vbase) == waiting[-1]
            seen += 1
    assert seen
