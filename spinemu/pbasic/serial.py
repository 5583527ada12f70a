"""Serial I/O of the BS2: DEBUG/DEBUGIN, SEROUT/SERIN waveforms, SHIFTOUT/SHIFTIN,
and the number formatters they share.

Sources: BASIC Stamp Syntax and Reference Manual v2.2 (DEBUG, DEBUGIN,
SERIN, SEROUT, SHIFTIN, SHIFTOUT pages) and BASIC Stamp Programming Manual
1.8 (SHIFTOUT timing diagram).

* Baudmode bits 0-12 are the bit time minus 20 us; bit 13 selects 7 data bits
  with even parity, bit 14 inverted polarity, bit 15 open (driven in one
  state only).  Pin 16 is the programming port (the DEBUG terminal).
* A SEROUT byte is a start bit, 8 data bits LSB first (or 7 + even parity),
  one stop bit; true mode idles high (the framing is
  :func:`spinemu.bench.uart.frame_bits`).  The decoded bytes are kept per pin
  next to the waveform (``Machine.serial_out``).
* Flow control: in true mode the receiver holds Fpin low for "ready", in
  inverted mode high.
* SHIFTOUT/SHIFTIN (BS2): data set 15 us before the clock rises, clock high
  14 us, low 46 us: about 60 us (16.7 kbit/s) per bit.
* Incoming serial data (``serial_in``, ``debug_in``) is available at once and
  arrives at the receiver's baud rate; when it runs out, SERIN waits for its
  timeout (or forever) and DEBUGIN waits forever.
* On a pin a bench part or a stimulus drives (a serial console,
  :mod:`spinemu.bench`), SERIN reads the line itself (:class:`WireReader`):
  a start edge, each bit in its middle; bytes arrive when they are sent, and
  the timeout limits the wait for each byte.
"""
from __future__ import annotations

from collections import deque
from typing import Callable, Optional

from ..bench.uart import frame_bits
from .machine import MASK, Machine, StopRun

__all__ = ["format_number", "make_debug", "make_serout", "make_serin", "make_debugin",
           "make_shiftout", "make_shiftin", "parse_formatter", "Emitter", "Reader"]

DEBUG_BIT_US = 1_000_000 / 9600


# ------------------------------------------------------------------ formatting
def parse_formatter(name: str) -> tuple[str, bool, bool, int]:
    """``"ISHEX4"`` -> ``("HEX", signed, indicated, digits)``.

    >>> parse_formatter("ISHEX4"), parse_formatter("DEC")
    (('HEX', True, True, 4), ('DEC', False, False, 0))
    """
    s = name.upper()
    indicated = s.startswith("I")
    if indicated:
        s = s[1:]
    signed = s.startswith("S")
    if signed:
        s = s[1:]
    base = s[:3]
    digits = int(s[3:]) if s[3:] else 0
    return base, signed, indicated, digits


def format_number(fmt: str, v: int) -> str:
    """The text a formatter produces for a 16-bit value.

    >>> format_number("SDEC5", 0xFFBF), format_number("ISHEX4", 0xFFBF), format_number("DEC4", 56422)
    ('-00065', '-$0041', '6422')
    >>> format_number("IBIN", 5), format_number("HEX", 255)
    ('%101', 'FF')
    """
    base, signed, indicated, n = parse_formatter(fmt)
    v &= MASK
    neg = signed and bool(v & 0x8000)
    mag = (-v) & MASK if neg else v
    if base == "DEC":
        digits = str(mag)
    elif base == "HEX":
        digits = f"{mag:X}"
    else:
        digits = f"{mag:b}"
    if n:
        digits = digits[-n:].rjust(n, "0")
    prefix = {"DEC": "", "HEX": "$", "BIN": "%"}[base] if indicated else ""
    return ("-" if neg else "") + prefix + digits


#: An output item: ``e(m) -> bytes``.
Emitter = Callable[[Machine], bytes]


