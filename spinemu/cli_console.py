"""The serial console's part of the command line: its ``run`` options, the run's console, ``trace decode uart``
(whose parser, with the other protocols', is in :mod:`spinemu.cli_bench`).

Only :mod:`spinemu.cli` imports this module (it keeps the console's
argument parsing and rendering out of the main command module); the library
behind it is :mod:`spinemu.bench`.
"""
from __future__ import annotations

import argparse
import contextlib
import math

from .diagnostics import SpinError, UsageError

__all__ = ["console_options", "console_wanted", "ConsoleSession", "decode_uart_frames", "baud_rate"]


def baud_rate(text: str) -> float:
    """``--baud``: a finite number of at least 1 (whether the clock allows it is checked with the clock)."""
    try:
        v = float(text.replace("_", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of bits per second, got {text!r}")
    if not math.isfinite(v) or v < 1:
        raise argparse.ArgumentTypeError(f"expected a number of bits per second of 1 or more, got {text!r}")
    return v


def _read_input(path: str) -> bytes:
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError as e:
        raise SpinError(f"cannot read file: {e.strerror or e}", path=path)


def _seconds_from_start(text: str) -> float:
    try:
        v = float(text.replace("_", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}")
    if not math.isfinite(v) or v < 0:
        raise argparse.ArgumentTypeError(f"expected a number of seconds of 0 or more, got {text!r}")
    return v


def _pin_pair(text: str) -> tuple[int, int]:
    parts = [p.strip().upper().removeprefix("P") for p in text.split(",")]
    try:
        if len(parts) != 2:
            raise ValueError
        tx, rx = (int(p, 10) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected two pin numbers TX,RX such as 30,31, got {text!r}")
    for p in (tx, rx):
        if not 0 <= p <= 31:
            raise argparse.ArgumentTypeError(f"pin {p} does not exist (pins are 0..31)")
    if tx == rx:
        raise argparse.ArgumentTypeError(f"TX and RX must be different pins, got {text!r}")
    return tx, rx


def console_wanted(args) -> bool:
    """Does the run ask for the serial console (any of its options)?"""
    return bool(args.console or args.console_out or args.console_in or args.console_pins or args.baud)


class ConsoleSession:
    """The serial console of a Spin run (``--console*``, ``--baud``): set up, live output, summary."""

    def __init__(self, args, out, clock_hz: int, live_text: bool = True):
        from .bench import SerialConsole, UartFormat
        from .bench.live import ConsoleLink, stdin_keyboard

        tx, rx = args.console_pins or (30, 31)
        baud = args.baud or 115_200
        try:
            UartFormat(baud).bit_cycles(clock_hz)
        except ValueError as e:
            raise UsageError(f"--baud: {e}")
        data = _read_input(args.console_in) if args.console_in else b""
        self.keyboard = stdin_keyboard() if args.console else None
        self.console = SerialConsole(tx, rx, baud, live_input=self.keyboard is not None)
        if args.console_in:
            self.console.send(data, at_seconds=args.console_in_at or 0.0)
        self.out_path = args.console_out
        self._stack = contextlib.ExitStack()
        self.shows = not out.quiet and live_text
        self.link = ConsoleLink(self.console, text_out=out.stdout if self.shows else None,
                                keyboard=self.keyboard)
        self.out = out

    def __enter__(self) -> "ConsoleSession":
        # the output file and the terminal's raw mode only for the run itself: an error in the
        # options checked after this object is made leaves no file open and the terminal as it was
        try:
            if self.out_path:
                self.link.raw_out = self._stack.enter_context(open(self.out_path, "wb"))
            if self.keyboard is not None:
                self._stack.enter_context(self.keyboard)
        except BaseException:
            self._stack.close()
            raise
        return self

    def __exit__(self, *exc) -> None:
        try:
            self.link.flush()
            if self.link.wrote_text and not self.link.ends_with_newline:
                self.out.stdout.write("\n")
        finally:
            self._stack.close()

    def summary(self) -> tuple[str, str]:
        c = self.console
        text = f"P{c.tx}: {len(c.received):,} bytes received at {c.baud:g} baud"
        if self.out_path:
            text += f" (in {self.out_path})"
        if c.sent:
            text += f"; P{c.rx}: {len(c.sent):,} bytes sent"
        return "console", text

    def warnings(self, end_cycle: int) -> list[str]:
        c = self.console
        notes = []
        if c.errors:
            first = c.errors[0]
            notes.append(f"console: {len(c.errors)} frame(s) on P{c.tx} without a stop bit (the first at "
                         f"{c.seconds(first.start):.6f} s): a different baud rate (--baud), or a break")
        late = [t for t, _ in c.sent if t >= end_cycle]
        if late:
            notes.append(f"console: the run ended before {len(late)} of the {len(c.sent)} bytes for P{c.rx} "
                         f"were sent")
        return notes


def console_options(p) -> None:
    """The serial console's options of ``spinemu run``."""
    g = p.add_argument_group(
        "serial console",
        "A serial terminal on the program's TX/RX pins, as a USB serial adapter on P30/P31:\n"
        "8 data bits, no parity, 1 stop bit. Any of these options attaches it; while it is\n"
        "attached, the RX pin idles high. See docs/console.md.")
    g.add_argument("--console", action="store_true",
                   help="attach the console and print what the program sends as it arrives; when stdin is a "
                        "terminal, the keys typed are sent (Enter sends CR) and the run keeps to real time")
    g.add_argument("--console-out", metavar="FILE",
                   help="write every byte received from TX to FILE (also printed live unless --quiet)")
    g.add_argument("--console-in", metavar="FILE", help="send the bytes of FILE to RX at the baud rate")
    g.add_argument("--console-in-at", type=_seconds_from_start, metavar="SECONDS",
                   help="simulated time at which --console-in starts sending (default 0)")
    g.add_argument("--console-pins", type=_pin_pair, metavar="TX,RX",
                   help="the program's transmit and receive pins (default 30,31)")
    g.add_argument("--baud", type=baud_rate, metavar="N", help="bits per second (default 115200)")


def decode_uart_frames(args, trace, out) -> list:
    """``trace decode uart``: print the bytes on one pin of a trace, as text or one line per frame.

    Returns:
        ``(start, end, text)`` of each frame (for an annotation file).
    """
    from .analysis.view import format_time
    from .bench.terminal import stream_text
    from .bench.uart import UartFormat, decode_uart, frame_cut_at_end

    if args.pin is None:
        raise UsageError("trace decode uart needs --pin N (the pin carrying the serial data)")
    if not 0 <= args.pin < trace.pin_count:
        raise UsageError(f"--pin {args.pin} does not exist (pins are 0..{trace.pin_count - 1})")
    fmt = UartFormat(args.baud, inverted=args.inverted)
    try:
        fmt.bit_cycles(trace.clock_hz)
    except ValueError as e:
        raise UsageError(f"--baud: {e}")
    lo = args.start if args.start is not None else 0
    hi = args.end if args.end is not None else 1 << 62
    frames = [f for f in decode_uart(trace, args.pin, fmt, hold_last=args.hold_last) if lo <= f.start <= hi]
    if args.frames:
        for f in frames:
            ch = chr(f.value) if 32 <= f.value < 127 else "."
            note = f"  {f.error} error" if f.error else ""
            out.stdout.write(f"{f.start:>12} {format_time(f.start, trace.clock_hz):>12}  "
                             f"${f.value:02X} {ch}{note}\n")
    else:
        text = stream_text(bytes(f.value for f in frames if f.error != "framing"))
        out.stdout.write(text if not text or text.endswith("\n") else text + "\n")
    bad = [f for f in frames if f.error]
    if bad:
        out.err_console.print(f"warning: {len(bad)} frame(s) on P{args.pin} without a stop bit (the first at "
                              f"cycle {bad[0].start}): a different baud rate (--baud) or polarity (--inverted)?",
                              markup=False)
    if not args.hold_last and frame_cut_at_end(trace, args.pin, fmt):
        out.err_console.print("warning: a frame was still being received when the trace ended (--hold-last "
                              "completes it with the line's last level)", markup=False)
    return [(f.start, f.end, f"${f.value:02X} {chr(f.value) if 32 <= f.value < 127 else '.'}"
             + (f" {f.error} error" if f.error else "")) for f in frames]
