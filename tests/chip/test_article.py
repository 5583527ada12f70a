"""The column's three programs against the reference traces and hub dumps (tests/data/article).

compat="spinsim" must reproduce spinsim 0.99 cycle for cycle: same pin
changes at the same cycles, and hub RAM byte-identical at the end of the two
demos.  compat="chip" models the chip, which differs from spinsim in one way
these programs show: a new cog loads for ~8,000 cycles before it runs, so in
the stepper demos the background cog makes its pins outputs *after* the main
cog enables pin 0 instead of before (the first two changes come in the other
order); everything else matches within the comparison's slack.
"""
from __future__ import annotations

import os

import pytest

from spinemu.chip import Chip

from chip_helpers import ARTICLE, article_image, compare, read_bytes, read_trace, trace_states

RUNS = {  # name: cycles to run (None: until every cog has stopped)
    "as_printed_simple_stepper": 1_000_000_000,
    "as_printed_stepper_demo": None,
    "corrected_stepper_demo": None,
}
DEMO_END = 1_152_058_552        # cog 0 executes its final COGSTOP then (pins went idle at 1_152_057_784)


def reference(name):
    return trace_states(read_trace(os.path.join(ARTICLE, name + ".trace")))


@pytest.fixture(scope="module")
def spinsim_runs():
    return {name: Chip(article_image(name), compat="spinsim").run(max_cycles=cycles)
            for name, cycles in RUNS.items()}


@pytest.mark.parametrize("name", sorted(RUNS))
def test_spinsim_mode_reproduces_the_reference_trace_cycle_for_cycle(spinsim_runs, name):
    result = spinsim_runs[name]
    assert trace_states(result.trace.changes) == reference(name)


@pytest.mark.parametrize("name", ["as_printed_stepper_demo", "corrected_stepper_demo"])
def test_spinsim_mode_ends_with_byte_identical_hub_ram(spinsim_runs, name):
    result = spinsim_runs[name]
    assert result.reason == "all cogs stopped"
    assert result.end_cycle == DEMO_END
    assert result.hub == read_bytes(os.path.join(ARTICLE, name + ".hub"))


def test_simple_stepper_runs_for_the_requested_cycles(spinsim_runs):
    result = spinsim_runs["as_printed_simple_stepper"]
    assert result.reason == "cycle limit" and result.end_cycle == 1_000_000_000
    assert result.trace.clock_hz == 80_000_000


@pytest.mark.parametrize("name", sorted(RUNS))
def test_chip_mode_matches_the_reference_within_the_comparison_rules(name):
    result = Chip(article_image(name), compat="chip").run(max_cycles=RUNS[name])
    ref, cand = reference(name), trace_states(result.trace.changes)
    if name != "as_printed_simple_stepper":
        # the chip's cog load delay swaps the first two changes (see module docstring)
        assert [s[1:] for s in ref[:2]] == [(0x1E, 0), (0x1F, 0)]
        assert [s[1:] for s in cand[:2]] == [(0x01, 0), (0x1F, 0)]
        ref, cand = ref[2:], cand[2:]
    same, worst, largest = compare(ref, cand)
    assert same
    assert worst <= 0.0005          # the project's goal: 0.05 %
    assert largest <= 16_000


def test_fast_forward_changes_nothing_on_the_demo():
    image = article_image("corrected_stepper_demo")
    fast = Chip(image).run()
    slow = Chip(image, fast_forward=False).run()
    assert fast.stats["bytecodes_skipped"] > 100_000
    assert slow.stats["bytecodes_skipped"] == 0
    assert fast.trace.changes == slow.trace.changes
    assert fast.hub == slow.hub
    assert (fast.end_cycle, fast.reason) == (slow.end_cycle, slow.reason)
    assert fast.stats["bytecodes_per_cog"] == slow.stats["bytecodes_per_cog"]
