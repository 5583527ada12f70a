"""A serial console connected to the real world: output as it arrives, keys typed, real time.

:class:`ConsoleLink` is what ``spinemu run --console`` puts between a
:class:`~spinemu.bench.console.SerialConsole` and the user: each time the
chip reports its pins, the bytes received so far go to a text stream
(rendered as a terminal shows them, :class:`~spinemu.bench.terminal.TextStream`)
and, raw, to a binary file; with a keyboard, the keys typed are sent to the
program's RX pin and the run is paced so that simulated time does not run
ahead of the wall clock (a person types in real time).

The keyboard is read without waiting and without echo, a key at a time
(POSIX terminals through ``termios``; Windows through ``msvcrt``).  Enter
sends a carriage return, as the Parallax Serial Terminal does.
"""
from __future__ import annotations

import os
import sys
import time
from typing import BinaryIO, Optional, TextIO

from .terminal import TextStream

__all__ = ["ConsoleLink", "Keyboard", "keyboard_available"]

#: the longest the run sleeps at once while pacing (keys are read in between)
_PACE_STEP_SECONDS = 0.02


def keyboard_available(stream) -> bool:
    """Can keys be read from ``stream`` one at a time (an interactive terminal)?"""
    try:
        if not stream.isatty():
            return False
    except (AttributeError, ValueError):
        return False
    if os.name == "nt":
        return True
    try:
        import termios  # noqa: F401
    except ImportError:
        return False
    return True


class Keyboard:
    """Keys typed on a terminal, read without blocking (use as a context manager).

    Args:
        stream: the terminal's input (``sys.stdin``).
    """

    def __init__(self, stream):
        self.stream = stream
        self._saved = None
        self._fd = None

    def __enter__(self) -> "Keyboard":
        if os.name != "nt":
            import termios
            import tty
            self._fd = self.stream.fileno()
            self._saved = termios.tcgetattr(self._fd)
            # a key at a time, no echo, keys typed ahead kept; Ctrl-C still interrupts
            tty.setcbreak(self._fd, termios.TCSANOW)
        return self

    def __exit__(self, *exc) -> None:
        if self._saved is not None:
            import termios
            termios.tcsetattr(self._fd, termios.TCSADRAIN, self._saved)
            self._saved = None

    def read(self, wait: float = 0.0) -> bytes:
        """The keys typed so far (waiting up to ``wait`` seconds for the first)."""
        if os.name == "nt":
            import msvcrt
            deadline = time.monotonic() + wait
            keys = bytearray()
            while True:
                while msvcrt.kbhit():
                    keys += msvcrt.getch()
                if keys or time.monotonic() >= deadline:
                    return bytes(keys).replace(b"\n", b"\r")
                time.sleep(0.005)
        import select
        ready, _, _ = select.select([self._fd], [], [], max(0.0, wait))
        if not ready:
            return b""
        data = os.read(self._fd, 1024)
        return data.replace(b"\n", b"\r")


class ConsoleLink:
    """Connects a :class:`~spinemu.bench.console.SerialConsole` to a terminal and files.

    Args:
        console: the console (its ``on_time`` hook is taken).
        text_out: where the received text is written as it arrives (``None``: nowhere).
        raw_out: a binary file for every received byte (``None``: none).
        keyboard: a :class:`Keyboard` whose keys are sent; the run is then
            paced to real time.
    """

    def __init__(self, console, *, text_out: Optional[TextIO] = None, raw_out: Optional[BinaryIO] = None,
                 keyboard: Optional[Keyboard] = None):
        self.console = console
        self.text_out = text_out
        self.raw_out = raw_out
        self.keyboard = keyboard
        self.typed = 0
        self.wrote_text = False
        self.ends_with_newline = True
        self._shown = 0
        self._render = TextStream()
        self._wall0 = None
        console.on_time = self._tick

    def _tick(self, cycle: int) -> None:
        self.flush()
        if self.keyboard is None:
            return
        if self._wall0 is None:
            self._wall0 = time.monotonic()
        self._keys(0.0)
        if cycle >= 1 << 62:                  # the run is over: nothing to pace
            return
        ahead = self.console.seconds(cycle) - (time.monotonic() - self._wall0)
        while ahead > 0:
            self._keys(min(ahead, _PACE_STEP_SECONDS))
            ahead = self.console.seconds(cycle) - (time.monotonic() - self._wall0)

    def _keys(self, wait: float) -> None:
        keys = self.keyboard.read(wait)
        if keys:
            self.typed += len(keys)
            self.console.send(keys)

    def flush(self) -> None:
        """Write what was received since the last call."""
        received = self.console.received
        if self._shown >= len(received):
            return
        data = bytes(b for _, b in received[self._shown:])
        self._shown = len(received)
        if self.raw_out is not None:
            self.raw_out.write(data)
            self.raw_out.flush()
        if self.text_out is not None:
            text = self._render.feed(data)
            if text:
                self.text_out.write(text)
                self.text_out.flush()
                self.wrote_text = True
                self.ends_with_newline = text.endswith("\n")


def stdin_keyboard() -> Optional[Keyboard]:
    """A :class:`Keyboard` on ``sys.stdin`` if it is an interactive terminal, else ``None``."""
    return Keyboard(sys.stdin) if keyboard_available(sys.stdin) else None
