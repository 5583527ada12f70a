"""The bench on the command line: ``run --bench/--input/--eeprom-out/--view`` on every engine, and
``trace decode i2c|spi|pwm`` with annotation files."""
import io
import struct
import time
from pathlib import Path

import pytest

from spinemu.cli import main
from spinemu.trace import read_log

ROOT = Path(__file__).parent.parent.parent
PARTS = ROOT / "tests" / "data" / "bench" / "parts"
DEMO = ROOT / "spin_src" / "examples" / "bench_demo.spin"


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


def test_the_demo_board_summary_says_what_each_part_did():
    code, out, err = run("run", DEMO, "--bench", DEMO.with_suffix(".toml"), "--seconds", "1")
    assert code == 0, err
    assert "button P0: pressed 3 times, bouncing 2 ms" in out
    assert "LED P16: turned on 2 times" in out
    assert "LCD 2x16: 'Presses: 3' / 'Servo: 1000 us'" in out
    assert "servo P17: 49 pulses" in out


@pytest.mark.parametrize("engine", ["bytecode", "python"])
def test_the_column_demo_shows_its_step_counts_per_run(engine):
    code, out, err = run("run", ROOT / "spin_src" / "stepper_demo.spin", "--bench", ROOT / "spin_src" / "stepper_board.toml",
                         "--engine", engine)
    assert code == 0, err
    text = " ".join(out.split())
    assert "stepper P1-P4: 880 steps (full-step (two-coil))" in text
    assert "steps per run: +88 -88 +88 -88 +88 -88 +88 -88 +88 -88" in text


def test_eeprom_out_saves_what_the_program_wrote_and_the_saved_file_boots_with_it(tmp_path):
    first, second = tmp_path / "first.eeprom", tmp_path / "second.eeprom"
    hub = tmp_path / "hub.bin"
    code, out, err = run("run", PARTS / "boot_count.spin", "--eeprom-out", first, "--seconds", "0.05")
    assert code == 0, err and f"saved to {first}" in " ".join(out.split())
    code, out, err = run("run", first, "--eeprom-out", second, "--seconds", "0.05", "--dump-hub", hub)
    assert code == 0, err
    from spinemu.compiler import compile_file
    vbase = struct.unpack_from("<H", compile_file(str(PARTS / "boot_count.spin")).binary, 8)[0]
    assert struct.unpack_from("<i", hub.read_bytes(), vbase)[0] == 2
    assert struct.unpack_from("<i", second.read_bytes(), vbase)[0] == 2
    assert len(second.read_bytes()) == 32768


def test_an_eeprom_target_runs_with_its_boot_eeprom_and_the_trace_decodes_as_i2c(tmp_path):
    image, log, notes = tmp_path / "rw.eeprom", tmp_path / "rw.log", tmp_path / "rw.i2c.txt"
    assert run("compile", PARTS / "eeprom_rw.spin", "-e", image)[0] == 0
    code, out, err = run("run", image, "--trace", log, "--seconds", "0.05")
    assert code == 0, err
    assert "EEPROM 24LC256 P28/P29: 5 bytes written" in " ".join(out.split())
    code, out, err = run("trace", "decode", "i2c", log, "--pins", "28,29", "--annotations", notes)
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].endswith("S 0x50 W ACK: 7F 00 07 0A 0D 10 13 P")
    assert lines[-1].endswith("Sr 0x50 R ACK: 07 0A 0D 10 13! P")              # after the address, a repeated START
    from spinemu.bench.annotations import read_annotations
    frames = read_annotations(notes.read_text())
    assert len(frames) == len(lines) and frames[-1][2] == "Sr 0x50 R ACK: 07 0A 0D 10 13! P"


def test_trace_decode_spi_and_pwm_on_basic_stamp_traces(tmp_path):
    log = tmp_path / "shift.log"
    code, out, err = run("run", PARTS / "shift.bs2", "--trace", log, "--seconds", "1")
    assert code == 0, err
    code, out, err = run("trace", "decode", "spi", log, "--pins", "0,1", "--clock", "1000000")
    assert code == 0, err
    assert [line.split()[-1] for line in out.splitlines()][:2] == ["A5", "3C"]
    log = tmp_path / "servo.log"
    assert run("run", PARTS / "servo.bs2", "--trace", log, "--seconds", "3")[0] == 0
    code, out, err = run("trace", "decode", "pwm", log, "--pins", "12", "--clock", "1000000")
    widths = {line.split("width ")[1].split()[0] for line in out.splitlines()}
    assert code == 0 and widths == {"1.0000", "2.0000"} and len(out.splitlines()) == 100


