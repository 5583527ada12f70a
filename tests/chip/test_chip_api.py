"""Chip behaviour through the public API: modes, inputs, faults, images, PASM, determinism.

Programs are in tests/data/chip/behaviour (Spin source + the OpenSpin image).
"""
from __future__ import annotations

import os
import struct

import pytest

from spinemu.chip import Chip, RunResult
from spinemu.chip.inputs import PinStimulus
from spinemu.diagnostics import EmulationError, ImageError
from spinemu.image import image_checksum, to_eeprom

from chip_helpers import ROOT, article_image, read_bytes

BEHAVIOUR = os.path.join(ROOT, "tests", "data", "chip", "behaviour")


def image(name):
    return read_bytes(os.path.join(BEHAVIOUR, name + ".binary"))


def var_longs(img, hub, n):
    vbase = struct.unpack_from("<H", img, 8)[0]
    return [struct.unpack_from("<i", hub, vbase + 4 * i)[0] for i in range(n)]


@pytest.mark.parametrize("compat, expected", [
    ("chip", [0, 1, 2, 3, 4, 5, 6, 7, -1]),
    ("spinsim", [1, 2, 3, 4, 5, 6, 7, -1, -1]),     # spinsim keeps lock 0 for itself
])
def test_locknew_hands_out_locks_in_the_order_of_the_mode(compat, expected):
    img = image("locks")
    assert var_longs(img, Chip(img, compat=compat).run().hub, 9) == expected


def test_cog_reuse_clears_dira_and_outa_in_chip_mode():
    result = Chip(image("cog_reuse"), compat="chip").run()
    starts = [e[0] for e in result.cog_events if e[1] == 1 and e[2] == "start"]
    assert len(starts) == 2
    # pin 5 is driven by the first run of cog 1 only
    assert result.trace.state_at(starts[1] + 1000) == (0, 0)


def test_cog_reuse_keeps_dira_and_outa_in_spinsim_mode():
    result = Chip(image("cog_reuse"), compat="spinsim").run()
    starts = [e[0] for e in result.cog_events if e[1] == 1 and e[2] == "start"]
    assert result.trace.state_at(starts[1]) == (0x20, 0x20)


def test_a_new_cog_loads_for_about_8000_cycles_in_chip_mode_and_4_in_spinsim_mode():
    img = image("cog_reuse")
    chip = Chip(img, compat="chip").run().cog_events
    sim = Chip(img, compat="spinsim").run().cog_events
    first = lambda ev: next(e[0] for e in ev if e[1] == 1)   # noqa: E731
    assert first(chip) - first(sim) == 496 * 16 + 16 + 4


def test_waitcnt_in_the_past_waits_a_full_wrap():
    result = Chip(image("waitcnt_past")).run(max_cycles=(1 << 32) + 1_000_000)
    (t_dir, d, o), (t_out, d2, o2) = result.trace.changes[1:3]
    assert (d, o, d2, o2) == (1, 0, 1, 1)
    # t := cnt, then WAITCNT(t): CNT has moved on, so it waits for the next time round
    assert (1 << 32) <= t_out - t_dir <= (1 << 32) + 2_000
    assert t_out / 80_000_000 == pytest.approx(53.7, abs=0.1)


def test_undriven_pins_read_as_the_input_model_says():
    img = image("wait_input")
    assert Chip(img, inputs="pullup").run().trace.changes[-2][1] == 1        # passes at once
    low = Chip(img, inputs="pulldown").run(max_cycles=5_000_000)
    assert low.reason == "cycle limit" and low.trace.changes == [(0, 0, 0)]
    assert Chip(img, compat="chip").run().reason == "deadlock"              # nothing can ever change pin 3
    assert Chip(img, compat="spinsim").run().reason == "all cogs stopped"  # spinsim reads 1
    assert Chip(img).run().reason == "all cogs stopped"                     # the default is spinsim's


def test_a_pin_stimulus_wakes_waitpeq_at_its_edge():
    stim = PinStimulus([(1_000_000, 1 << 3, 1 << 3)])
    result = Chip(image("wait_input"), inputs=stim).run()
    t = result.trace.changes[1][0]
    assert 1_000_000 < t < 1_001_000


def test_a_callable_stimulus_is_polled():
    result = Chip(image("wait_input"), inputs=lambda cycle: (1 << 3) if cycle >= 500_000 else 0).run()
    assert 500_000 < result.trace.changes[1][0] < 502_000


def test_a_pasm_cog_started_from_spin_runs_and_is_reported():
    result = Chip(image("pasm_cog")).run()
    assert not result.warnings and result.reason == "all cogs stopped"
    # its `mov dira, #1` makes P0 an output (the first instruction after the start),
    # then it waits 100_000 cycles and stops: P0 floats
    (t0, d0, o0), (t1, d1, o1) = result.trace.changes[1:3]
    assert (t0, d0, o0, d1, o1) == (908, 1, 0, 0, 0) and 100_000 < t1 - t0 < 100_100
    start = [e for e in result.cog_events if e[1] == 1 and e[2] == "start"]
    assert start and "PASM at $00" in start[0][3]
    assert result.stats["pasm_instructions_per_cog"] == {1: 6}


