"""An I2C EEPROM (24LC256, 24LC512) on the pins: the Propeller's boot EEPROM on P28/P29.

Microchip 24LC256 (DS21203) and 24LC512 (DS21754) as the bus sees them:

* the control byte ``1010 A2 A1 A0 R/W`` after a START selects the device
  (``address`` gives A2-A0); it acknowledges by pulling SDA low during the
  9th clock, from the falling edge of the 8th to that of the 9th;
* a write sends two address bytes (high first) and data bytes, each
  acknowledged, into a page buffer (64 bytes on the 24LC256, 128 on the
  24LC512); a STOP on a byte boundary starts the write cycle: the bytes go
  to memory, and for ``write_time`` (5 ms) the device acknowledges nothing
  (the master polls it with control bytes).  Bytes past the end of a page
  wrap to its start (reported as a warning).  A START before the STOP, or a
  STOP in the middle of a byte, writes nothing;
* a read (R/W = 1) sends the byte at the address counter, most significant
  bit first, each bit put on SDA after SCL falls; the master acknowledges to
  get the next byte (the counter rolls over at the end of the memory) or
  leaves SDA high (NAK) and sends a STOP.  A random read is a write of the
  address followed by a repeated START and a read;
* a START or STOP in the middle of a byte the device is receiving or
  sending (after its second clock: the clock that sets up a START or STOP
  is always the first of a byte) resets it and is reported as a warning
  at its cycle.

The bus lines are open drain; the part includes the board's pull-up
resistors, so both lines read 1 unless the program or the EEPROM pulls them
low.  Responses come one clock cycle after the SCL edge that causes them
(the datasheet allows up to 900 ns).  The content starts as ``data``
(padded with erased bytes, ``$FF``); :meth:`I2cEeprom.save_file` writes it to a
file.  On the Propeller the first 32 KB are the boot image
(``spinemu run X.eeprom`` starts with the file loaded).
"""
from __future__ import annotations

import copy
import os
from dataclasses import dataclass, field
from typing import Optional, Union

from .part import ReactivePart, check_pin

__all__ = ["I2cEeprom", "EEPROM_SIZES"]

#: bytes and page size of each supported chip
EEPROM_SIZES = {"24LC256": (32768, 64), "24LC512": (65536, 128)}


@dataclass
class _BusState:
    scl: int = 1
    sda: int = 1
    phase: str = "idle"             # idle, receive, send, ignore
    bits: int = 0                   # bits of the byte being received or sent
    value: int = 0
    index: int = 0                  # bytes of this transfer so far (0: the control byte)
    in_ack: bool = False            # the 9th clock of a byte
    read: bool = False
    ptr: int = 0                    # the address counter
    page: list = field(default_factory=list)   # (address, value) waiting for the STOP
    start: int = 0                  # the address a write began at
    sent: list = field(default_factory=list)   # the data bytes of the write, as sent
    wrapped: bool = False
    busy_until: int = 0
    sending: int = 0
    master_ack: bool = True
    bytes_read: int = 0
    nak_polls: int = 0


