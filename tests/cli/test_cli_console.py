"""The serial console on the command line: ``spinemu run --console*``, ``--baud`` and ``trace decode uart``.

Runs in-process (``main(argv, stdout, stderr)``) on spinemu's own bit-banged
serial programs (spin_src/examples, tests/data/bench).
"""
import io
import os
import sys
import time
from pathlib import Path

import pytest

from spinemu.cli import main

ROOT = Path(__file__).parent.parent.parent
BENCH = ROOT / "tests" / "data" / "bench"
EXAMPLES = ROOT / "spin_src" / "examples"
HELLO = EXAMPLES / "serial_hello.spin"
ECHO = EXAMPLES / "serial_echo.spin"
TWO_COGS = BENCH / "serial_two_cogs.spin"


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


def test_console_out_writes_every_byte_and_prints_the_text_live(tmp_path):
    target = tmp_path / "out.txt"
    code, out, err = run("run", HELLO, "--baud", "19200", "--console-out", target)
    assert code == 0, err
    assert target.read_bytes() == (BENCH / "serial_hello.spinsim.out").read_bytes()
    assert out.startswith("Hello from Spin!\n7 14 21 \n")          # the text first, then the summary
    assert "26 bytes received at 19200 baud" in out


def test_quiet_keeps_the_terminal_silent_but_still_writes_the_file(tmp_path):
    target = tmp_path / "out.txt"
    code, out, err = run("run", HELLO, "--baud", "19200", "--console-out", target, "-q")
    assert (code, out) == (0, "")
    assert target.read_bytes() == b"Hello from Spin!\r7 14 21 \r"


@pytest.mark.parametrize("engine", ["bytecode", "python"])
def test_console_in_sends_a_file_at_the_given_time_and_the_answer_comes_back(tmp_path, engine):
    numbers = tmp_path / "numbers.txt"
    numbers.write_bytes(b"12345\r")
    target = tmp_path / "out.txt"
    code, out, err = run("run", ECHO, "--baud", "9600", "--console-in", numbers, "--console-in-at", "0.05",
                         "--console-out", target, "--seconds", "0.3", "--engine", engine)
    assert code == 0, err
    assert target.read_bytes() == b"Number? Twice 12345 is 24690\rNumber? "
    assert "6 bytes sent" in out


def test_bytes_sent_after_the_run_ended_are_reported(tmp_path):
    numbers = tmp_path / "numbers.txt"
    numbers.write_bytes(b"7\r")
    code, out, err = run("run", ECHO, "--baud", "9600", "--console-in", numbers, "--console-in-at", "2",
                         "--seconds", "0.1", "-q")
    assert code == 0
    assert "the run ended before 2 of the 2 bytes" in err


def test_console_pins_and_baud_pick_another_port():
    code, out, err = run("run", TWO_COGS, "-L", EXAMPLES, "--console-pins", "0,1", "--baud", "19_200",
                         "--compat", "chip")
    assert code == 0, err
    assert out.startswith("1,2,3,4,5,6,7,8,9,10,11,12,\n")
    assert "P0: 28 bytes received" in out


def test_a_wrong_baud_rate_gives_framing_warnings_not_text(tmp_path):
    code, out, err = run("run", HELLO, "--baud", "38400", "-q", "--console-out", tmp_path / "x")
    assert code == 0
    assert "without a stop bit" in err and "--baud" in err


@pytest.mark.parametrize("args, message", [
    (["--baud", "nan"], "--baud: expected a number of bits per second of 1 or more"),
    (["--baud", "inf"], "--baud: expected a number of bits per second of 1 or more"),
    (["--baud", "0"], "--baud: expected a number of bits per second of 1 or more"),
    (["--baud", "1e-300"], "--baud: expected a number of bits per second of 1 or more"),
    (["--baud", "fast"], "--baud: expected a number of bits per second"),
    (["--baud", "50e6"], "too fast for a 80,000,000 Hz clock"),
    (["--console-pins", "30"], "expected two pin numbers TX,RX"),
    (["--console-pins", "30,32"], "pin 32 does not exist"),
    (["--console-pins", "5,5"], "must be different pins"),
    (["--console-in-at", "1"], "--console-in-at needs --console-in"),
    (["--console-in", "x.txt", "--console-in-at", "-1"], "seconds of 0 or more"),
    (["--console-in", "x.txt", "--console-in-at", "nan"], "seconds of 0 or more"),
])
def test_bad_console_numbers_get_a_clear_message(args, message):
    code, out, err = run("run", HELLO, *args)
    assert code == 2
    assert message in err and "Traceback" not in err


