"""Counter modules: NCO and DUTY outputs on pins, PHS accumulation (Propeller Manual, CTRA/CTRB).

spinsim does not emulate counters, so the expected values come from the
manual's definitions: NCO output = PHS[31] with PHS += FRQ each clock; DUTY
output = the carry of that addition; differential modes drive BPIN inverted.
"""
from __future__ import annotations

import os
import struct

from spinemu.chip import Chip
from spinemu.chip.counters import _Counter

from chip_helpers import ROOT, read_bytes

BEHAVIOUR = os.path.join(ROOT, "tests", "data", "chip", "behaviour")


def run(name, **kw):
    img = read_bytes(os.path.join(BEHAVIOUR, name + ".binary"))
    return img, Chip(img, **kw).run()


def test_nco_mode_toggles_its_pin_every_2_pow_31_over_frq_cycles():
    _, r = run("counter_nco")
    edges = [c for c, d, o in r.trace.changes if d == 0b100]
    half_periods = {b - a for a, b in zip(edges[1:], edges[2:])}
    assert half_periods == {40_000, 40_001}         # 2**31 / 53_687 = 40_000.1 cycles
    assert len(edges) >= 20                         # 10 ms of a ~1 kHz square wave
    assert not r.warnings


def test_logic_always_mode_counts_clocks_in_phs():
    img, r = run("counter_nco")
    vbase = struct.unpack_from("<H", img, 8)[0]
    phs1, phs2 = struct.unpack_from("<II", r.hub, vbase)
    assert 0 < phs1 < phs2 and (phs2 - phs1) % 4 == 0  # FRQB = 1: one count per clock


def test_duty_differential_mode_drives_the_carry_and_its_inverse():
    _, r = run("counter_duty")
    pulses = [(c, o) for c, d, o in r.trace.changes if d == 0b11000 and o]
    highs = [c for c, o in pulses if o == 0b01000]
    assert highs and {b - a for a, b in zip(highs, highs[1:])} == {4}   # FRQ = 2**32 / 4
    assert all(o in (0b01000, 0b10000) for _, o in pulses)            # exactly one of the two pins


def test_counter_edges_are_closed_form():
    u = _Counter()
    u.ctr, u.mode, u.frq, u.phs0, u.t0 = 5, 0b00100, 1 << 30, 0, 100
    assert list(u.edges(100, 120)) == [102, 104, 106, 108, 110, 112, 114, 116, 118, 120]
    assert u.outputs(102) == 1 << 5 and u.outputs(104) == 0
