"""The UART framing of spinemu.bench.uart: encoder and decoder against each other and against the frame definition.

The frame (start bit, data LSB first, optional parity, stop bits) is the one
of every UART datasheet; bit k of a burst starts at ``start + floor(k *
clock / baud)``.  Random cases are seeded, so a failure repeats.
"""
from __future__ import annotations

import doctest
import importlib
import math
import random

import pytest

from spinemu.bench.uart import (Frame, UartDecoder, UartFormat, UartWaveform, decode_uart, frame_bits,
                                frame_cut_at_end, pin_changes)
from spinemu.trace import PinTrace


def feed_waveform(decoder: UartDecoder, wave: UartWaveform, until: int) -> None:
    """Hand the decoder every change of ``wave`` before ``until`` (found with next_change), then advance."""
    t = 0
    level = wave.level(0)
    if level != decoder.level:
        decoder.feed(0, level)
    while (t := wave.next_change(t)) is not None and t < until:
        decoder.feed(t, wave.level(t))
    decoder.advance(until)


@pytest.mark.parametrize("name", ["spinemu.bench.uart", "spinemu.bench.inputs", "spinemu.bench.terminal",
                                  "spinemu.bench.console", "spinemu.bench"])
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name))
    assert result.failed == 0


def test_frame_bits_follow_the_8n1_definition():
    assert frame_bits(0x55) == [0, 1, 0, 1, 0, 1, 0, 1, 0, 1]
    assert frame_bits(0x80, stop_bits=2) == [0] + [0] * 7 + [1] + [1, 1]
    assert frame_bits(0x03, data_bits=7, parity="even") == [0, 1, 1, 0, 0, 0, 0, 0, 0, 1]
    assert frame_bits(0x03, data_bits=7, parity="odd") == [0, 1, 1, 0, 0, 0, 0, 0, 1, 1]


