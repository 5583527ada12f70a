"""Character LCDs: the HD44780 controller on parallel pins (4- or 8-bit), and a serial LCD.

:class:`Lcd` is the Hitachi HD44780U (datasheet ADE-207-272(Z), '99.9, rev.
0.0: "Instructions" table 6, "Interfacing to the MPU", "Initializing by
Instruction", DDRAM addresses figures 4-7) as the pins see it:

* a write is latched when E falls (RS: 0 instruction, 1 data); in 4-bit
  mode (data on D4-D7) two writes make a byte, high nibble first.  The
  controller starts in 8-bit mode; a function set with DL = 0 switches it
  to 4 bits (D0-D3 unconnected read 0);
* with an R/W pin, a read (R/W high) puts the busy flag and address counter
  (RS 0) or the data at the address counter (RS 1) on the data pins while E
  is high; the part then drives those pins, otherwise it leaves them alone;
* each instruction keeps the controller busy: 1.52 ms for clear display and
  return home, 37 us for the others and for data (fosc = 270 kHz); after
  power-on it is busy for 15 ms.  An instruction while busy is carried out
  anyway and reported as a warning (a real controller may lose it);
* the screen: ``lines`` x ``columns`` characters; line ``r`` shows DDRAM from
  ``(r % 2) * 0x40 + (r // 2) * columns``, shifted by the display shift.
  Character codes 0x20-0x7D are ASCII (0x5C shows as a yen sign on the A00
  ROM, kept as a backslash here); codes 0-7 and 8-15 are the user-defined
  characters (shown as ``█``), the others ``?``.

:class:`SerialLcd` is a Parallax serial LCD (#27977 family: 2 x 16 or 4 x 20
behind a UART input; Parallax "Serial LCD" documentation, command set table):
bytes at the baud rate on one pin, 8 = left, 9 = right, 10 = down, 12 =
clear, 13 = carriage return, 17/18 = backlight on/off, 21 = display off,
22-25 = on (cursor and blink variants), 128 + position = move the cursor
(positions of 20 per line on a 4-line display, 20 on a 2-line one starting
at 148), 248-255 = define a character (8 bytes follow); sound commands
(208-232) are accepted and ignored.
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Optional, Sequence

from .part import Part, ReactivePart, check_pin, pins_mask
from .uart import UartDecoder, UartFormat

__all__ = ["Lcd", "SerialLcd", "lcd_char"]

_CLEAR_HOME_US = 1520
_OTHER_US = 37
_POWER_ON_US = 15_000


def lcd_char(code: int) -> str:
    """How a character code shows on the A00 ROM (user-defined characters as ``█``)."""
    if code < 16:
        return "\u2588"
    if 0x20 <= code <= 0x7D:
        return chr(code)
    return "?"


def _screen_lines(ddram, lines: int, columns: int, shift: int, two_line: bool) -> tuple:
    """The text on the screen: in two-line mode row ``r`` shows line ``r % 2`` of DDRAM from
    ``(r // 2) * columns``; in one-line mode the first row shows DDRAM from 0 and the others stay blank."""
    out = []
    for r in range(lines):
        if two_line:
            line, offset = r % 2, (r // 2) * columns
            row = "".join(lcd_char(ddram[line * 40 + (offset + c + shift) % 40]) for c in range(columns))
        elif r == 0:
            row = "".join(lcd_char(ddram[(c + shift) % 80]) for c in range(columns))
        else:
            row = " " * columns
        out.append(row)
    return tuple(out)


@dataclass
class _LcdState:
    ddram: bytearray = field(default_factory=lambda: bytearray(b" " * 80))
    cgram: bytearray = field(default_factory=lambda: bytearray(64))
    ac: int = 0
    to_cgram: bool = False
    increment: bool = True
    shift_on_write: bool = False
    display_on: bool = False
    cursor: bool = False
    blink: bool = False
    two_line: bool = False
    eight_bit: bool = True
    high_nibble: Optional[int] = None     # 4-bit mode: the first half of a byte written
    read_half: int = 0                    # 4-bit mode: which half of a byte a read gives next
    shift: int = 0
    busy_until: int = 0
    e: int = 0
    writes: int = 0                       # characters written
    instructions: int = 0
    busy_violations: int = 0


class Lcd(ReactivePart):
    """An HD44780 character LCD on parallel pins (see the module docstring).

    Args:
        rs, e: the register-select and enable pins.
        data: D4-D7 (4-bit mode) or D0-D7 (8-bit), in that order.
        rw: the read/write pin (``None``: tied low, the program only writes).
        lines, columns: the display's size (2 x 16 default).

    Attributes:
        screens: ``(cycle, lines)`` each time the text on the screen changed.

    Raises:
        ValueError: for a bad pin, a data bus that is not 4 or 8 pins, or a pin used twice.
    """

    kind = "lcd"
    pin_parameters = ("rs", "e", "rw", "data")

    def __init__(self, *, rs: int, e: int, data: Sequence[int], rw: Optional[int] = None, lines: int = 2,
                 columns: int = 16, name: Optional[str] = None):
        super().__init__(name=name)
        self.rs, self.e = check_pin(rs, "rs"), check_pin(e, "e")
        self.rw = None if rw is None else check_pin(rw, "rw")
        self.data = tuple(check_pin(p, "data pin") for p in data)
        if len(self.data) not in (4, 8):
            raise ValueError(f"an LCD's data bus is 4 pins (D4-D7) or 8 pins (D0-D7), not {len(self.data)}")
        pins = [self.rs, self.e, *self.data] + ([self.rw] if self.rw is not None else [])
        if len(set(pins)) != len(pins):
            raise ValueError("an LCD needs a different pin for RS, E, R/W and each data line")
        if lines not in (1, 2, 4) or not 8 <= columns <= 40:
            raise ValueError(f"an HD44780 display has 1, 2 or 4 lines of 8 to 40 characters, not {lines} x {columns}")
        self.lines, self.columns = lines, columns
        self.screens: list = []

    @property
    def name(self) -> str:
        return self._name or f"LCD {self.lines}x{self.columns}"

    def driven_pins(self) -> tuple:
        return self.data if self.rw is not None else ()

    def watched_pins(self) -> tuple:
        return tuple(p for p in (self.rs, self.e, self.rw) if p is not None) + self.data

    releases = True

    # ------------------------------------------------------------------ state
    def reset(self) -> None:
        self.s = _LcdState()
        self.s.busy_until = int(_POWER_ON_US * self.clock_hz // 1_000_000)
        self.screens = [(0, self._lines())]

    def initial_levels(self) -> int:
        return pins_mask(self.data) << 32           # data pins released

    def save(self):
        return copy.deepcopy(self.s), len(self.screens)

    def restore(self, state) -> None:
        s, n = state
        self.s = copy.deepcopy(s)
        del self.screens[n:]

    def released(self, cycle: int) -> int:
        self._sync(cycle)
        return self.output_at(cycle) >> 32

    def levels(self, cycle: int) -> int:
        return super().levels(cycle) & 0xFFFFFFFF

    # ------------------------------------------------------------------ the pins
    def on_drive(self, cycle: int, d: int, o: int) -> None:
        s = self.s
        e = (o >> self.e) & 1
        if e == s.e:
            return
        s.e = e
        rw = (o >> self.rw) & 1 if self.rw is not None else 0
        rs = (o >> self.rs) & 1
        if rw:
            if e:
                self._put_read(cycle, rs)
            else:
                self.output(cycle + 1, pins_mask(self.data) << 32)     # release the bus
                self._read_done(rs)
            return
        if e:
            return
        value = 0
        for i, p in enumerate(self.data):
            value |= ((o >> p) & 1) << i
        if len(self.data) == 4:
            value <<= 4
            if not s.eight_bit:
                if s.high_nibble is None:
                    s.high_nibble = value
                    return
                value, s.high_nibble = s.high_nibble | (value >> 4), None
        self._write(cycle, rs, value)

    def _us(self, us: int) -> int:
        return us * self.clock_hz // 1_000_000

    def _write(self, cycle: int, rs: int, value: int) -> None:
        s = self.s
        if cycle < s.busy_until:
            s.busy_violations += 1
            if s.busy_violations <= 5:
                self.warn(cycle, f"{'data' if rs else 'instruction'} ${value:02X} written while the LCD was "
                                 f"busy ({(s.busy_until - cycle) * 1e6 / self.clock_hz:.0f} us before it was ready)")
        if rs:
            self._data(value)
            s.busy_until = cycle + self._us(_OTHER_US)
        else:
            s.instructions += 1
            s.busy_until = cycle + self._us(self._instruction(value))
        lines = self._lines()
        if lines != self.screens[-1][1]:
            self.screens.append((cycle, lines))

    def _instruction(self, v: int) -> int:
        """Carry out instruction ``v``; returns its execution time in us."""
        s = self.s
        if v == 0x01:                                       # clear display
            s.ddram[:] = b" " * 80
            s.ac, s.to_cgram, s.shift, s.increment = 0, False, 0, True
            return _CLEAR_HOME_US
        if v & 0xFE == 0x02:                                # return home
            s.ac, s.to_cgram, s.shift = 0, False, 0
            return _CLEAR_HOME_US
        if v & 0xFC == 0x04:                                # entry mode set
            s.increment, s.shift_on_write = bool(v & 2), bool(v & 1)
        elif v & 0xF8 == 0x08:                              # display on/off control
            s.display_on, s.cursor, s.blink = bool(v & 4), bool(v & 2), bool(v & 1)
        elif v & 0xF0 == 0x10:                              # cursor or display shift
            step = 1 if v & 4 else -1
            if v & 8:
                s.shift = (s.shift - step) % 80
            else:
                self._move(step)
        elif v & 0xE0 == 0x20:                              # function set
            s.eight_bit = bool(v & 0x10)
            s.two_line = bool(v & 0x08)
            s.high_nibble = None
        elif v & 0xC0 == 0x40:                              # set CGRAM address
            s.ac, s.to_cgram = v & 0x3F, True
        elif v & 0x80:                                      # set DDRAM address
            s.ac, s.to_cgram = v & 0x7F, False
        return _OTHER_US

    def _index(self, ac: int) -> int:
        """DDRAM address to an index of ``ddram`` (two lines of 40, or one of 80)."""
        if self.s.two_line:
            return (40 if ac & 0x40 else 0) + (ac & 0x3F) % 40
        return ac % 80

    def _move(self, step: int) -> None:
        s = self.s
        if s.to_cgram:
            s.ac = (s.ac + step) & 0x3F
        elif s.two_line:
            i = (self._index(s.ac) + step) % 80
            s.ac = (0x40 + i - 40) if i >= 40 else i
        else:
            s.ac = (s.ac + step) % 80

    def _data(self, value: int) -> None:
        s = self.s
        if s.to_cgram:
            s.cgram[s.ac & 0x3F] = value
        else:
            s.ddram[self._index(s.ac)] = value
            s.writes += 1
            if s.shift_on_write:
                s.shift = (s.shift + (1 if s.increment else -1)) % 80
        self._move(1 if s.increment else -1)

    def _read_value(self, cycle: int, rs: int) -> int:
        s = self.s
        if not rs:
            return (0x80 if cycle < s.busy_until else 0) | (s.ac & 0x7F)
        return s.cgram[s.ac & 0x3F] if s.to_cgram else s.ddram[self._index(s.ac)]

    def _put_read(self, cycle: int, rs: int) -> None:
        s = self.s
        v = self._read_value(cycle + 1, rs)
        if len(self.data) == 4:
            v = (v >> 4) if s.eight_bit or s.read_half == 0 else v & 0xF
        levels = sum(((v >> i) & 1) << p for i, p in enumerate(self.data))
        self.output(cycle + 1, levels)

    def _read_done(self, rs: int) -> None:
        s = self.s
        if len(self.data) == 4 and not s.eight_bit:
            s.read_half ^= 1
            if s.read_half:
                return
        if rs:
            self._move(1 if s.increment else -1)

    # ------------------------------------------------------------------ reports
    def _lines(self) -> tuple:
        s = self.s
        return _screen_lines(s.ddram, self.lines, self.columns, s.shift, s.two_line)

    def text_lines(self) -> list[str]:
        """The screen now (each line's trailing blanks removed)."""
        return [line.rstrip() for line in self.screens[-1][1]]

    def text_at(self, seconds: float) -> list[str]:
        """The screen at ``seconds`` of the run."""
        cycle = seconds * self.clock_hz
        shown = self.screens[0][1]
        for c, lines in self.screens:
            if c > cycle:
                break
            shown = lines
        return [line.rstrip() for line in shown]

    def summary(self) -> str:
        s = self.s
        text = " / ".join(repr(line) for line in self.text_lines())
        state = "" if s.display_on else " (display off)"
        return f"{self.name}: {text}{state}; {s.writes} characters written"

    def view(self) -> str:
        return "\n".join(f"|{line}|" for line in self.screens[-1][1])


class SerialLcd(Part):
    """A Parallax serial LCD on one pin (see the module docstring).

    Args:
        pin: the LCD's RX pin (the program's TX).
        baud: 2400, 9600 or 19200 (the LCD's switches), or any rate.
        lines, columns: 2 x 16 (default) or 4 x 20.
        inverted: the program sends inverted serial (the LCD takes true mode).

    Attributes:
        screens: ``(cycle, lines)`` each time the text changed.
    """

    kind = "serial-lcd"

    def __init__(self, *, pin: int, baud: float = 9600, lines: int = 2, columns: int = 16,
                 inverted: bool = False, name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        self.format = UartFormat(baud, inverted=inverted)
        if (lines, columns) not in ((2, 16), (4, 20), (4, 16), (2, 20)):
            raise ValueError(f"a serial LCD is 2 x 16, 2 x 20, 4 x 16 or 4 x 20, not {lines} x {columns}")
        self.lines, self.columns = lines, columns
        self.rows = [[" "] * columns for _ in range(lines)]
        self.x = self.y = 0
        self.display_on = True
        self.backlight = False
        self.screens: list = [(0, self._lines())]
        self.bytes = 0
        self._skip = 0
        self._level = self.format.idle

    @property
    def name(self) -> str:
        return self._name or f"serial LCD P{self.pin}"

    def watched_pins(self) -> tuple:
        return (self.pin,)

    def connect(self, port) -> None:
        super().connect(port)
        self._decoder = UartDecoder(self.format, port.clock_hz, on_frame=self._frame)

    def on_pins(self, changes, upto, present) -> None:
        pin, idle = self.pin, self.format.idle
        for c, d, o in changes:
            level = (o >> pin) & 1 if (d >> pin) & 1 else idle
            if level != self._level:
                self._level = level
                self._decoder.feed(c, level)
        self._decoder.advance(upto)

    def _lines(self) -> tuple:
        return tuple("".join(r) for r in self.rows)

    def _frame(self, frame) -> None:
        if frame.error:
            self.warn(frame.start, f"serial frame without a stop bit (a different baud rate than {self.format.baud:g}?)")
            return
        self.bytes += 1
        b = frame.value
        if self._skip:
            self._skip -= 1
            return
        cols, lines = self.columns, self.lines
        if 32 <= b < 128:
            self.rows[self.y][self.x] = lcd_char(b)
            self.x += 1
            if self.x >= cols:
                self.x, self.y = 0, (self.y + 1) % lines
        elif b < 8:
            self.rows[self.y][self.x] = lcd_char(b)
            self.x = (self.x + 1) % cols
        elif b == 8:
            self.x = max(0, self.x - 1)
        elif b == 9:
            self.x = min(cols - 1, self.x + 1)
        elif b == 10:
            self.y = (self.y + 1) % lines
        elif b == 12:
            self.rows = [[" "] * cols for _ in range(lines)]
            self.x = self.y = 0
        elif b == 13:
            self.x, self.y = 0, (self.y + 1) % lines
        elif b in (17, 18):
            self.backlight = b == 17
        elif b == 21:
            self.display_on = False
        elif 22 <= b <= 25:
            self.display_on = True
        elif 128 <= b < 128 + 20 * lines:
            row, col = divmod(b - 128, 20)
            self.x, self.y = min(col, cols - 1), row % lines
        elif b >= 248:
            self._skip = 8
        lines_now = self._lines()
        if lines_now != self.screens[-1][1]:
            self.screens.append((frame.start, lines_now))

    def text_lines(self) -> list[str]:
        return [line.rstrip() for line in self.screens[-1][1]]

    def summary(self) -> str:
        text = " / ".join(repr(line) for line in self.text_lines())
        return f"{self.name}: {text}; {self.bytes} bytes received"

    def view(self) -> str:
        return "\n".join(f"|{line}|" for line in self.screens[-1][1])
