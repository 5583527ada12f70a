"""Bench files: parts from TOML, and every mistake reported at its file, line and column with a caret."""
from pathlib import Path

import pytest

from spinemu.bench import Button, Lcd, Led, Servo
from spinemu.bench.benchfile import load_bench, read_bench
from spinemu.diagnostics import SpinError

ROOT = Path(__file__).parent.parent.parent


def error(text, **kw):
    with pytest.raises(SpinError) as e:
        read_bench(text, "board.toml", **kw)
    return e.value


def test_the_demo_bench_file_gives_its_four_parts():
    bench = load_bench(str(ROOT / "spin_src" / "examples" / "bench_demo.toml"))
    assert [type(p) for p in bench.parts] == [Button, Led, Servo, Lcd]
    button = bench.parts[0]
    assert button.presses == [(0.2, 0.3), (0.45, 0.55), (0.7, 0.8)] and button.bounce == 0.002
    assert bench.parts[3].data == (10, 11, 12, 13)


def test_an_unknown_part_type_is_named_with_a_caret_under_it():
    e = error('[[part]]\ntype = "laser"\npin = 3\n')
    assert (e.path, e.line, e.column) == ("board.toml", 2, 8)
    assert "there is no part of type 'laser'" in e.message and "led" in e.message
    assert e.render().splitlines() == [
        "board.toml:2:8: error: " + e.message, 'type = "laser"', "       ^~~~~~~"]


def test_an_unknown_parameter_lists_the_ones_the_part_has():
    e = error('[[part]]\ntype = "led"\npin = 3\ncolour = "red"\n')
    assert (e.line, e.column) == (4, 10)
    assert "a led has no parameter 'colour'; its parameters are pin, active, name" in e.message


def test_a_missing_parameter_is_reported_at_the_part():
    e = error('# my board\n\n[[part]]\ntype = "servo"\n')
    assert (e.line, e.column) == (3, 1) and "a servo needs 'pin'" in e.message


def test_a_part_without_a_type_is_reported_at_its_table():
    e = error('[[part]]\ntype = "led"\npin = 1\n\n[[part]]\npin = 2\n')
    assert e.line == 5 and "has no 'type'" in e.message


@pytest.mark.parametrize("text, pins, line, what", [
    ('[[part]]\ntype = "led"\npin = 32\n', 32, 3, "pin 32 does not exist on the Propeller (pins are 0..31)"),
    ('[[part]]\ntype = "led"\npin = 20\n', 16, 3, "pin 20 does not exist on the BASIC Stamp (pins are 0..15)"),
    ('[[part]]\ntype = "lcd"\nrs = 0\ne = 1\ndata = [2, 3, 4, 40]\n', 32, 5, "pin 40 does not exist"),
    ('[[part]]\ntype = "led"\npin = -1\n', 32, 3, "pin -1 does not exist"),
])
def test_a_pin_the_engine_does_not_have_is_reported_at_its_value(text, pins, line, what):
    engine = "the BASIC Stamp" if pins == 16 else "the Propeller"
    e = error(text, pin_count=pins, engine=engine)
    assert e.line == line and what in e.message


def test_a_default_pin_the_engine_lacks_is_reported_at_the_part():
    e = error('[[part]]\ntype = "eeprom"\n', pin_count=16, engine="the BASIC Stamp")
    assert e.line == 1 and "EEPROM 24LC256 P28/P29: P28 does not exist on the BASIC Stamp" in e.message


def test_two_parts_driving_one_pin_are_reported_at_the_second():
    e = error('[[part]]\ntype = "button"\npin = 28\n\n[[part]]\ntype = "eeprom"\nchip = "24LC512"\n'
              'scl = 28\nsda = 29\n')
    assert (e.line, e.column) == (8, 7)
    assert "P28 is driven by two parts: button P28 and EEPROM 24LC512 P28/P29" in e.message


def test_a_value_a_part_refuses_is_reported_at_that_value():
    e = error('[[part]]\ntype = "servo"\npin = 1\nspeed = -5\n')
    assert e.line == 4 and "servo: speed must be above 0" in e.message
    e = error('[[part]]\ntype = "eeprom"\nchip = "24C02"\n')
    assert e.line == 3 and "chip must be one of 24LC256, 24LC512" in e.message


def test_a_toml_syntax_error_keeps_its_line_and_column():
    e = error('[[part]]\ntype = "led"\npin = = 3\n')
    assert e.line == 3 and "not a valid bench file" in e.message


def test_only_part_tables_are_allowed():
    e = error('board = "demo"\n[[part]]\ntype = "led"\npin = 1\n')
    assert e.line == 1 and "'board' is not one" in e.message


def test_a_user_part_class_in_a_python_file_next_to_the_bench_file(tmp_path):
    (tmp_path / "myparts.py").write_text(
        "from spinemu.bench import Part\n"
        "class Beeper(Part):\n"
        "    kind = 'beeper'\n"
        "    def __init__(self, *, pin, pitch=440, name=None):\n"
        "        super().__init__(name=name)\n"
        "        self.pin, self.pitch = pin, pitch\n"
        "    def watched_pins(self):\n"
        "        return (self.pin,)\n"
        "class NotAPart:\n"
        "    pass\n")
    board = tmp_path / "board.toml"
    board.write_text('[[part]]\ntype = "myparts.py:Beeper"\npin = 4\npitch = 880\n')
    (part,) = load_bench(str(board)).parts
    assert (type(part).__name__, part.pin, part.pitch, part.name) == ("Beeper", 4, 880, "beeper P4")
    board.write_text('[[part]]\ntype = "myparts.py:Nothing"\npin = 4\n')
    with pytest.raises(SpinError, match="cannot load the part class 'myparts.py:Nothing'") as e:
        load_bench(str(board))
    assert e.value.line == 2
    board.write_text('[[part]]\ntype = "myparts.py:NotAPart"\n')
    with pytest.raises(SpinError, match="'myparts.py:NotAPart' is not a part"):
        load_bench(str(board))


def test_an_eeprom_data_file_is_relative_to_the_bench_file(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "content.bin").write_bytes(b"\x01\x02\x03")
    board = tmp_path / "sub" / "board.toml"
    board.write_text('[[part]]\ntype = "eeprom"\ndata = "content.bin"\n')
    (eeprom,) = load_bench(str(board)).parts
    assert bytes(eeprom.memory[:4]) == b"\x01\x02\x03\xff" and eeprom.data_given
    board.write_text('[[part]]\ntype = "eeprom"\ndata = "missing.bin"\n')
    with pytest.raises(SpinError, match="No such file") as e:
        load_bench(str(board))
    assert e.value.line == 3


def test_a_missing_bench_file_is_named():
    with pytest.raises(SpinError, match="cannot read the bench file"):
        load_bench("no/such/board.toml")