def _drive(m: Machine, bit: int, level: int, inverted: bool, open_: bool) -> None:
    """Put a serial line at ``level`` (electrical), honouring open baudmodes."""
    active = 1 if inverted else 0           # the level an open pin actually drives
    if open_ and level != active:
        m.w[2] &= ~bit
    else:
        m.w[2] |= bit
        m.w[1] = (m.w[1] | bit) if level else (m.w[1] & ~bit)
    m.pins_changed()


def _frame_bits(b: int, seven_e: bool) -> list[int]:
    """The bits of one SEROUT frame (8N1, or 7E1 with baudmode bit 13): the bench's UART framing."""
    return frame_bits(b, data_bits=7, parity="even") if seven_e else frame_bits(b)


def _wait_pin(m: Machine, pin: int, level: int, timeout_ms: Optional[int]) -> bool:
    """Wait for an input to read ``level``; False if ``timeout_ms`` passed first."""
    return m.wait_input(pin, level, None if timeout_ms is None else m.t + timeout_ms * 1000) is not None


def make_debug(items: list) -> Callable:
    """DEBUG: text to the programming port (9600 baud: takes time in realistic mode only)."""
    def run(m):
        data = b"".join(e(m) for e in items)
        m.debug_out += data
        if m.debug_char_us and data:
            m.advance(int(round(len(data) * m.debug_char_us)))
    return run


def make_serout(tpin: Callable, fpin: Optional[Callable], baud: Callable,
                pace: Optional[Callable], timeout: Optional[Callable], tlabel,
                items: list) -> Callable:
    def run(m):
        p = tpin(m)
        mode = baud(m)
        data = b"".join(e(m) for e in items)
        bit_us = (mode & 0x1FFF) + 20
        seven_e = bool(mode & 0x2000)
        inverted = bool(mode & 0x4000)
        open_ = bool(mode & 0x8000)
        if p >= 16:
            m.emit(16, data)
            m.advance(len(data) * 10 * bit_us)
            return None
        bit = 1 << p
        f = fpin(m) & 15 if fpin else None
        if f is not None:
            m.set_pin(f, output=False)
        gap = pace(m) * 1000 if pace else 0
        tmo = timeout(m) if timeout else None
        _drive(m, bit, 0 if inverted else 1, inverted, open_)      # idle
        for i, b in enumerate(data):
            if f is not None and not _wait_pin(m, f, 1 if inverted else 0, tmo):
                return tlabel.pc
            for lb in _frame_bits(b, seven_e):
                _drive(m, bit, lb ^ inverted, inverted, open_)
                m.advance(bit_us)
            m.emit(p, bytes([b]))
            if gap and i < len(data) - 1:
                m.advance(gap)
        return None
    return run


# ------------------------------------------------------------------ input
class _NoData(Exception):
    pass


class Reader:
    """Bytes arriving on one serial input, at ``byte_us`` per byte (a queue: ``serial_in``, ``debug_in``)."""

    #: time passes in :meth:`finish`, not while reading
    waits = False

    def __init__(self, m: Machine, queue, byte_us: float):
        self.m, self.q, self.byte_us = m, queue, byte_us
        self.n = 0

    def get(self) -> int:
        if not self.q:
            raise _NoData()
        self.n += 1
        return self.q.popleft()

    def peek(self) -> Optional[int]:
        return self.q[0] if self.q else None

    def finish(self, start: int) -> None:
        """The bytes read took their time at the baud rate, from ``start``."""
        self.m.t = start
        self.m.advance(int(round(self.n * self.byte_us)))


