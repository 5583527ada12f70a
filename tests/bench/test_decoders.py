"""The protocol decoders reproduce known frames from generated traces: I2C, SPI (modes 0-3), pulses.

Signals come from the modules' own generators (``i2c_levels``, ``spi_levels``)
and from random frames, turned into :class:`~spinemu.trace.PinTrace` logs the
way a run records them; violations are planted and must be reported at their
cycle.
"""
import random

import pytest

from spinemu.bench.annotations import read_annotations, write_annotations
from spinemu.bench.i2c import I2cDecoder, decode_i2c, i2c_levels
from spinemu.bench.pwm import decode_pulses, pulse_stats
from spinemu.bench.spi import SpiDecoder, decode_spi, spi_levels
from spinemu.trace import PinTrace, read_log


def trace_of(levels, pins, clock_hz=80_000_000, open_drain=False):
    """A pin trace of ``(cycle, level, level, ...)`` rows on ``pins``; ``open_drain``: a 1 is released (undriven)."""
    t = PinTrace(clock_hz)
    t.record(0, 0, 0)
    for cycle, *lv in levels:
        d = o = 0
        for p, v in zip(pins, lv):
            if open_drain and v:
                continue
            d |= 1 << p
            o |= v << p
        t.record(cycle, d, o)
    t.end_cycle = levels[-1][0] + 10
    return t


def test_i2c_transfers_with_addresses_directions_data_and_acks_round_trip():
    rng = random.Random(5)
    transfers = [(rng.randrange(128), rng.random() < 0.5, bytes(rng.randrange(256) for _ in range(rng.randrange(6))))
                 for _ in range(20)]
    acks = [rng.randrange(2) for _ in range(sum(1 + len(d) for _, _, d in transfers))]
    trace = trace_of(i2c_levels(transfers, half_bit=37, acks=acks), (28, 29), open_drain=True)
    d = decode_i2c(trace, 28, 29)
    assert [(x.address, x.read, bytes(x.data)) for x in d.transfers] == [(a, r, b) for a, r, b in transfers]
    got_acks = [a for x in d.transfers for a in [x.acked] + x.acks]
    assert got_acks == [not a for a in acks]
    assert [x.restart for x in d.transfers] == [False] + [True] * 19
    assert [x.stopped for x in d.transfers] == [False] * 19 + [True]
    assert not d.violations


def test_i2c_text_shows_nak_bytes():
    d = I2cDecoder()
    for t, scl, sda in i2c_levels([(0x50, True, b"\x12\x34")], half_bit=5, acks=[0, 0, 1]):
        d.feed(t, scl, sda)
    assert d.transfers[0].text() == "0x50 R ACK: 12 34!"


def test_an_i2c_start_in_the_middle_of_a_byte_is_a_violation_at_its_cycle():
    levels = i2c_levels([(0x50, False, b"\xAA")], half_bit=10)
    # cut the data byte after 3 bits: SDA high, SCL high, then SDA falls (a START)
    cut = levels[:2 + 18 + 2 * 3]
    t = cut[-1][0]
    cut += [(t + 10, 0, 1), (t + 20, 1, 1), (t + 30, 1, 0)]
    d = I2cDecoder()
    for c, scl, sda in cut:
        d.feed(c, scl, sda)
    assert d.violations == [(t + 30, "I2C repeated START in the middle of a byte (after 4 bits)")]


def test_a_start_or_stop_after_the_setup_clock_alone_is_no_violation():
    d = I2cDecoder()
    for c, scl, sda in i2c_levels([(0x50, False, b"\x01"), (0x51, True, b"")], half_bit=10):
        d.feed(c, scl, sda)
    assert not d.violations and len(d.transfers) == 2


@pytest.mark.parametrize("mode", [0, 1, 2, 3])
@pytest.mark.parametrize("lsb_first", [False, True])
def test_spi_words_round_trip_in_every_mode(mode, lsb_first):
    rng = random.Random(mode * 2 + lsb_first)
    words = [rng.randrange(256) for _ in range(12)]
    miso = [rng.randrange(256) for _ in range(12)]
    levels = spi_levels(words, mode=mode, half_bit=20, miso_words=miso, lsb_first=lsb_first)
    trace = trace_of(levels, (0, 1, 2, 3))
    d = decode_spi(trace, 0, 1, 2, 3, mode=mode, lsb_first=lsb_first)
    assert [w.mosi for w in d.words] == words and [w.miso for w in d.words] == miso
    assert not d.violations


