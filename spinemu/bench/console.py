"""The serial console: what a USB serial adapter on the Propeller's P30/P31 sees and sends.

A :class:`SerialConsole` attached to a run decodes the program's TX pin live
(:class:`spinemu.bench.uart.UartDecoder`) and drives its RX pin with the
bytes it is given, at the baud rate (:class:`spinemu.bench.uart.UartWaveform`).
While a console is attached, RX idles at the idle level (high), as the
adapter holds it; the other pins read what the run's input model says
(pull-ups, ``--input`` stimuli).

It is a bench part (:class:`spinemu.bench.part.Part`): it works on every
engine -- the Propeller chip (Spin and PASM cogs), the Python engine's chip
and the BASIC Stamp (its SEROUT and SERIN on P0-P15).

>>> from spinemu.bench import SerialConsole
>>> console = SerialConsole(tx=30, rx=31, baud=115_200)
>>> console.send(b"42\\r", at_seconds=0.5)       # queued until attached
>>> console.data, console.text
(b'', '')
"""
from __future__ import annotations

import math
from typing import Callable, Optional, Union

from .part import Part
from .terminal import stream_text
from .uart import Frame, UartDecoder, UartFormat, UartWaveform

__all__ = ["SerialConsole"]

#: the Propeller's programming port: TX (chip to host) on P30, RX on P31
DEFAULT_TX, DEFAULT_RX, DEFAULT_BAUD = 30, 31, 115_200
#: how long after the chip's present a byte sent during the run starts at the earliest
_SEND_MARGIN_CYCLES = 1000


