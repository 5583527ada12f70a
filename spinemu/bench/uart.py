"""Asynchronous serial framing (UART), written once for every engine and tool.

A byte on an asynchronous serial line is a *frame*: a start bit at the active
level, the data bits least significant first, an optional parity bit, then
one or more stop bits at the idle level (the line's rest state).  In the
usual ("true", non-inverted) mode the line idles high and the start bit is
low; inverted mode (the RS-232 levels of a BASIC Stamp's programming port)
swaps the two.  Each bit lasts ``clock_hz / baud`` cycles; bit ``k`` of a
burst of back-to-back frames starts at ``start + floor(k * clock_hz / baud)``
so that a long burst keeps the exact baud rate even when a bit is not a whole
number of cycles.

* :class:`UartFormat` - baud, data bits, parity, stop bits, polarity.
* :func:`frame_bits` - the logical bits of one frame (the encoder's core,
  also used by the BASIC Stamp's SEROUT).
* :class:`UartWaveform` - bytes queued at cycles, as pin levels over time:
  ``level(cycle)`` and the exact ``next_change(cycle)`` that input models need
  so that WAITPEQ/WAITPNE still skip time.
* :class:`UartDecoder` - a streaming receiver fed a pin's level changes in
  time order (``feed(cycle, level)``, ``advance(cycle)``), as a hardware UART
  samples: a start edge, then each bit in its middle; a stop bit at the
  active level is a framing error.  Works live and on recorded traces
  (:func:`decode_uart`).

Sources: the 8N1 frame of EIA/TIA-232 and every UART datasheet; Propeller
Manual v1.2 (the Propeller Plug on P30/P31 idles high).

This module imports nothing from the engines.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass
from fractions import Fraction
from typing import Callable, Iterable, Optional

__all__ = ["UartFormat", "Frame", "frame_bits", "UartWaveform", "UartDecoder", "decode_uart",
           "frame_cut_at_end", "pin_changes", "PARITIES"]

PARITIES = (None, "even", "odd")


@dataclass(frozen=True)
class UartFormat:
    """How bytes are framed on the line.

    Args:
        baud: bits per second (any positive number; one bit must last at
            least 2 clock cycles of the engine that uses it).
        data_bits: 5 to 8.
        parity: ``None``, ``"even"`` or ``"odd"``.
        stop_bits: 1 or 2 (the receiver checks the first).
        inverted: ``True``: the line idles low and the start bit is high.

    Raises:
        ValueError: for a value out of range (the message names it).

    >>> UartFormat(9600).bits_per_frame, UartFormat(9600, parity="even", stop_bits=2).bits_per_frame
    (10, 12)
    """

    baud: float = 115_200
    data_bits: int = 8
    parity: Optional[str] = None
    stop_bits: int = 1
    inverted: bool = False

    def __post_init__(self):
        if isinstance(self.baud, bool) or not isinstance(self.baud, (int, float, Fraction)) \
                or not math.isfinite(self.baud) or self.baud <= 0:
            raise ValueError(f"baud must be a finite number above 0, not {self.baud!r}")
        if self.data_bits not in (5, 6, 7, 8):
            raise ValueError(f"data bits must be 5 to 8, not {self.data_bits!r}")
        if self.parity not in PARITIES:
            raise ValueError(f"parity must be None, 'even' or 'odd', not {self.parity!r}")
        if self.stop_bits not in (1, 2):
            raise ValueError(f"stop bits must be 1 or 2, not {self.stop_bits!r}")

    @property
    def bits_per_frame(self) -> int:
        """Start bit, data bits, parity bit and stop bits."""
        return 1 + self.data_bits + (self.parity is not None) + self.stop_bits

    @property
    def idle(self) -> int:
        """The level of the line at rest (and of stop bits)."""
        return 0 if self.inverted else 1

    def bit_cycles(self, clock_hz: int) -> Fraction:
        """Cycles per bit at ``clock_hz`` (exact).

        Raises:
            ValueError: if a bit would last less than 2 cycles.
        """
        period = Fraction(clock_hz) / Fraction(self.baud)
        if period < 2:
            raise ValueError(f"{float(self.baud):g} baud is too fast for a {clock_hz:,} Hz clock "
                             f"(a bit must last at least 2 clock cycles)")
        return period


def frame_bits(value: int, data_bits: int = 8, parity: Optional[str] = None, stop_bits: int = 1) -> list[int]:
    """The logical bits of one frame (1 = idle level): start, data LSB first, parity, stop.

    >>> frame_bits(0x41)
    [0, 1, 0, 0, 0, 0, 0, 1, 0, 1]
    >>> frame_bits(0x41, data_bits=7, parity="even")
    [0, 1, 0, 0, 0, 0, 0, 1, 0, 1]
    """
    data = [(value >> i) & 1 for i in range(data_bits)]
    bits = [0] + data
    if parity is not None:
        bits.append((sum(data) & 1) ^ (parity == "odd"))
    return bits + [1] * stop_bits


@dataclass(frozen=True)
class Frame:
    """One received frame.

    Attributes:
        start: the cycle of the start bit's leading edge.
        end: the cycle its (first) stop bit was sampled.
        value: the data bits.
        error: ``None``, ``"framing"`` (the stop bit was at the active
            level; ``value`` 0 with the line held active is a *break*) or
            ``"parity"``.
    """

    start: int
    end: int
    value: int
    error: Optional[str] = None


class UartWaveform:
    """Bytes sent on one line at given cycles: the line's level over time.

    Bytes go out in the order they are added; bytes added with a start
    before the end of those already queued follow them back to back.

    Args:
        fmt: the framing.
        clock_hz: cycles per second of the time base.

    >>> w = UartWaveform(UartFormat(baud=1_000_000), clock_hz=10_000_000)   # 10 cycles a bit
    >>> w.add(100, b"\\x01")
    (100, 200)
    >>> [w.level(t) for t in (99, 100, 110, 120)], w.next_change(100), w.next_change(110)
    ([1, 0, 1, 0], 110, 120)
    >>> w.next_change(190) is None
    True
    """

    def __init__(self, fmt: UartFormat, clock_hz: int):
        self.fmt = fmt
        self.clock_hz = clock_hz
        period = fmt.bit_cycles(clock_hz)
        self._p, self._q = period.numerator, period.denominator
        self._nbits = fmt.bits_per_frame
        self._starts: list[int] = []
        self._bursts: list[tuple[int, bytes, int]] = []     # (start, data, end)
        self.end = 0            # the cycle the last queued frame's stop bits end

    # ------------------------------------------------------------------ building
    def frame_cycles(self, count: int = 1) -> int:
        """Cycles ``count`` back-to-back frames take (rounded down)."""
        return (count * self._nbits * self._p) // self._q

    def add(self, start: int, data: bytes) -> tuple[int, int]:
        """Queue ``data`` to start at cycle ``start`` (or when the bytes before it are out).

        Returns:
            ``(first cycle, end cycle)`` of the burst.
        """
        data = bytes(data)
        start = max(int(start), self.end)
        if not data:
            return start, start
        end = start + self.frame_cycles(len(data))
        self._starts.append(start)
        self._bursts.append((start, data, end))
        self.end = end
        return start, end

    # ------------------------------------------------------------------ reading
    def _bit(self, data: bytes, k: int) -> int:
        """Logical level of bit ``k`` of a burst (1 = idle)."""
        n, j = divmod(k, self._nbits)
        if n >= len(data):
            return 1
        fmt = self.fmt
        if j == 0:
            return 0
        if j <= fmt.data_bits:
            return (data[n] >> (j - 1)) & 1
        if fmt.parity is not None and j == fmt.data_bits + 1:
            v = data[n] & ((1 << fmt.data_bits) - 1)
            return (bin(v).count("1") & 1) ^ (fmt.parity == "odd")
        return 1

    def _index(self, cycle: int) -> tuple[int, int]:
        """``(burst number, bit index)`` at ``cycle``; burst -1 before the first."""
        i = bisect_right(self._starts, cycle) - 1
        if i < 0:
            return -1, 0
        start = self._starts[i]
        return i, (((cycle - start + 1) * self._q - 1) // self._p)

    def level(self, cycle: int) -> int:
        """The electrical level (0/1) of the line at ``cycle``."""
        i, k = self._index(cycle)
        logical = 1 if i < 0 else self._bit(self._bursts[i][1], k)
        return logical ^ self.fmt.inverted

    def next_change(self, cycle: int) -> Optional[int]:
        """The first cycle after ``cycle`` at which :meth:`level` differs from its value at ``cycle``, or ``None``."""
        i, k = self._index(cycle)
        if i >= 0:
            start, data, _ = self._bursts[i]
            last = len(data) * self._nbits
            now = self._bit(data, k)
            for j in range(k + 1, last):
                if self._bit(data, j) != now:
                    return start + (j * self._p) // self._q
            if now != 1:                # a burst always ends at the idle level
                return start + (last * self._p) // self._q
        if i + 1 < len(self._starts):
            return self._starts[i + 1]  # the next burst's start bit
        return None


class UartDecoder:
    """A receiver of one line, fed its level changes in time order.

    Args:
        fmt: the framing (the receiver checks one stop bit).
        clock_hz: cycles per second of the changes' time base.
        on_frame: called with each :class:`Frame` as it completes.

    The line starts at the idle level.  A change to the active level while
    idle is a start edge; each bit is then sampled in its middle; a start bit
    no longer active in its middle was a glitch and is ignored.  After a
    framing error with the line still active (a break), the receiver waits
    for the line to return to idle.

    >>> d = UartDecoder(UartFormat(baud=1_000_000), clock_hz=10_000_000)
    >>> w = UartWaveform(d.fmt, 10_000_000); _ = w.add(50, b"Hi")
    >>> t = 0
    >>> while (t := w.next_change(t)) is not None:
    ...     d.feed(t, w.level(t))
    >>> d.advance(10_000); bytes(f.value for f in d.frames)
    b'Hi'
    """

    _IDLE, _FRAME, _WAIT_IDLE = 0, 1, 2

    def __init__(self, fmt: UartFormat, clock_hz: int, on_frame: Optional[Callable[[Frame], None]] = None):
        self.fmt = fmt
        self.clock_hz = clock_hz
        period = fmt.bit_cycles(clock_hz)
        p, q = period.numerator, period.denominator
        nbits = 1 + fmt.data_bits + (fmt.parity is not None) + 1      # the receiver checks one stop bit
        #: sample offsets from the start edge: the middle of each bit
        self._mid = [((2 * k + 1) * p) // (2 * q) for k in range(nbits)]
        self.on_frame = on_frame
        self.frames: list[Frame] = []
        self.level = fmt.idle
        self.time = 0               # the latest cycle fed or advanced to
        self._state = self._IDLE
        self._start = 0
        self._k = 0
        self._bits: list[int] = []

    def feed(self, cycle: int, level: int) -> None:
        """From ``cycle`` on the line is at ``level`` (changes must come in time order)."""
        self._sample_before(cycle)
        if cycle > self.time:
            self.time = cycle
        level = 1 if level else 0
        if level == self.level:
            return
        self.level = level
        if self._state == self._IDLE:
            if level != self.fmt.idle:
                self._state, self._start, self._k, self._bits = self._FRAME, cycle, 0, []
        elif self._state == self._WAIT_IDLE and level == self.fmt.idle:
            self._state = self._IDLE

    @property
    def receiving(self) -> bool:
        """A frame has started and is not complete yet."""
        return self._state == self._FRAME

    def advance(self, cycle: int) -> None:
        """The line's level is known up to (not including) ``cycle``: complete the frames sampled before it."""
        self._sample_before(cycle)
        if cycle > self.time:
            self.time = cycle

    def _sample_before(self, cycle: int) -> None:
        fmt = self.fmt
        mid = self._mid
        while self._state == self._FRAME and self._start + mid[self._k] < cycle:
            logical = self.level ^ fmt.inverted
            k = self._k
            if k == 0:
                if logical:                     # not a start bit after all
                    self._state = self._IDLE
                    continue
            elif k < len(mid) - 1:
                self._bits.append(logical)
            else:
                self._finish(logical)
                continue
            self._k = k + 1

    def _finish(self, stop: int) -> None:
        fmt = self.fmt
        data = self._bits[:fmt.data_bits]
        value = sum(b << i for i, b in enumerate(data))
        error = None
        if fmt.parity is not None:
            want = (sum(data) & 1) ^ (fmt.parity == "odd")
            if self._bits[fmt.data_bits] != want:
                error = "parity"
        if not stop:
            error = "framing"
        frame = Frame(self._start, self._start + self._mid[-1], value, error)
        self.frames.append(frame)
        if error == "framing" and (self.level ^ fmt.inverted) == 0:
            self._state = self._WAIT_IDLE
        else:
            self._state = self._IDLE
        if self.on_frame is not None:
            self.on_frame(frame)