@pytest.mark.parametrize("mode", [1, 3])
def test_spi_read_on_the_leading_edge_in_a_cpha_1_mode_gives_other_words(mode):
    # CPHA 1 shifts a bit out just after the leading edge: read there, it is the previous bit
    # (CPHA 0 data are steady over both edges, so the other phase reads them alike)
    words = [0x5A, 0xC3, 0x0F]
    trace = trace_of(spi_levels(words, mode=mode, half_bit=20), (0, 1, 2, 3))
    other = mode ^ 1
    assert [w.mosi for w in decode_spi(trace, 0, 1, 2, 3, mode=other).words] != words


def test_spi_without_chip_select_counts_words_from_the_first_clock_and_12_bit_words_work():
    levels = spi_levels([0xABC, 0x123], mode=0, bits=12, half_bit=15)
    d = SpiDecoder(mode=0, bits=12, has_cs=False, has_miso=False)
    for c, sclk, mosi, miso, cs in levels:
        d.feed(c, sclk, mosi)
    assert [w.mosi for w in d.words] == [0xABC, 0x123] and d.words[0].miso is None


def test_a_chip_select_that_cuts_a_word_short_is_a_violation():
    levels = spi_levels([0xFF], mode=0, half_bit=10)
    cut = [row for row in levels if row[0] <= levels[1][0] + 3 * 20 + 5]      # select and 3 clocks
    t = cut[-1][0] + 10
    cut.append((t, 0, 0, 0, 1))
    d = SpiDecoder(mode=0)
    for row in cut:
        d.feed(*row)
    assert d.violations == [(t, "SPI chip select ended a word after 3 of 8 bits")] and not d.words


def test_pulses_give_widths_periods_and_duty():
    clock = 1_000_000
    rows, t = [], 1000
    widths = [1000, 1500, 2000, 1250]
    for w in widths:
        rows += [(t, 1), (t + w, 0)]
        t += 20_000
    trace = trace_of(rows, (5,), clock_hz=clock)
    d = decode_pulses(trace, 5)
    assert [p.width for p in d.pulses] == widths
    assert [p.period for p in d.pulses] == [20_000] * 3 + [None]
    st = pulse_stats(d.pulses, clock)
    assert (st["min_width"], st["max_width"]) == (1e-3, 2e-3) and st["duty"] == pytest.approx(0.075)
    low = decode_pulses(trace, 5, active=0)
    assert [p.width for p in low.pulses] == [19_000, 18_500, 18_000]


def test_decoders_refuse_pins_the_trace_does_not_have():
    trace = PinTrace(1_000_000, [(0, 0, 0)], 10, pin_count=16)
    for call in (lambda: decode_i2c(trace, 15, 16), lambda: decode_spi(trace, 20, 1), lambda: decode_pulses(trace, 16)):
        with pytest.raises(ValueError, match="does not exist"):
            call()


def test_annotations_round_trip_and_name_vcd_times():
    import io
    frames = [(1000, 2000, "S 0x50 W ACK: 01 P"), (5000, 7000, "S 0x50 R NAK")]
    buf = io.StringIO()
    write_annotations(buf, frames, 80_000_000, "i2c", [28, 29])
    text = buf.getvalue()
    assert "VCD time unit 100 ps (125 per cycle)" in text
    assert read_annotations(text) == frames
    assert text.splitlines()[3].split("\t")[2] == str(1000 * 125)


def test_a_logged_trace_decodes_as_the_one_in_memory(tmp_path):
    trace = trace_of(i2c_levels([(0x3C, False, b"hi")], half_bit=50), (28, 29), open_drain=True)
    log = tmp_path / "i2c.log"
    log.write_text(trace.log_text())
    again = read_log(log.read_text())
    assert [x.text() for x in decode_i2c(again, 28, 29).transfers] == ["0x3C W ACK: 68 69"]
