"""Running ahead (spinemu/chip/ahead.py) changes nothing: the same runs as the exact hand-over.

Every comparison runs a program with ``Chip(run_ahead=False)`` (every hub
access handed over in cycle order) and with the default scheduling, and
requires everything a run produces to be identical (schedule_compare.py):
pin trace, hub RAM, end cycle and reason, bytecodes and PASM instructions
per cog, cog events, or the fault's message.  The programs: every image
under tests/data, and a seeded sample of the generated multi-cog programs
(tests/benchmarks/run_ahead_campaign.py runs thousands).
"""
from __future__ import annotations

import glob
import os

import pytest

from spinemu.chip import Chip
from spinemu.compiler import compile_source

from chip_helpers import ROOT
from multicog_programs import program
from schedule_compare import differences, generated_differences, generated_image

IMAGES = sorted(p for p in glob.glob(os.path.join(ROOT, "tests", "data", "**", "*.binary"), recursive=True)
                if os.sep + "disasm" + os.sep not in p)
#: cycles each image runs (the article programs run longer: their cogs start late)
CYCLES = 5_000_000


@pytest.mark.parametrize("path", IMAGES, ids=lambda p: os.path.relpath(p, os.path.join(ROOT, "tests", "data"))[:-7])
def test_every_test_image_runs_the_same_ahead_and_exact(path):
    with open(path, "rb") as f:
        image = f.read()
    cycles = 40_000_000 if os.sep + "article" + os.sep in path else CYCLES
    assert differences(image, cycles) == []


SOURCES = sorted(glob.glob(os.path.join(ROOT, "spin_src", "**", "*.spin"), recursive=True))


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: os.path.relpath(p, os.path.join(ROOT, "spin_src"))[:-5])
def test_every_spin_source_runs_the_same_ahead_and_exact_with_its_debug_info(path):
    # with debug info every runtime check is on (the uninitialized-locals check wraps handlers: then
    # nothing runs ahead); without it, running ahead is on and the warnings must be the same
    from spinemu.compiler import compile_file
    from schedule_compare import outcome
    prog = compile_file(path)
    assert differences(prog.binary, 1_500_000) == []
    info = prog.debug_info()
    assert outcome(prog.binary, False, 1_500_000, debug_info=info) == outcome(prog.binary, True, 1_500_000,
                                                                              debug_info=info)


#: a seeded sample of the generated programs (the campaign script runs 0..999 and more)
SEEDS = [3, 17, 42, 101, 256, 333, 463, 512, 777, 901, 1053, 1234, 1461, 1504, 2024, 4096]


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_multicog_programs_run_the_same_ahead_and_exact(seed):
    assert generated_differences(seed, 1_500_000) == []


_BUSY = "\n".join([
    "VAR", "  long stack[224], results[8]",
    "PUB main | i", "  repeat i from 1 to 7", "    cognew(work(i), @stack[(i - 1) * 32])", "  work(0)",
    "PRI work(id) | k, x", "  x := id", "  repeat k from 1 to 500", "    x := x * 3 + k ^ (x >> 5)",
    "  results[id] := x", ""])


def test_busy_cogs_do_run_ahead():
    # eight cogs in loops over locals: most of their bytecodes run in private stretches
    image = compile_source(_BUSY, "busy.spin").binary
    r = Chip(image).run()
    assert r.reason == "all cogs stopped"
    assert r.stats["private_stretches"] >= 8          # every cog ran ahead at least once
    assert Chip(image, run_ahead=False).run().stats["private_stretches"] == 0
    assert differences(image, None) == []


def test_the_sample_rolls_cogs_back():
    # the sample reaches the rollback path (another cog touches a window of a cog that is ahead)
    r = Chip(generated_image(1234)).run(max_cycles=1_500_000)
    assert r.stats["rollbacks"] > 0 and r.stats["private_stretches"] > 0


def test_a_reboot_brings_back_the_cogs_that_ran_past_it():
    # seed 463: a cog started at $0000 runs into CLKSET's reset bit while cog 0 is ahead in a private
    # stretch; cog 0's stack and bytecode count must be as at the reboot's moment
    image = generated_image(463)
    r = Chip(image).run(max_cycles=4_000_000)
    assert r.reason == "reboot"
    assert differences(image, 4_000_000) == []


def test_a_wrapped_handler_keeps_every_cog_in_the_exact_order():
    # the checked handlers a cog ahead needs are the interpreter's own: a tool's wrapper (the test
    # harness's idle hook, the runtime checks' uninitialized-local handlers) turns running ahead off
    image = compile_source(_BUSY, "busy.spin").binary
    chip = Chip(image)
    seen = []
    inner = chip.handlers[0x1F]

    def hook(c, op, t):
        seen.append(c.id)
        return inner(c, op, t)
    chip.wrap_handler(0x1F, hook)
    r = chip.run()
    assert r.stats["private_stretches"] == 0
    assert r.hub == Chip(image, run_ahead=False).run().hub


def test_a_waitcnt_already_passed_warns_as_in_the_exact_order():
    # cog 1's loop over locals ends in a WAITCNT whose count has passed: the runtime check's warning
    # (cog, place, cycle) is the exact order's while cog 0 and cog 1 run ahead
    src = "\n".join([
        "VAR", "  long stack[32], out",
        "PUB main | k, y", "  cognew(late, @stack)", "  repeat k from 1 to 3000", "    y := y * 3 + k", "  out := y",
        "PRI late | k, x, y", "  repeat 3", "    x := cnt - 50", "    repeat k from 1 to 300",
        "      y := y * 3 + k", "    waitcnt(x)", "    out := y", ""])
    image = compile_source(src, "late.spin").binary
    r = Chip(image).run(max_cycles=20_000_000)
    assert [w.kind for w in r.runtime_warnings] == ["waitcnt-passed"] and r.stats["private_stretches"] > 0
    assert differences(image, 20_000_000) == []


def test_a_stack_past_memory_while_the_fast_forward_learns_is_the_same_fault():
    # seed 1864: a cog's frame goes past $FFFF while its loop is being learned; the learner raised a
    # bare IndexError where the run loops report the fault
    from schedule_compare import outcome
    image = generated_image(1864)
    want = outcome(image, False, 4_000_000, fast_forward=False)
    assert want[0] == "EmulationError" and "out of hub range" in want[1]
    assert outcome(image, True, 4_000_000) == want == outcome(image, False, 4_000_000)


def test_a_generated_program_exercises_every_kind_of_meeting():
    # the generator's menu reaches locks, mailboxes, pins, cog control and stack peeks within the sample
    text = "\n".join(program(s) for s in SEEDS)
    for needle in ("lockset", "mbox", "ring[", "waitpeq", "waitpne", "cogstop", "coginit", "ina[", "stacks[",
                   "long[ptr]"):
        assert needle in text, needle