def pin_changes(changes: Iterable[tuple[int, int, int]], pin: int, idle: int):
    """``(cycle, level)`` of one pin from ``(cycle, dir, out)`` states; an undriven pin reads ``idle``.

    >>> list(pin_changes([(0, 0, 0), (5, 1, 1), (9, 1, 0), (12, 0, 0)], 0, idle=1))
    [(9, 0), (12, 1)]
    """
    last = idle
    for cycle, d, o in changes:
        level = (o >> pin) & 1 if (d >> pin) & 1 else idle
        if level != last:
            last = level
            yield cycle, level


def decode_uart(trace, pin: int, fmt: UartFormat, *, hold_last: bool = False) -> list[Frame]:
    """The frames on ``pin`` of a recorded :class:`spinemu.trace.PinTrace`.

    An undriven pin reads the idle level (a serial adapter's input is pulled
    to it).  A frame still being received at the trace's end is left out,
    unless ``hold_last``: the line then keeps its last level after the end
    (as it does when the run ended because every cog stopped).

    Raises:
        ValueError: for a pin the trace does not have.
    """
    return _decoder_for_trace(trace, pin, fmt, hold_last).frames


def _decoder_for_trace(trace, pin: int, fmt: UartFormat, hold_last: bool) -> "UartDecoder":
    if not 0 <= pin < trace.pin_count:
        raise ValueError(f"pin {pin} does not exist (pins are 0..{trace.pin_count - 1})")
    decoder = UartDecoder(fmt, trace.clock_hz)
    for cycle, level in pin_changes(trace.changes, pin, fmt.idle):
        decoder.feed(cycle, level)
    end = max(trace.end_cycle, trace.changes[-1][0] if trace.changes else 0)
    decoder.advance(1 << 62 if hold_last else end + 1)
    return decoder


def frame_cut_at_end(trace, pin: int, fmt: UartFormat) -> bool:
    """Was a frame still being received on ``pin`` when ``trace`` ended?"""
    return _decoder_for_trace(trace, pin, fmt, False).receiving
