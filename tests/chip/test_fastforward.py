"""Busy-loop fast-forward (spinemu/chip/fastforward.py): exact, and cheap when a loop is woken often.

Every run is compared with ``fast_forward=False``: pin trace, hub RAM, end
cycle and bytecodes per cog must be identical.
"""
from __future__ import annotations

import os

from spinemu.chip import Chip

from chip_helpers import ARTICLE, make_image, read_bytes


def run_both(image: bytes, cycles, compat: str = "chip"):
    fast = Chip(image, compat=compat).run(max_cycles=cycles)
    slow = Chip(image, compat=compat, fast_forward=False).run(max_cycles=cycles)
    assert (fast.trace.changes, fast.hub, fast.end_cycle) == (slow.trace.changes, slow.hub, slow.end_cycle)
    assert fast.stats["bytecodes_per_cog"] == slow.stats["bytecodes_per_cog"]
    return fast


def test_a_loop_woken_with_values_it_saw_before_is_not_learned_again():
    # cog 0 spins until var0 == -1; cog 1 flips var0 between 0 and 3 every 100_000 cycles
    main = bytes([0x39, 0x00, 0x02, 0xCB, 0x40, 0x15, 0x2C,   # cognew(method2, @var[16])
                  0x40, 0x34, 0xFC, 0x0A, 0x7B])               # repeat until var0 == -1
    worker = bytes([0x3F, 0x91, 0x3A, 0x01, 0x86, 0xA0,        # waitcnt(cnt + 100_000)
                    0xEC, 0x23,
                    0x38, 0x03, 0x40, 0xED, 0x41,              # var0 := 3 - var0
                    0x04, 0x71])                               # repeat
    image = make_image(main, var_longs=48, methods=[(worker, 0)])
    for compat in ("chip", "spinsim"):
        r = run_both(image, 40_000_000, compat)
        assert r.stats["bytecodes_skipped"] > 100_000
        assert r.stats["busy_loops_learned"] <= 4          # one per value (and head), not one per wake


def test_the_corrected_demo_relearns_its_wait_loop_once_per_step_count():
    r = run_both(read_bytes(os.path.join(ARTICLE, "corrected_stepper_demo.binary")), 400_000_000, "spinsim")
    # 10 revolutions of 48 steps wake the wait loops 470 times; from the second revolution
    # on the step counts repeat and their loops come from memory
    assert r.stats["bytecodes_skipped"] > 800_000
    assert r.stats["busy_loops_learned"] < 250