@pytest.mark.parametrize("args, message", [
    (["i2c", "--pins", "28"], "needs --pins SCL,SDA"),
    (["spi", "--pins", "0,1,2,3,4"], "needs --pins SCLK,MOSI"),
    (["pwm"], "needs --pins N"),
    (["i2c", "--pins", "28,x"], "--pins: expected pin numbers"),
    (["uart"], "needs --pin N"),
])
def test_trace_decode_says_which_pins_it_needs(tmp_path, args, message):
    log = tmp_path / "t.log"
    log.write_text("0 00000000 00000000\n")
    code, out, err = run("trace", "decode", args[0], log, *args[1:])
    assert code == 2 and message in err


def test_protocol_violations_of_parts_are_warnings_not_tracebacks(tmp_path):
    board = tmp_path / "board.toml"
    board.write_text('[[part]]\ntype = "servo"\npin = 17\n')
    code, out, err = run("run", PARTS / "servo_sweep.spin", "--bench", board, "--seconds", "2")
    assert code == 0, err
    assert "warning: servo P17: pulse of 2.980 ms is outside the servo's 0.5-2.5 ms: ignored (at 0.5" in err
    assert "Traceback" not in err


def test_a_bench_file_mistake_is_an_error_with_file_line_and_caret(tmp_path):
    board = tmp_path / "board.toml"
    board.write_text('[[part]]\ntype = "led"\npin = 3\n\n[[part]]\ntype = "buton"\npin = 4\n')
    code, out, err = run("run", DEMO, "--bench", board)
    assert code == 1
    assert "board.toml:6:8: error: there is no part of type 'buton'" in err and "^~~~~~~" in err
    board.write_text('[[part]]\ntype = "led"\npin = 20\n')
    code, out, err = run("run", PARTS / "servo.bs2", "--bench", board)
    assert code == 1 and "pin 20 does not exist on the BASIC Stamp (pins are 0..15)" in err


def test_the_basic_stamp_takes_a_bench_and_input_like_the_propeller(tmp_path):
    board = tmp_path / "board.toml"
    board.write_text('[[part]]\ntype = "servo"\npin = 12\n\n[[part]]\ntype = "led"\npin = 3\n')
    code, out, err = run("run", PARTS / "servo.bs2", "--bench", board, "--seconds", "3", "--input", "P3=1")
    assert code == 0, err
    assert "servo P12: 100 pulses 1.000-2.000 ms; at 180.0°" in out


def test_input_mistakes_read_alike_for_both_engines():
    for target in (DEMO, PARTS / "servo.bs2"):
        code, out, err = run("run", target, "--input", "P3=2")
        assert code == 2 and "--input: cannot read 'P3=2'; expected e.g. 'P3=1'" in err


def test_a_console_on_basic_stamp_pins_talks_to_serin_and_serout(tmp_path):
    answer = tmp_path / "answer.txt"
    numbers = tmp_path / "numbers.txt"
    numbers.write_bytes(b"21\r")
    code, out, err = run("run", PARTS / "serin.bs2", "--console-pins", "0,1", "--baud", "9600",
                         "--console-in", numbers, "--console-in-at", "0.02", "--console-out", answer)
    assert code == 0, err
    assert answer.read_bytes() == b"Number? Twice 21 is 42\r"


def test_view_shows_the_parts_and_keeps_to_real_time():
    t0 = time.monotonic()
    code, out, err = run("run", DEMO, "--bench", DEMO.with_suffix(".toml"), "--seconds", "0.3", "--view")
    assert code == 0, err
    assert time.monotonic() - t0 >= 0.3
    assert "|Presses: 1" in out and "LED P16" in out


def test_trace_of_a_bench_run_records_the_parts_levels(tmp_path):
    log = tmp_path / "demo.log"
    code, out, err = run("run", DEMO, "--bench", DEMO.with_suffix(".toml"), "--seconds", "0.3", "--trace", log)
    assert code == 0, err
    trace = read_log(log.read_text())
    assert [c for c, v in trace.pin_levels(0) if v == "1"][0] == 16_000_000    # the button, pressed at 0.2 s
    assert trace.changes[0][1] & 1                      # P0 is driven by the button from the start
