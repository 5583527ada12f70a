"""The same parts on the BASIC Stamp, with the commands it has for them (tests/data/bench/parts/*.bs2).

BUTTON and a button that bounces, RCTIME and an RC circuit, PULSOUT and a
servo, SHIFTOUT and SHIFTIN with an SPI monitor and a user-written shift
register part, SEROUT to a serial LCD, and SERIN reading a serial console.
"""
import math
from pathlib import Path

import pytest

import spinemu
from spinemu.bench import (Bench, Button, Led, RcCircuit, ReactivePart, SerialConsole, SerialLcd, Servo,
                           SpiMonitor)

PARTS = Path(__file__).parent.parent / "data" / "bench" / "parts"


def bs2(name, parts, seconds=1.0, **kw):
    return spinemu.run_bs2(PARTS / name, seconds=seconds, parts=parts, **kw)


def test_button_counts_presses_where_reading_each_millisecond_sees_the_bounce():
    button = Button(pin=3, presses=[(0.1, 0.2), (0.5, 0.6), (1.2, 1.3), (1.6, 1.7)], bounce=0.003)
    led = Led(pin=10)
    result = bs2("button.bs2", [button, led], seconds=3)
    assert result.reason == "end"
    assert result.var("presses") == 2                   # BUTTON: once per press
    assert result.var("edges") > 2                      # the first second's two presses bounced
    assert led.turned_on == 1 and not led.lit           # toggled twice
    assert not result.warnings                          # P3 is driven by the button: no floating input


def test_an_unconnected_button_pin_floats_and_is_warned_about():
    result = bs2("button.bs2", [Led(pin=10)], seconds=3)
    assert any("P3" in w.message and "no stimulus" in w.message for w in result.warnings)


def test_rctime_measures_the_decay_of_an_rc_circuit_on_a_bs2():
    rc = RcCircuit(pin=7, r=10e3, c=0.1e-6, vdd=5.0, threshold=1.4)
    result = bs2("rctime.bs2", [rc], seconds=4)
    # from 5 V x 10k/10.22k down to 1.4 V through 10 k and 0.1 uF: 1.2520 ms, in RCTIME's 2 us units
    assert result.debug_output == "626\n626\n626\n"
    assert rc.decay_seconds() == [pytest.approx(1.252e-3, abs=1e-6)] * 3


def test_rctime_of_a_potentiometer_follows_its_knob():
    from spinemu.bench import Potentiometer
    pot = Potentiometer(pin=7, r_max=10e3, position=[(0, 1.0), (0.5, 0.5), (1.5, 0.25)], vdd=5.0, threshold=1.4)
    result = bs2("rctime.bs2", [pot], seconds=4)
    readings = [int(x) for x in result.debug_output.split()]

    def units(r):                                       # charged to 5 V x r / (r + 220), down to 1.4 V
        return r * 0.1e-6 * math.log(5 * r / (r + 220) / 1.4) / 2e-6

    assert readings == [pytest.approx(units(r), abs=1) for r in (10e3, 5e3, 2.5e3)]


def test_pulsout_moves_a_servo_from_one_end_to_the_other():
    servo = Servo(pin=12)
    bs2("servo.bs2", [servo], seconds=3)
    assert len(servo.pulses) == 100
    assert {round(p.width / 1e3, 3) for p in servo.pulses} == {1.0, 2.0}     # 1 cycle = 1 us on the BS2
    assert servo.angle_at(1.0) == 0.0 and servo.angle == 180.0
    assert servo.angle_at(1.1) == pytest.approx((1.1 - servo.moves[-1][0] / 1e6) * 60 / 0.19, abs=0.01)


class ShiftIn165(ReactivePart):
    """A 74HC165 parallel-in shift register, written as a user would: load low latches ``value``, each
    rising clock edge shifts, the output is the register's top bit (what a part written outside
    spinemu looks like)."""

    kind = "74hc165"

    def __init__(self, *, clock, out, load, value, name=None):
        super().__init__(name=name)
        self.clock, self.out, self.load, self.value = clock, out, load, value

    def driven_pins(self):
        return (self.out,)

    def watched_pins(self):
        return (self.clock, self.load)

    def reset(self):
        self.s = (0, 0)                                 # register, clock level

    def on_drive(self, cycle, d, o):
        reg, clk = self.s
        c = (o >> self.clock) & 1
        loading = (d >> self.load) & 1 and not (o >> self.load) & 1
        if loading:
            reg = self.value
        elif c and not clk:
            reg = (reg << 1) & 0xFF
        self.s = (reg, c)
        self.output(cycle + 1, ((reg >> 7) & 1) << self.out)


def test_shiftout_is_spi_mode_0_and_shiftin_reads_a_user_written_part():
    spi = SpiMonitor(sclk=0, mosi=1)
    register = ShiftIn165(clock=0, out=4, load=5, value=0b1011_0010)
    result = bs2("shift.bs2", [spi, register])
    assert [w.mosi for w in spi.words[:2]] == [0xA5, 0x3C]
    assert result.debug_output == "B2\n"
    assert not result.warnings


def test_serout_writes_to_a_serial_lcd():
    lcd = SerialLcd(pin=15, baud=9600)
    bs2("serial_lcd.bs2", [lcd])
    assert lcd.text_lines() == ["Hello, BS2", "Line 2"] and not lcd.warnings


def test_serin_reads_what_a_serial_console_sends_on_its_pin():
    console = SerialConsole(tx=0, rx=1, baud=9600)
    console.send(b"21\r", at_seconds=0.02)
    result = bs2("serin.bs2", [console])
    assert console.text == "Number? Twice 21 is 42\n"
    assert result.serial_output == {0: b"Number? Twice 21 is 42\r"}


def test_serin_times_out_when_the_console_sends_nothing():
    console = SerialConsole(tx=0, rx=1, baud=9600)
    result = bs2("serin.bs2", [console], seconds=3)
    assert console.text == "Number? no answer\n"
    assert result.end_time == pytest.approx(0.0083 + 2.0 + 0.0104, abs=0.002)


def test_a_byte_sent_before_serin_listens_is_lost_as_on_the_wire():
    console = SerialConsole(tx=0, rx=1, baud=9600)
    console.send(b"5", at_seconds=0.001)                # while the program is still sending its prompt
    console.send(b"7\r", at_seconds=0.5)
    bs2("serin.bs2", [console])
    assert console.text == "Number? Twice 7 is 14\n"


def test_a_bench_is_one_object_for_several_bs2_parts():
    bench = Bench([Servo(pin=12), Led(pin=12 - 2)])
    bs2("servo.bs2", bench, seconds=3)
    assert bench.summary()[0].startswith("servo P12: 100 pulses")