def test_an_eeprom_image_runs_like_the_binary():
    binary = article_image("as_printed_simple_stepper")
    a = Chip(binary).run(max_cycles=20_000_000)
    b = Chip(to_eeprom(binary)).run(max_cycles=20_000_000)
    assert a.trace.changes == b.trace.changes and a.hub == b.hub


@pytest.mark.parametrize("data", [b"", b"\x00" * 10, b"\x00" * 64])
def test_bad_images_raise_image_error(data):
    with pytest.raises(ImageError):
        Chip(data)


def test_a_corrupted_checksum_is_an_image_error():
    bad = bytearray(article_image("as_printed_simple_stepper"))
    bad[0x20] ^= 0xFF
    with pytest.raises(ImageError, match="checksum"):
        Chip(bytes(bad))


def _patched(img: bytes, addr: int, value: int) -> bytes:
    data = bytearray(img)
    data[addr] = value
    data[5] = image_checksum(bytes(data))
    return bytes(data)


def test_unknown_bytecode_names_cog_address_and_source_line():
    img = article_image("as_printed_simple_stepper")
    pcurr = struct.unpack_from("<H", img, 0x0C)[0]
    bad = _patched(img, pcurr, 0x3C)
    chip = Chip(bad, source_map=lambda addr: ("simple_stepper.spin", 31) if addr == pcurr else None)
    with pytest.raises(EmulationError) as err:
        chip.run(max_cycles=1_000_000)
    text = str(err.value)
    assert "unknown bytecode $3C" in text and "cog 0" in text and f"${pcurr:04X}" in text
    assert text.startswith("simple_stepper.spin:31:")


def test_stack_overflow_past_hub_ram_is_an_emulation_error():
    with pytest.raises(EmulationError, match="stack"):
        Chip(image("deep_recursion")).run()


def test_runs_are_deterministic():
    img = article_image("corrected_stepper_demo")
    a = Chip(img).run(max_cycles=100_000_000)
    b = Chip(img).run(max_cycles=100_000_000)
    assert (a.trace.changes, a.hub, a.end_cycle) == (b.trace.changes, b.hub, b.end_cycle)


def test_run_result_fields_and_progress():
    seen = []
    result = Chip(article_image("as_printed_simple_stepper")).run(max_cycles=50_000_000, progress=seen.append)
    assert isinstance(result, RunResult)
    assert len(result.hub) == 32768 and result.reason == "cycle limit"
    assert result.trace.changes[0] == (0, 0, 0)
    assert result.stats["bytecodes"] == result.stats["bytecodes_per_cog"][0] > 0
    assert result.cog_events[0][:3] == (0, 0, "start")
    assert seen and seen == sorted(seen)


def test_a_chip_runs_once():
    chip = Chip(article_image("as_printed_simple_stepper"))
    chip.run(max_cycles=1000)
    with pytest.raises(RuntimeError):
        chip.run(max_cycles=1000)


def test_compat_and_inputs_are_checked():
    img = article_image("as_printed_simple_stepper")
    with pytest.raises(ValueError):
        Chip(img, compat="p2")
    with pytest.raises(ValueError):
        Chip(img, inputs="floating")


def test_reboot_ends_the_run():
    result = Chip(image("reboot")).run()
    assert result.reason == "reboot"
    assert result.trace.changes[-1][1] == 1          # pin 0 driven, pin 1 never


def test_waitvid_waits_one_frame_of_vscl_clocks_per_call():
    img = image("waitvid")
    t0, t1 = var_longs(img, Chip(img).run().hub, 2)
    assert 3 * 1_000 <= t1 - t0 < 3 * 1_000 + 1_000


def test_a_busy_loop_on_a_variable_another_cog_changes_is_parked_and_woken_exactly():
    img = read_bytes(os.path.join(ROOT, "tests", "data", "chip", "programs", "cogs_share_variable.binary"))
    for compat in ("chip", "spinsim"):
        fast = Chip(img, compat=compat).run()
        slow = Chip(img, compat=compat, fast_forward=False).run()
        assert fast.stats["busy_loops_learned"] > 0 and fast.stats["bytecodes_skipped"] > 1000
        assert (fast.trace.changes, fast.hub, fast.end_cycle) == (slow.trace.changes, slow.hub, slow.end_cycle)
        assert fast.stats["bytecodes_per_cog"] == slow.stats["bytecodes_per_cog"]


def test_a_cog_whose_engine_is_an_object_is_run_by_that_engine():
    # the extension point of spinemu.translate: engine.run(cog, until) advances the cog
    chip = Chip(article_image("as_printed_simple_stepper"))
    calls = []

    class Engine:
        def key(self, c):               # when the cog next touches shared state
            return c.t

        def run(self, c, until):
            calls.append((c.id, c.t, until))
            c.t += 1_000
            if len(calls) == 5:
                chip.stop_cog(c, c.t, "the engine is done")

    chip._boot()
    chip.cogs[0].engine = Engine()
    result = chip.run(max_cycles=1_000_000)
    assert result.reason == "all cogs stopped" and len(calls) == 5
    assert [t for _, t, _ in calls] == [calls[0][1] + 1_000 * k for k in range(5)]
    assert all(until == 1_000_000 for _, _, until in calls)
