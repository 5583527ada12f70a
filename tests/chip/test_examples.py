"""The example programs in spin_src/examples: OpenSpin's images, and what their pins do.

The expected images are OpenSpin 1.00.81's (tests/data/examples); the pin
behaviour is what the programs say they do, in clock cycles at 80 MHz.
"""
from __future__ import annotations

import struct
from pathlib import Path

import pytest

from spinemu.chip import Chip
from spinemu.compiler import compile_file
from spinemu.image import ImageHeader

ROOT = Path(__file__).parent.parent.parent
EXAMPLES = ROOT / "spin_src" / "examples"
IMAGES = ROOT / "tests" / "data" / "examples"
QUARTER = 20_000_000                    # clkfreq / 4 at 80 MHz


@pytest.mark.parametrize("name", ["blink", "two_cogs", "knight_rider", "serial_hello", "serial_echo", "bench_demo"])
def test_an_example_compiles_to_openspins_image(name):
    assert compile_file(str(EXAMPLES / f"{name}.spin")).binary == (IMAGES / f"{name}.binary").read_bytes()


def steady(times, period):
    """Every interval after the first (which includes the set-up before the first WAITCNT) is ``period``."""
    gaps = [b - a for a, b in zip(times, times[1:])]
    return set(gaps[1:]) == {period} and abs(gaps[0] - period) < 400


def pin_times(trace, pin):
    """Cycles at which ``pin`` changes level while driven (a stopped cog releasing it is no toggle)."""
    times, last = [], 0
    for t, driven, out in trace.changes:
        level = out >> pin & 1
        if driven >> pin & 1 and level != last:
            times.append(t)
            last = level
    return times


def test_blink_toggles_p16_every_quarter_second():
    result = Chip((IMAGES / "blink.binary").read_bytes()).run(max_cycles=5 * 80_000_000)
    times = pin_times(result.trace, 16)
    assert len(times) == 20 and steady(times, QUARTER)
    assert result.trace.changes[-1][1] == 1 << 16       # only P16 is ever an output


def test_two_cogs_blink_at_their_own_rates_and_count_every_toggle_under_the_lock():
    image = (IMAGES / "two_cogs.binary").read_bytes()
    result = Chip(image).run()
    assert result.reason == "all cogs stopped"
    p16, p17 = pin_times(result.trace, 16), pin_times(result.trace, 17)
    assert len(p16) == 12 and steady(p16, QUARTER)
    assert len(p17) > 20 and steady(p17, 8_000_000)                    # clkfreq / 10
    vbase = ImageHeader.parse(image).vbase
    toggles = struct.unpack_from("<I", result.hub, vbase + 24 * 4)[0]     # after long stack[24]
    assert toggles == len(p16) + len(p17)                              # no update lost


def test_knight_rider_sweeps_one_lit_led_up_and_down():
    result = Chip((IMAGES / "knight_rider.binary").read_bytes()).run()
    assert result.reason == "all cogs stopped"
    lit = [out >> 16 & 0xFF for _, d, out in result.trace.changes if d >> 16 & 0xFF == 0xFF]
    sweep = [1 << k for k in range(7)] + [1 << k for k in range(7, 0, -1)]
    assert lit == [0] + sweep * 6 + [0]