class WireReader:
    """Bytes received from a pin's level, as the BS2's UART does: a start edge, then each bit in its middle.

    Used when a bench part or a stimulus drives the pin (a serial console,
    a device): the bytes arrive when the sender sends them, and a byte sent
    while SERIN is not listening is lost, as on the real line.  Time passes
    while reading; ``timeout_us`` limits the wait for each byte.
    """

    waits = True

    def __init__(self, m: Machine, pin: int, bit_us: int, seven_e: bool, inverted: bool,
                 timeout_us: Optional[int]):
        self.m, self.pin, self.bit_us = m, pin, bit_us
        self.nbits = 8
        self.seven = seven_e
        self.inverted = 1 if inverted else 0
        self.timeout_us = timeout_us
        self.n = 0
        self._held: Optional[int] = None

    def _receive(self) -> int:
        m = self.m
        deadline = m.t + self.timeout_us if self.timeout_us is not None else m.limit
        active = self.inverted                      # a start bit: low in true mode
        if m.wait_input(self.pin, 1 - active, deadline) is None:    # the line at rest first
            raise _NoData()
        t = m.wait_input(self.pin, active, deadline)
        if t is None:
            raise _NoData()
        value = 0
        for k in range(self.nbits):
            m.advance_to(t + (2 * k + 3) * self.bit_us // 2)
            value |= (m.input_level(self.pin) ^ self.inverted) << k
        m.advance_to(t + (2 * self.nbits + 3) * self.bit_us // 2)       # the stop bit's middle
        return value & 0x7F if self.seven else value

    def get(self) -> int:
        if self._held is not None:
            b, self._held = self._held, None
        else:
            b = self._receive()
        self.n += 1
        return b

    def peek(self) -> Optional[int]:
        if self._held is None:
            try:
                self._held = self._receive()
            except _NoData:
                return None
        return self._held

    def finish(self, start: int) -> None:
        """Time has passed while reading."""


def _read_number(r: Reader, fmt: str) -> int:
    base, signed, indicated, n = parse_formatter(fmt)
    radix = {"DEC": 10, "HEX": 16, "BIN": 2}[base]
    marker = {"DEC": None, "HEX": "$", "BIN": "%"}[base] if indicated else None
    valid = "0123456789ABCDEF"[:radix]
    neg = False
    # skip to the number (and its sign / indicator)
    while True:
        ch = chr(r.get()).upper()
        if signed and ch == "-":
            neg = True
            ch = chr(r.get()).upper()
        if marker:
            if ch == marker:
                ch = chr(r.get()).upper()
            else:
                continue
        if ch in valid:
            break
        neg = False
    value, count = 0, 0
    while True:
        value = (value * radix + valid.index(ch)) & MASK
        count += 1
        if n and count >= n:
            break
        nxt = r.peek()
        if nxt is None:
            raise _NoData()
        if chr(nxt).upper() not in valid:
            r.get()                      # the terminator is consumed
            break
        ch = chr(r.get()).upper()
    return (-value) & MASK if neg else value


def run_input_items(r: Reader, items: list) -> None:
    """Apply DEBUGIN/SERIN items (closures ``item(m, reader)``) in order."""
    for item in items:
        item(r.m, r)


def in_byte(write: Callable) -> Callable:
    return lambda m, r: write(m, r.get())


def in_number(fmt: str, write: Callable) -> Callable:
    return lambda m, r: write(m, _read_number(r, fmt))


def in_str(byte_write: Callable, length: Callable, end: Optional[Callable]) -> Callable:
    """STR arr\\L{\\E}: L bytes into the array (stop at E); the rest of L is zeroed."""
    def item(m, r):
        n = length(m)
        e = end(m) & 0xFF if end else None
        i = 0
        while i < n:
            b = r.get()
            if e is not None and b == e:
                break
            byte_write(m, i, b)
            i += 1
        while i < n:
            byte_write(m, i, 0)
            i += 1
    return item


def in_wait(values: list) -> Callable:
    """WAIT(...): skip input until this byte sequence has been received."""
    def item(m, r):
        seq = bytes(v(m) & 0xFF for v in values)
        window = b""
        while not window.endswith(seq):
            window = (window + bytes([r.get()]))[-len(seq):]
    return item


def in_waitstr(byte_read: Callable, length: Optional[Callable]) -> Callable:
    def item(m, r):
        n = length(m) if length else 32
        seq = bytearray()
        for i in range(n):
            b = byte_read(m, i)
            if length is None and b == 0:
                break
            seq.append(b)
        window = b""
        while seq and not window.endswith(bytes(seq)):
            window = (window + bytes([r.get()]))[-len(seq):]
    return item


def in_skip(count: Callable) -> Callable:
    def item(m, r):
        for _ in range(count(m)):
            r.get()
    return item


def _receive(m: Machine, r, items: list, start: int) -> bool:
    try:
        run_input_items(r, items)
        ok = True
    except _NoData:
        ok = False
    r.finish(start)
    return ok


def make_debugin(items: list, pos) -> Callable:
    def run(m):
        r = Reader(m, m.debug_in, m.debug_char_us)
        if not _receive(m, r, items, m.t):
            m.wait_forever("DEBUGIN", pos)
    return run


def make_serin(rpin: Callable, fpin: Optional[Callable], baud: Callable,
               timeout: Optional[Callable], tlabel, items: list, pos) -> Callable:
    def run(m):
        p = rpin(m)
        mode = baud(m)
        bit_us = (mode & 0x1FFF) + 20
        inverted = bool(mode & 0x4000)
        wired = p < 16 and (int(getattr(m.inputs, "mask", 0) or 0) >> p) & 1
        if p >= 16:
            queue = m.debug_in
        else:
            m.set_pin(p, output=False)
            queue = m.serial_in.setdefault(p, deque())
        f = fpin(m) & 15 if fpin else None
        if f is not None:
            m.set_pin(f, out=1 if inverted else 0, output=True)         # ready
        tmo = timeout(m) * 1000 if timeout is not None else None
        if wired:                       # a part or stimulus drives the pin: read the line itself
            r = WireReader(m, p, bit_us, bool(mode & 0x2000), inverted, tmo)
        else:
            r = Reader(m, queue, 10 * bit_us)
        ok = _receive(m, r, items, m.t)
        if f is not None:
            m.set_pin(f, out=0 if inverted else 1, output=True)         # not ready
        if ok:
            return None
        if timeout is not None:
            if not r.waits:
                m.advance(tmo)
            return tlabel.pc
        m.wait_forever(f"SERIN pin {p}", pos)
        return None
    return run


# ------------------------------------------------------------------ synchronous
SHIFT_TA, SHIFT_TH, SHIFT_TB = 15, 14, 31      # data->clock, clock high, clock low->data


def make_shiftout(dpin: Callable, cpin: Callable, mode: Callable, items: list) -> Callable:
    """items: [(value_f, bits_f | None)].  Mode 0 LSBFIRST, 1 MSBFIRST."""
    def run(m):
        d, c = dpin(m), cpin(m)
        msb = mode(m) & 1
        m.set_pin(c, out=0, output=True)
        m.advance(SHIFT_TA)
        for value_f, bits_f in items:
            v = value_f(m)
            n = bits_f(m) if bits_f else 8
            n = min(max(n, 1), 16)
            order = range(n - 1, -1, -1) if msb else range(n)
            for i in order:
                m.set_pin(d, out=(v >> i) & 1, output=True)
                m.advance(SHIFT_TA)
                m.set_pin(c, out=1)
                m.advance(SHIFT_TH)
                m.set_pin(c, out=0)
                m.advance(SHIFT_TB)
    return run


def make_shiftin(dpin: Callable, cpin: Callable, mode: Callable, items: list) -> Callable:
    """items: [(write, width, bits_f | None)].  Modes: 0 MSBPRE, 1 LSBPRE, 2 MSBPOST, 3 LSBPOST."""
    def run(m):
        d, c = dpin(m), cpin(m)
        md = mode(m) & 3
        post = md >= 2
        lsb = md & 1
        m.set_pin(d, output=False)
        m.set_pin(c, out=0, output=True)
        m.advance(SHIFT_TA)
        for write, width, bits_f in items:
            n = bits_f(m) if bits_f else 8
            n = min(max(n, 1), 16)
            v = 0
            for i in range(n):
                if not post:
                    b = m.input_level(d)
                m.set_pin(c, out=1)
                m.advance(SHIFT_TH)
                m.set_pin(c, out=0)
                if post:
                    b = m.input_level(d)
                m.advance(SHIFT_TB + SHIFT_TA)
                if lsb:
                    v |= b << i
                else:
                    v = (v << 1) | b
            write(m, v)
    return run
