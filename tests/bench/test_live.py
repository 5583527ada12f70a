"""ConsoleLink: a console's output as it arrives, keys typed sent to the program, the run kept to real time."""
from __future__ import annotations

import io
import os
import time

from spinemu.bench import SerialConsole
from spinemu.bench.live import ConsoleLink, Keyboard, keyboard_available
from spinemu.chip import Chip
from spinemu.compiler import compile_file

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ECHO = os.path.join(ROOT, "spin_src", "examples", "serial_echo.spin")


class ScriptedKeys:
    """A keyboard on which keys are typed at given reports of the chip (not at wall-clock times)."""

    def __init__(self, script):
        self.script = dict(script)          # report number -> keys
        self.reports = 0

    def read(self, wait: float = 0.0) -> bytes:
        if wait:
            time.sleep(wait)
            return b""
        self.reports += 1
        return self.script.pop(self.reports, b"")


def test_keys_typed_while_the_program_waits_are_answered_and_nothing_arrives_late():
    image = compile_file(ECHO).binary
    console = SerialConsole(baud=9600, live_input=True)
    text, raw = io.StringIO(), io.BytesIO()
    keys = ScriptedKeys({3: b"4", 5: b"2\r", 20: b"-8\r"})
    link = ConsoleLink(console, text_out=text, raw_out=raw, keyboard=keys)
    chip = Chip(image)
    console.attach(chip)
    t0 = time.monotonic()
    result = chip.run(max_cycles=24_000_000)                     # 0.3 s at most: it ends after two numbers
    wall = time.monotonic() - t0
    link.flush()
    assert result.reason == "all cogs stopped"
    assert raw.getvalue() == b"Number? Twice 42 is 84\rNumber? Twice -8 is -16\r"
    assert text.getvalue() == "Number? Twice 42 is 84\nNumber? Twice -8 is -16\n"
    assert link.typed == 6 and [b for _, b in console.sent] == list(b"42\r-8\r")
    assert chip.late_pin_events == 0
    assert wall >= 0.95 * result.end_cycle / 80_000_000        # paced: simulated time never ran ahead


def test_without_a_keyboard_the_link_only_writes_and_does_not_pace():
    image = compile_file(ECHO).binary
    console = SerialConsole(baud=9600)
    console.send(b"3\r", at_seconds=0.01)
    raw = io.BytesIO()
    ConsoleLink(console, raw_out=raw)
    chip = Chip(image)
    console.attach(chip)
    t0 = time.monotonic()
    chip.run(max_cycles=80_000_000 * 5)                         # 5 s simulated
    assert time.monotonic() - t0 < 4
    assert raw.getvalue() == b"Number? Twice 3 is 6\rNumber? "


def test_a_keyboard_needs_an_interactive_terminal():
    assert not keyboard_available(io.StringIO())
    if os.name == "posix":
        import pty
        master, slave = pty.openpty()
        try:
            with open(slave, "r", closefd=True) as tty:
                assert keyboard_available(tty)
                with Keyboard(tty) as kb:
                    assert kb.read() == b""
                    os.write(master, b"ab\n")
                    assert kb.read(1.0) == b"ab\r"                # Enter sends CR
        finally:
            os.close(master)