class SerialConsole(Part):
    """A serial terminal on two pins of a run.

    Args:
        tx: the program's transmit pin (the console decodes it); default P30.
        rx: the program's receive pin (the console drives it); default P31.
        baud: bits per second, both directions (default 115200).
        inverted: the line idles low and the start bit is high.
        stop_bits: stop bits of the bytes the console sends (1 or 2).
        on_byte: called as ``on_byte(cycle, byte)`` for each byte received,
            as soon as it is decoded (it may call :meth:`send`).
        live_input: bytes may be sent at any time during the run (a
            keyboard): the RX line then never counts as "nothing will ever
            change", so a program waiting for input waits instead of ending
            in a deadlock.

    Attributes:
        received: ``(cycle, byte)`` of each byte decoded from TX (the cycle
            of its start bit); bytes with a framing error are in ``errors``.
        errors: :class:`~spinemu.bench.uart.Frame` of each byte whose stop
            bit was missing (or a break on the line).
        sent: ``(cycle, byte)`` of each byte queued on RX (its start bit).

    Raises:
        ValueError: for a pin outside 0..31, TX equal to RX, or a bad baud
            rate or stop-bit count.
    """

    kind = "console"
    pin_parameters = ("tx", "rx")

    def __init__(self, tx: int = DEFAULT_TX, rx: int = DEFAULT_RX, baud: float = DEFAULT_BAUD, *,
                 inverted: bool = False, stop_bits: int = 1,
                 on_byte: Optional[Callable[[int, int], None]] = None, live_input: bool = False,
                 name: Optional[str] = None):
        super().__init__(name=name)
        for name, pin in (("tx", tx), ("rx", rx)):
            if isinstance(pin, bool) or not isinstance(pin, int) or not 0 <= pin <= 31:
                raise ValueError(f"{name} must be a pin number 0..31, not {pin!r}")
        if tx == rx:
            raise ValueError(f"tx and rx must be different pins (both are P{tx})")
        self.tx, self.rx = tx, rx
        self.tx_format = UartFormat(baud, inverted=inverted)
        self.rx_format = UartFormat(baud, stop_bits=stop_bits, inverted=inverted)
        self.baud = baud
        self.on_byte = on_byte
        #: called as ``on_time(cycle)`` after each report of the chip (pins known up to ``cycle``)
        self.on_time: Optional[Callable[[int], None]] = None
        self.live_input = live_input
        self.received: list[tuple[int, int]] = []
        self.errors: list[Frame] = []
        self.sent: list[tuple[int, int]] = []
        #: every cycle before this one has been decoded
        self.now = 0
        #: the chip's present (bytes sent now start at or after it); ``None`` before the run
        self.present: Optional[int] = None
        self.poll_cycles = 0
        self._pending: list = []
        self._wave: Optional[UartWaveform] = None
        self._decoder: Optional[UartDecoder] = None
        self._tx_level = self.tx_format.idle

    # ------------------------------------------------------------------ results
    @property
    def data(self) -> bytes:
        """Every byte received, in order."""
        return bytes(b for _, b in self.received)

    @property
    def text(self) -> str:
        """The received bytes as a terminal shows them: CR, CR LF and LF are new lines, other controls dropped."""
        return stream_text(self.data)

    def seconds(self, cycle: int) -> float:
        """``cycle`` in seconds of the attached run's clock."""
        if not self.clock_hz:
            raise RuntimeError("the console is not attached to a run")
        return cycle / self.clock_hz

    # ------------------------------------------------------------------ input
    def send(self, data: Union[bytes, bytearray, str], at_seconds: Optional[float] = None,
             at_cycle: Optional[int] = None) -> None:
        """Send ``data`` to the program's RX pin, from ``at_seconds`` (or ``at_cycle``) on.

        Bytes go out back to back at the baud rate, in the order of the
        calls; bytes whose time comes while earlier ones are still going out
        follow them.  Without a time: as soon as possible (cycle 0 before the
        run; during the run, from a callback, just after the chip's present:
        never at a moment the program has already read).  A ``str`` is sent
        as UTF-8.

        Raises:
            ValueError: for a time that is negative or not a finite number.
        """
        if isinstance(data, str):
            data = data.encode("utf-8")
        data = bytes(data)
        if at_seconds is not None and at_cycle is not None:
            raise ValueError("give at_seconds or at_cycle, not both")
        if at_seconds is not None:
            if isinstance(at_seconds, bool) or not isinstance(at_seconds, (int, float)) \
                    or not math.isfinite(at_seconds) or at_seconds < 0:
                raise ValueError(f"at_seconds must be a finite number of seconds >= 0, not {at_seconds!r}")
        if at_cycle is not None:
            if isinstance(at_cycle, bool) or not isinstance(at_cycle, int) or at_cycle < 0:
                raise ValueError(f"at_cycle must be a whole number >= 0, not {at_cycle!r}")
        if self._wave is None:
            self._pending.append((data, at_seconds, at_cycle))
            return
        self._queue(data, at_seconds, at_cycle)

    def _queue(self, data: bytes, at_seconds, at_cycle) -> None:
        if at_seconds is not None:
            at = int(round(at_seconds * self.clock_hz))
        elif at_cycle is not None:
            at = at_cycle
        else:
            at = 0
        if self.present is not None:
            at = max(at, self.present + _SEND_MARGIN_CYCLES)
        start, _ = self._wave.add(at, data)
        per = self._wave.frame_cycles
        self.sent.extend((start + per(i), b) for i, b in enumerate(data))

    # ------------------------------------------------------------------ the part
    @property
    def name(self) -> str:
        return self._name or f"console P{self.tx}/P{self.rx}"

    def driven_pins(self) -> tuple:
        return (self.rx,)

    def watched_pins(self) -> tuple:
        return (self.tx,)

    def connect(self, port) -> None:
        """Connected to a run by its bench (``console.attach(engine)`` makes a one-part bench).

        Raises:
            RuntimeError: if this console is already attached to a run.
            ValueError: if the baud rate is too fast for the engine's clock.
        """
        if self._wave is not None:
            raise RuntimeError("a SerialConsole is attached to one run; make a new one for another run")
        clock = int(port.clock_hz)
        self._wave = UartWaveform(self.rx_format, clock)
        self._decoder = UartDecoder(self.tx_format, clock, on_frame=self._frame)
        super().connect(port)
        self.poll_cycles = max(1, clock // 100)
        pending, self._pending = self._pending, []
        for data, at_seconds, at_cycle in pending:
            self._queue(data, at_seconds, at_cycle)

    def levels(self, cycle: int) -> int:
        """The RX line (the console's drive)."""
        return self._wave.level(cycle) << self.rx

    def next_change(self, cycle: int) -> Optional[int]:
        nxt = self._wave.next_change(cycle)
        if nxt is None and self.live_input:
            return cycle + self.poll_cycles       # keys may come: keep time moving
        return nxt

    def on_pins(self, changes, upto: int, present: int) -> None:
        """Decode TX up to ``upto``; bytes sent now start at ``present`` or later."""
        tx, idle = self.tx, self.tx_format.idle
        decoder = self._decoder
        last = self._tx_level
        self.now = upto
        self.present = present
        for cycle, d, o in changes:
            level = (o >> tx) & 1 if (d >> tx) & 1 else idle
            if level != last:
                last = level
                decoder.feed(cycle, level)
        self._tx_level = last
        decoder.advance(upto)
        if self.on_time is not None:
            self.on_time(upto)

    def summary(self) -> str:
        text = f"P{self.tx}: {len(self.received):,} bytes received at {self.baud:g} baud"
        if self.sent:
            text += f"; P{self.rx}: {len(self.sent):,} bytes sent"
        return f"{self.name}: {text}"

    def view(self) -> str:
        lines = self.text.splitlines() or [""]
        return lines[-1][-60:]

    def _frame(self, frame: Frame) -> None:
        if frame.error == "framing":
            self.errors.append(frame)
            return
        self.received.append((frame.start, frame.value))
        if self.on_byte is not None:
            self.on_byte(frame.start, frame.value)
