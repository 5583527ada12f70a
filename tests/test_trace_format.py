"""Pin-trace files: the log format of the reference traces and VCD for waveform viewers."""
import pytest

from spinemu.trace import PinTrace, TraceFormatError, read_log, vcd_timescale


def test_log_round_trips_the_reference_format():
    text = "4 00000000 00000000\n1000 0000001f 00000000\n1608 0000001f 00000001\n"
    assert read_log(text).log_text() == text


def test_malformed_log_line_names_its_line():
    with pytest.raises(TraceFormatError) as e:
        read_log("4 00000000 00000000\n12 zz\n")
    assert e.value.line == 2


def test_vcd_has_one_wire_per_driven_pin_and_z_while_undriven():
    t = PinTrace(80_000_000, [(0, 0, 0), (1000, 0x3, 0x1), (2000, 0x1, 0x1)], end_cycle=3000)
    vcd = t.vcd_text()
    assert "$timescale 100 ps $end" in vcd
    assert vcd.count("$var wire 1") == 2
    assert "$var wire 1 ! P0 $end" in vcd and '$var wire 1 " P1 $end' in vcd
    body = vcd.split("$enddefinitions $end\n")[1]
    assert body.startswith("#0\n$dumpvars\nz!\nz\"\n$end\n")
    assert "#125000\n1!\n0\"\n" in body          # cycle 1000 at 12.5 ns
    assert "#250000\nz\"\n" in body               # P1 released
    assert body.rstrip().endswith("#375000")


def test_vcd_timescale_is_whole_units_per_cycle():
    assert vcd_timescale(80_000_000) == ("100 ps", 125)
    assert vcd_timescale(1_000_000) == ("1 us", 1)
    assert vcd_timescale(5_000_000) == ("100 ns", 2)


def test_edge_counts_ignore_float_transitions():
    t = PinTrace(1000, [(0, 0, 0), (1, 1, 0), (2, 1, 1), (3, 1, 0), (4, 0, 0), (5, 1, 1)])
    assert t.edge_counts() == {0: 2}
