"""I2C: a decoder of the bus, live or on recorded traces.

The bus is two open-drain lines, SCL and SDA, pulled up (an undriven line
reads 1).  NXP UM10204 "I2C-bus specification and user manual", sections
3.1.4-3.1.10: SDA falling while SCL is high is a START (a *repeated* START
inside a transfer), SDA rising while SCL is high a STOP; otherwise SDA only
changes while SCL is low and each bit is read while SCL is high (at its
rising edge here).  A byte is 8 bits, most significant first, then a 9th
clock on which the receiver pulls SDA low to acknowledge (ACK) or leaves it
high (NAK).  The first byte after a START is the address: 7 bits and the
R/W bit (1 = read).

:class:`I2cDecoder` is fed ``(cycle, scl, sda)`` in time order and makes
:class:`I2cTransfer` records; a START or STOP in the middle of a byte is a
protocol violation, reported in ``violations`` at its cycle (after the
second clock of a byte: the clock that sets up a START or STOP is always
the first of the next byte).
:func:`decode_i2c` does it on a :class:`~spinemu.trace.PinTrace`.  Decoding
what a device sends (ACKs, data it reads back) needs its levels in the
trace: record a bench run's wire trace (:meth:`spinemu.bench.Bench.wire_trace`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional

from .levels import level_changes

__all__ = ["I2cTransfer", "I2cDecoder", "decode_i2c", "i2c_levels"]


@dataclass
class I2cTransfer:
    """One addressed transfer: a START (or repeated START), an address, bytes, until the next START or a STOP.

    Attributes:
        start: the cycle of its START.
        end: the cycle of the STOP or repeated START that ended it (``None`` while open).
        address: the 7-bit address.
        read: the R/W bit was 1.
        acked: someone acknowledged the address.
        data: the bytes after the address.
        acks: for each byte, whether it was acknowledged.
        byte_cycles: ``(first rising SCL edge, ACK clock)`` of the address and each byte.
        restart: it began with a repeated START.
        stopped: a STOP ended it.
    """

    start: int
    address: int = 0
    read: bool = False
    acked: bool = False
    data: list = field(default_factory=list)
    acks: list = field(default_factory=list)
    byte_cycles: list = field(default_factory=list)
    restart: bool = False
    end: Optional[int] = None
    stopped: bool = False
    complete_address: bool = False

    def text(self) -> str:
        """``"0x50 W ACK: 00 10 2A"`` (NAKed bytes marked ``!``)."""
        if not self.complete_address:
            return "START without an address"
        rw = "R" if self.read else "W"
        head = f"0x{self.address:02X} {rw} {'ACK' if self.acked else 'NAK'}"
        if not self.data:
            return head
        return head + ": " + " ".join(f"{b:02X}{'' if a else '!'}" for b, a in zip(self.data, self.acks))


class I2cDecoder:
    """A streaming I2C decoder (see the module docstring).

    Args:
        on_transfer: called with each :class:`I2cTransfer` when it ends.

    >>> d = I2cDecoder()
    >>> for t, scl, sda in i2c_levels([(0x50, False, [0x12, 0x34])], half_bit=10):
    ...     d.feed(t, scl, sda)
    >>> d.transfers[0].text()
    '0x50 W ACK: 12 34'
    """

    def __init__(self, on_transfer: Optional[Callable[[I2cTransfer], None]] = None):
        self.on_transfer = on_transfer
        self.transfers: list[I2cTransfer] = []
        #: ``(cycle, message)`` of each protocol violation
        self.violations: list = []
        self.scl = self.sda = 1
        self.current: Optional[I2cTransfer] = None
        self._bits = 0              # bits of the current byte so far (9: the ACK clock)
        self._value = 0
        self._first = 0

    def feed(self, cycle: int, scl: int, sda: int) -> None:
        """From ``cycle`` on the lines are at ``scl``/``sda`` (calls in time order)."""
        if scl == self.scl:
            if sda != self.sda and scl:
                self._start(cycle) if not sda else self._stop(cycle)
            self.sda = sda
            return
        self.scl, self.sda = scl, sda
        cur = self.current
        if cur is None:
            return
        if scl:                                 # a rising edge: read a bit
            if self._bits < 8:
                if self._bits == 0:
                    self._first = cycle
                self._value = (self._value << 1) | sda
                self._bits += 1
            elif self._bits == 8:
                self._byte(cycle, ack=not sda)
                self._bits = 9
        elif self._bits == 9:                   # the ACK clock ended
            self._bits = 0
            self._value = 0

    def _byte(self, cycle: int, ack: bool) -> None:
        cur = self.current
        cur.byte_cycles.append((self._first, cycle))
        if not cur.complete_address:
            cur.address, cur.read, cur.acked, cur.complete_address = self._value >> 1, bool(self._value & 1), ack, True
        else:
            cur.data.append(self._value)
            cur.acks.append(ack)

    def _mid_byte(self, cycle: int, what: str) -> None:
        # the clock that sets up a START or STOP is the first of a byte: from the second on, it is cut
        if 1 < self._bits < 9:
            self.violations.append((cycle, f"I2C {what} in the middle of a byte (after {self._bits} bits)"))

    def _start(self, cycle: int) -> None:
        restart = self.current is not None
        if restart:
            self._mid_byte(cycle, "repeated START")
            self._close(cycle, stopped=False)
        self.current = I2cTransfer(cycle, restart=restart)
        self._bits = self._value = 0

    def _stop(self, cycle: int) -> None:
        if self.current is not None:
            self._mid_byte(cycle, "STOP")
            self._close(cycle, stopped=True)
        self._bits = self._value = 0

    def _close(self, cycle: int, stopped: bool) -> None:
        cur = self.current
        cur.end, cur.stopped = cycle, stopped
        self.transfers.append(cur)
        self.current = None
        if self.on_transfer is not None:
            self.on_transfer(cur)

    def finish(self, cycle: int) -> None:
        """The recording ended at ``cycle``: keep an open transfer (``end`` stays ``None``)."""
        if self.current is not None:
            self.transfers.append(self.current)
            self.current = None


def decode_i2c(trace, scl: int, sda: int) -> I2cDecoder:
    """Decode the I2C bus on ``scl``/``sda`` of a recorded trace (undriven lines read 1).

    Returns:
        the decoder: ``.transfers`` and ``.violations``.

    Raises:
        ValueError: for a pin the trace does not have.
    """
    for p in (scl, sda):
        if not 0 <= p < trace.pin_count:
            raise ValueError(f"pin {p} does not exist (pins are 0..{trace.pin_count - 1})")
    d = I2cDecoder()
    for cycle, (c, s) in level_changes(trace.changes, (scl, sda), idle=1):
        d.feed(cycle, c, s)
    d.finish(trace.end_cycle)
    return d


def i2c_levels(transfers, *, half_bit: int = 100, start: int = 0, acks=None) -> list:
    """The levels ``(cycle, scl, sda)`` of a master sending ``transfers`` (a test signal generator).

    Args:
        transfers: ``(address, read, data)`` each; the transfers follow one
            another with repeated STARTs and end with one STOP.
        half_bit: cycles SCL stays low or high.
        start: the cycle of the first START.
        acks: the ACK bit level after each byte, in order (default: all
            ACKed, i.e. 0: a receiver that acknowledges everything).
    """
    out = [(start, 1, 1)]
    t = start
    acks = list(acks) if acks is not None else None

    def put(scl, sda):
        nonlocal t
        t += half_bit
        out.append((t, scl, sda))

    def byte(value):
        for i in range(7, -1, -1):
            bit = (value >> i) & 1
            put(0, bit)
            put(1, bit)
        ack = acks.pop(0) if acks else 0
        put(0, ack)
        put(1, ack)

    for k, (address, read, data) in enumerate(transfers):
        if k:
            put(0, 1)
            put(1, 1)                   # SCL high with SDA high: ready for a repeated START
        put(1, 0)                       # START: SDA falls while SCL is high
        byte((address << 1) | bool(read))
        for b in data:
            byte(b)
    put(0, 0)
    put(1, 0)
    put(1, 1)                           # STOP: SDA rises while SCL is high
    return out