class I2cEeprom(ReactivePart):
    """An I2C EEPROM (see the module docstring).

    Args:
        scl, sda: its clock and data pins (default P28, P29: the Propeller's boot EEPROM).
        chip: ``"24LC256"`` (32 KB) or ``"24LC512"`` (64 KB).
        address: its A2-A0 pins (0-7).
        data: the content at power-up (bytes, or a file's path); the rest is ``$FF``.
        write_time: the write cycle (seconds).

    Attributes:
        memory: the content (a ``bytearray``).
        writes: ``(cycle, first address, bytes as sent)`` of each page write
            (bytes past the end of the page went to its start).

    Raises:
        ValueError: for a bad pin, chip name, address, or data longer than the memory.
        OSError: if ``data`` names a file that cannot be read.
    """

    kind = "eeprom"
    pin_parameters = ("scl", "sda")

    def __init__(self, *, scl: int = 28, sda: int = 29, chip: str = "24LC256", address: int = 0,
                 data: Union[bytes, bytearray, str, os.PathLike, None] = None, write_time: float = 5e-3,
                 name: Optional[str] = None):
        super().__init__(name=name)
        self.scl, self.sda = check_pin(scl, "scl"), check_pin(sda, "sda")
        if scl == sda:
            raise ValueError("scl and sda must be different pins")
        chip = chip.upper()
        if chip not in EEPROM_SIZES:
            raise ValueError(f"chip must be one of {', '.join(EEPROM_SIZES)}, not {chip!r}")
        if not (isinstance(address, int) and 0 <= address <= 7):
            raise ValueError(f"address must be 0-7 (the A2-A0 pins), not {address!r}")
        self.chip = chip
        self.size, self.page_size = EEPROM_SIZES[chip]
        self.device = 0x50 | address
        if write_time < 0:
            raise ValueError("write_time must be >= 0 seconds")
        self.write_time = write_time
        self.memory = bytearray(b"\xff" * self.size)
        #: the content was given (else a board's boot EEPROM holds the program: the command line loads it)
        self.data_given = data is not None
        if data is not None:
            self.load(data)
        self.writes: list = []
        self._journal: list = []

    @property
    def name(self) -> str:
        return self._name or f"EEPROM {self.chip} P{self.scl}/P{self.sda}"

    def load(self, data, offset: int = 0) -> None:
        """Put ``data`` (bytes or a file's path) into the memory at ``offset`` (before the run).

        Raises:
            ValueError: if it does not fit.
            OSError: if the file cannot be read.
        """
        if isinstance(data, (str, os.PathLike)):
            with open(data, "rb") as f:
                data = f.read()
        data = bytes(data)
        if offset + len(data) > self.size:
            raise ValueError(f"{len(data)} bytes do not fit in a {self.size}-byte {self.chip} at ${offset:04X}")
        self.memory[offset:offset + len(data)] = data

    def save_file(self, path) -> None:
        """Write the memory to a file (``--eeprom-out``).

        Raises:
            OSError: if the file cannot be written.
        """
        with open(path, "wb") as f:
            f.write(bytes(self.memory))

    def save(self):
        return copy.deepcopy(self.s), len(self._journal), len(self.writes)

    def restore(self, state) -> None:
        s, n_journal, n_writes = state
        self.s = copy.deepcopy(s)
        while len(self._journal) > n_journal:
            addr, old = self._journal.pop()
            self.memory[addr] = old
        del self.writes[n_writes:]

    # ------------------------------------------------------------------ pins
    def driven_pins(self) -> tuple:
        return (self.scl, self.sda)

    def watched_pins(self) -> tuple:
        return (self.scl, self.sda)

    def reset(self) -> None:
        self.s = _BusState()

    def initial_levels(self) -> int:
        return (1 << self.scl) | (1 << self.sda)

    def _drive_sda(self, cycle: int, low: bool) -> None:
        self.output(cycle + 1, (1 << self.scl) | (0 if low else 1 << self.sda))

    def on_drive(self, cycle: int, d: int, o: int) -> None:
        s = self.s
        scl = (o >> self.scl) & 1 if (d >> self.scl) & 1 else 1
        if (d >> self.sda) & 1:
            sda = (o >> self.sda) & 1
        else:
            sda = (self.output_at(cycle) >> self.sda) & 1
        if scl == s.scl:
            if sda != s.sda and scl:
                if sda:
                    self._stop(cycle)
                else:
                    self._start(cycle)
            s.sda = sda
            return
        s.scl, s.sda = scl, sda
        if scl:
            self._rise(sda)
        else:
            self._fall(cycle)

    # ------------------------------------------------------------------ bus conditions
    def _mid_byte(self, cycle: int, what: str) -> bool:
        s = self.s
        # the clock that sets up a START or STOP is the first of a byte: from the second on, it is cut
        if s.phase in ("receive", "send") and 1 < s.bits <= 8 and not s.in_ack:
            self.warn(cycle, f"I2C {what} in the middle of a byte ({s.bits} bits {'sent' if s.phase == 'send' else 'received'})")
            return True
        return False

    def _start(self, cycle: int) -> None:
        s = self.s
        self._mid_byte(cycle, "START")
        if s.page:
            s.page = []                             # no STOP: nothing is written
        s.phase, s.bits, s.value, s.index, s.in_ack, s.wrapped = "receive", 0, 0, 0, False, False
        self._drive_sda(cycle, False)

    def _stop(self, cycle: int) -> None:
        s = self.s
        mid = self._mid_byte(cycle, "STOP")
        if s.phase == "receive" and s.page and not mid and not s.in_ack:
            self._commit(cycle)
        s.page = []
        s.phase, s.bits, s.in_ack = "idle", 0, False
        self._drive_sda(cycle, False)

    def _commit(self, cycle: int) -> None:
        s = self.s
        for addr, value in s.page:
            self._journal.append((addr, self.memory[addr]))
            self.memory[addr] = value
        self.writes.append((cycle, s.start, bytes(s.sent)))
        if s.wrapped:
            self.warn(cycle, f"page write of {len(s.sent)} bytes from ${s.start:04X} went past the end of its "
                             f"{self.page_size}-byte page and wrapped to its start")
        s.ptr = (s.page[-1][0] + 1) % self.size
        s.busy_until = cycle + int(round(self.write_time * self.clock_hz))

    # ------------------------------------------------------------------ clock edges
    def _rise(self, sda: int) -> None:
        s = self.s
        if s.phase == "receive" and not s.in_ack and s.bits < 8:
            s.value = (s.value << 1) | sda
            s.bits += 1
        elif s.phase == "send" and s.in_ack:
            s.master_ack = not sda

    def _fall(self, cycle: int) -> None:
        s = self.s
        if s.phase == "receive":
            if s.in_ack:
                s.in_ack = False
                s.bits = s.value = 0
                if s.index == 1 and s.read:
                    s.phase = "send"
                    self._load_byte(cycle)
                else:
                    self._drive_sda(cycle, False)
            elif s.bits == 8:
                if self._accept(cycle):
                    s.in_ack = True
                    self._drive_sda(cycle, True)
                else:
                    s.phase = "ignore"
        elif s.phase == "send":
            if s.in_ack:
                s.in_ack = False
                if s.master_ack:
                    s.ptr = (s.ptr + 1) % self.size
                    self._load_byte(cycle)
                else:
                    s.ptr = (s.ptr + 1) % self.size
                    s.phase = "ignore"              # the master is done: wait for its STOP
                    self._drive_sda(cycle, False)
            else:
                s.bits += 1
                if s.bits == 8:
                    s.bytes_read += 1
                    s.in_ack = True
                    self._drive_sda(cycle, False)   # let the master acknowledge
                else:
                    self._drive_sda(cycle, not (s.sending >> (7 - s.bits)) & 1)

    def _load_byte(self, cycle: int) -> None:
        s = self.s
        s.sending = self.memory[s.ptr]
        s.bits = 0
        s.master_ack = True
        self._drive_sda(cycle, not (s.sending >> 7) & 1)

    def _accept(self, cycle: int) -> bool:
        """A whole byte was received: does the device acknowledge it?"""
        s = self.s
        v, index = s.value, s.index
        s.index += 1
        if index == 0:
            if v >> 1 != self.device:
                return False
            if cycle < s.busy_until:
                s.nak_polls += 1
                return False
            s.read = bool(v & 1)
            return True
        if s.read:
            return False
        if index == 1:
            s.ptr = (v << 8) & (self.size - 1)
        elif index == 2:
            s.ptr = (s.ptr | v) & (self.size - 1)
            s.start, s.sent = s.ptr, []
        else:
            n = index - 3
            s.sent.append(v)
            page = s.ptr & ~(self.page_size - 1)
            addr = page | ((s.ptr + n) & (self.page_size - 1))
            if n >= self.page_size:
                s.wrapped = True
                s.page = [(a, x) for a, x in s.page if a != addr]
            s.page.append((addr, v))
        return True

    # ------------------------------------------------------------------ reports
    def written_addresses(self, write) -> list:
        """The addresses a page write ``(cycle, first, data)`` went to, in the order sent."""
        _, first, data = write
        page = first & ~(self.page_size - 1)
        return [page | ((first + n) & (self.page_size - 1)) for n in range(len(data))]

    @property
    def bytes_written(self) -> int:
        """Bytes of memory written (a byte written twice in one page write counts once)."""
        return sum(len(set(self.written_addresses(w))) for w in self.writes)

    @property
    def bytes_read(self) -> int:
        return self.s.bytes_read

    def summary(self) -> str:
        w = self.writes
        if w:
            addresses = [a for x in w for a in self.written_addresses(x)]
            lo, hi = min(addresses), max(addresses)
            wrote = (f"{self.bytes_written} bytes written in {len(w)} page write{'s' if len(w) != 1 else ''} "
                     f"(${lo:04X}-${hi:04X})")
        else:
            wrote = "nothing written"
        return f"{self.name}: {wrote}, {self.bytes_read} bytes read"

    def view(self) -> str:
        s = self.s
        return f"{self.bytes_written} written, {self.bytes_read} read, {s.phase}"