def test_each_bit_of_a_burst_starts_at_the_floor_of_k_bit_times():
    clock, baud = 80_000_000, 115_200                # 694.44 cycles a bit
    wave = UartWaveform(UartFormat(baud), clock)
    start, end = wave.add(1000, b"\x00\xff")
    assert (start, end) == (1000, 1000 + (20 * clock) // baud)
    # byte 0: start bit and 8 zeros are low, the stop bit (bit 9) is high; byte 1's start bit is bit 10
    assert wave.next_change(1000) == 1000 + (9 * clock) // baud
    assert wave.next_change(1000 + (9 * clock) // baud) == 1000 + (10 * clock) // baud
    assert wave.next_change(1000 + (10 * clock) // baud) == 1000 + (11 * clock) // baud
    assert wave.next_change(1000 + (11 * clock) // baud) is None     # 0xFF and its stop bit are high to the end
    assert wave.level(999) == 1 and wave.level(1000) == 0 and wave.level(end) == 1


def test_next_change_is_exact_against_the_level_at_every_cycle():
    rng = random.Random(7)
    for _ in range(20):
        fmt = UartFormat(rng.choice([3, 7, 10, 13]) / 100 * 1000, data_bits=rng.choice([5, 6, 7, 8]),
                         parity=rng.choice([None, "even", "odd"]), stop_bits=rng.choice([1, 2]),
                         inverted=rng.random() < 0.5)
        wave = UartWaveform(fmt, clock_hz=1000)    # 7.7 to 33 cycles a bit
        t = rng.randrange(50)
        for _ in range(rng.randrange(1, 4)):
            _, t = wave.add(t + rng.choice([0, 0, rng.randrange(200)]), bytes(rng.randrange(256) for _ in range(3)))
        levels = [wave.level(c) for c in range(t + 50)]
        for c in range(t + 40):
            expected = next((k for k in range(c + 1, len(levels)) if levels[k] != levels[c]), None)
            assert wave.next_change(c) == expected, (fmt, c)


@pytest.mark.parametrize("seed", range(12))
def test_random_bytes_survive_encoding_and_decoding_at_random_bauds(seed):
    rng = random.Random(seed)
    clock = rng.choice([80_000_000, 1_000_000, 12_000_000, 96_000_000])
    baud = rng.choice([300, 1200, 9600, 19200, 57600, 115_200, 230_400, 1_000_000, 31_250.5])
    baud = min(baud, clock / 8)
    fmt = UartFormat(baud, data_bits=rng.choice([5, 6, 7, 8]), parity=rng.choice([None, "even", "odd"]),
                     stop_bits=rng.choice([1, 2]), inverted=rng.random() < 0.5)
    wave = UartWaveform(fmt, clock)
    sent = []
    t = 0
    for _ in range(4):
        data = bytes(rng.randrange(1 << fmt.data_bits) for _ in range(rng.randrange(1, 30)))
        _, t = wave.add(t + rng.choice([0, rng.randrange(5 * wave.frame_cycles())]), data)
        sent += data
    decoder = UartDecoder(fmt, clock)
    feed_waveform(decoder, wave, t + 1)
    assert [f.value for f in decoder.frames] == sent
    assert all(f.error is None for f in decoder.frames)


@pytest.mark.parametrize("off", [-0.03, 0.03])
def test_the_decoder_tolerates_a_transmitter_three_percent_off(off):
    clock = 80_000_000
    wave = UartWaveform(UartFormat(9600 * (1 + off)), clock)
    wave.add(500, b"The quick brown fox\r\n")
    decoder = UartDecoder(UartFormat(9600), clock)
    feed_waveform(decoder, wave, wave.end + 1)
    assert bytes(f.value for f in decoder.frames) == b"The quick brown fox\r\n"


def _line(changes, end, clock=1000, pin=0):
    """A trace of one driven pin with the given ``(cycle, level)`` changes."""
    trace = PinTrace(clock, [(0, 1 << pin, 1 << pin)], end_cycle=end)
    for c, v in changes:
        trace.record(c, 1 << pin, v << pin)
    return trace


def test_a_stop_bit_at_the_active_level_is_a_framing_error_and_a_break_waits_for_idle():
    fmt = UartFormat(100)                      # 10 cycles a bit at 1 kHz
    # 0x00 with its stop bit low, the line held low (a break) for 45 bits, then a good 'A'
    a = frame_bits(0x41)
    changes = [(100, 0), (550, 1)]
    t = 600
    for i, bit in enumerate(a):
        changes.append((t + 10 * i, bit))
    frames = decode_uart(_line(changes, 800), 0, fmt)
    assert frames[0] == Frame(100, 100 + 95, 0, "framing")
    assert [(f.value, f.error) for f in frames[1:]] == [(0x41, None)]


def test_a_glitch_shorter_than_half_a_bit_is_not_a_start_bit():
    fmt = UartFormat(100)
    frames = decode_uart(_line([(100, 0), (104, 1)], 400), 0, fmt)
    assert frames == []


def test_a_wrong_parity_bit_is_reported():
    fmt = UartFormat(100, data_bits=7, parity="even")
    bits = frame_bits(0x03, data_bits=7, parity="even")
    bits[8] ^= 1
    frames = decode_uart(_line([(100 + 10 * i, b) for i, b in enumerate(bits)], 300), 0, fmt)
    assert [(f.value, f.error) for f in frames] == [(0x03, "parity")]


def test_an_undriven_pin_reads_as_the_idle_level():
    trace = PinTrace(1000, [(0, 0, 0)], end_cycle=300)          # never driven: idle, no frame
    assert decode_uart(trace, 5, UartFormat(100)) == []
    assert decode_uart(trace, 5, UartFormat(100, inverted=True)) == []
    assert list(pin_changes([(0, 0, 0), (10, 1, 0), (20, 0, 0)], 0, idle=1)) == [(10, 0), (20, 1)]


@pytest.mark.parametrize("end, complete", [(100 + 94, False), (100 + 95, True)])
def test_a_frame_counts_once_its_stop_bit_is_sampled_before_the_end(end, complete):
    """'A' starting at 100 with 10-cycle bits: its stop bit starts at 190, its middle is at 195."""
    bits = frame_bits(0x41)
    trace = _line([(100 + 10 * i, b) for i, b in enumerate(bits)], end)
    frames = decode_uart(trace, 0, UartFormat(100))
    assert [f.value for f in frames] == ([0x41] if complete else [])
    assert frame_cut_at_end(trace, 0, UartFormat(100)) is (not complete)
    # hold_last: the line keeps its last level (the stop bit's) after the end
    assert [(f.value, f.error) for f in decode_uart(trace, 0, UartFormat(100), hold_last=True)] == [(0x41, None)]


def test_hold_last_reads_the_rest_of_a_cut_frame_at_the_last_level():
    bits = frame_bits(0x41)                    # 0, 1,0,0,0,0,0,1,0, 1
    trace = _line([(100 + 10 * i, b) for i, b in enumerate(bits[:3])], 125)   # cut in data bit 1 (low)
    assert decode_uart(trace, 0, UartFormat(100)) == []
    held = decode_uart(trace, 0, UartFormat(100), hold_last=True)
    assert [(f.value, f.error) for f in held] == [(0x01, "framing")]


@pytest.mark.parametrize("kw, word", [({"baud": 0}, "baud"), ({"baud": -5}, "baud"), ({"baud": math.nan}, "baud"),
                                      ({"baud": math.inf}, "baud"), ({"baud": True}, "baud"),
                                      ({"data_bits": 9}, "data bits"), ({"parity": "mark"}, "parity"),
                                      ({"stop_bits": 3}, "stop bits")])
def test_bad_formats_are_refused_with_the_field_named(kw, word):
    with pytest.raises(ValueError, match=word):
        UartFormat(**kw)


def test_a_baud_rate_faster_than_half_the_clock_is_refused():
    with pytest.raises(ValueError, match="too fast"):
        UartWaveform(UartFormat(600_000), clock_hz=1_000_000)
    UartWaveform(UartFormat(500_000), clock_hz=1_000_000)


@pytest.mark.parametrize("mode, fmt", [(84, UartFormat(9600)), (84 + 16384, UartFormat(9600, inverted=True)),
                                       (84 + 8192, UartFormat(9600, data_bits=7, parity="even")),
                                       (396, UartFormat(2400))])
def test_the_basic_stamps_serout_waveform_decodes_to_what_it_sent(tmp_path, mode, fmt):
    """SEROUT frames with the bench's framing; the decoder reads them back from the BS2's pin trace (1 MHz)."""
    from spinemu.pbasic import run_file

    src = tmp_path / "serout.bs2"
    src.write_text("' {$STAMP BS2}\n' {$PBASIC 2.5}\n"
                   f"SEROUT 3, {mode}, [\"Hi there\", CR, DEC 4242]\nPAUSE 10\nEND\n")
    result = run_file(str(src), seconds=1)
    assert result.serial_output[3] == b"Hi there\r4242"
    frames = decode_uart(result.trace, 3, fmt)
    assert [(f.value, f.error) for f in frames] == [(b, None) for b in b"Hi there\r4242"]