def test_a_missing_console_in_file_is_named():
    code, out, err = run("run", HELLO, "--console-in", "no_such_file.txt")
    assert code == 1
    assert "no_such_file.txt" in err and "cannot read" in err


def test_the_console_on_a_basic_stamp_program_needs_pins_it_has():
    code, out, err = run("run", ROOT / "spin_src" / "bs2" / "stepper_bs2.bs2", "--console")
    assert code == 2 and "--console-pins" in err
    code, out, err = run("run", ROOT / "spin_src" / "bs2" / "stepper_bs2.bs2", "--console", "--console-pins", "15,31")
    assert code == 2 and "pins 0..15" in err


def test_run_help_describes_the_console():
    code, out, err = run("run", "--help")
    assert code == 0
    for option in ("--console ", "--console-out", "--console-in ", "--console-in-at", "--console-pins", "--baud"):
        assert option in out
    assert "RX pin idles high" in out


def test_trace_decode_uart_reads_the_serial_text_from_a_trace(tmp_path):
    log = tmp_path / "two.log"
    assert run("run", TWO_COGS, "-L", EXAMPLES, "--trace", log, "-q")[0] == 0
    code, out, err = run("trace", "decode", "uart", log, "--pin", "0", "--baud", "19200", "--hold-last")
    assert (code, out, err) == (0, "1,2,3,4,5,6,7,8,9,10,11,12,\n", "")
    code, out, err = run("trace", "decode", "uart", log, "--pin", "0", "--baud", "19200")
    assert out == "1,2,3,4,5,6,7,8,9,10,11,12,\n" and "--hold-last" in err     # the CR was cut by the end
    code, out, err = run("trace", "decode", "uart", log, "--pin", "0", "--baud", "19200", "--frames", "--hold-last")
    lines = out.splitlines()
    assert len(lines) == 28 and lines[0].split()[-2:] == ["$31", "1"] and lines[-1].split()[-2] == "$0D"
    code, out, err = run("trace", "decode", "uart", log, "--pin", "0", "--baud", "9600")
    assert "without a stop bit" in err


@pytest.mark.parametrize("args, message", [(["--pin", "32"], "--pin 32 does not exist"),
                                           (["--pin", "0", "--baud", "1e9"], "too fast")])
def test_trace_decode_refuses_bad_pins_and_bauds(tmp_path, args, message):
    log = tmp_path / "t.log"
    log.write_text("0 00000000 00000000\n")
    code, out, err = run("trace", "decode", "uart", log, *args)
    assert code == 2 and message in err


@pytest.mark.skipif(os.name != "posix", reason="a pseudo-terminal stands in for the keyboard")
def test_keys_typed_on_a_terminal_reach_the_program_and_the_run_keeps_to_real_time(monkeypatch):
    import pty
    import threading

    master, slave = pty.openpty()
    with open(slave, "r", closefd=True) as fake_stdin:
        monkeypatch.setattr(sys, "stdin", fake_stdin)
        # typed 0.1 s of real time into the run, after the prompt (8 ms): timed from the console's
        # first tick, so that a slow start-up (compile, a loaded machine) does not eat into it
        typist = threading.Timer(0.1, os.write, (master, b"21\n"))
        from spinemu.bench.live import ConsoleLink
        tick = ConsoleLink._tick

        def first_tick_starts_typist(link, cycle):
            if not typist.is_alive() and not typist.finished.is_set():
                typist.start()
            tick(link, cycle)

        monkeypatch.setattr(ConsoleLink, "_tick", first_tick_starts_typist)
        t0 = time.monotonic()
        code, out, err = run("run", ECHO, "--baud", "9600", "--console", "--seconds", "0.25")
        wall = time.monotonic() - t0
        typist.join()
    os.close(master)
    assert code == 0, err
    assert out.startswith("Number? Twice 21 is 42\nNumber? \n")   # Enter arrives as CR
    assert "3 bytes sent" in out
    assert wall >= 0.25
