"""Pin traces: what every pin did and when, and the files they are written to.

A :class:`PinTrace` is the record a chip model (the Propeller emulator or the
BASIC Stamp interpreter) produces: the state of the pins after every change,
stamped with the clock cycle at which it happened.  Each state is two 32-bit
masks, exactly as in the reference traces (``tests/data/README.md``):

* ``dir``: pins driven by someone (the OR of DIRA over running cogs);
* ``out``: pins driven high (the OR over running cogs of DIRA & OUTA).

A pin with its ``dir`` bit clear floats: it reads as ``z`` in a VCD file.

Writers:

* :meth:`PinTrace.write_log` - the ``<cycle> <dir> <out>`` text format, one
  line per change, hex masks of 8 digits;
* :meth:`PinTrace.write_vcd` - IEEE 1364 value change dump for GTKWave and
  PulseView: one wire per pin that was ever driven, ``z`` while undriven,
  the timescale chosen so that one clock cycle is a whole number of units.

This module is a shared leaf: it imports nothing from the project.
"""
from __future__ import annotations

import io
from collections.abc import Iterable
from io import TextIOBase

from .records import Record

__all__ = ["PinTrace", "TraceFormatError", "read_log", "vcd_timescale"]

#: VCD time units, as (name, powers of ten below a second)
_UNITS = [("s", 0), ("ms", 3), ("us", 6), ("ns", 9), ("ps", 12), ("fs", 15)]


def vcd_timescale(clock_hz: int) -> tuple[str, int]:
    """The coarsest VCD timescale in which one clock period is a whole number.

    Returns ``(timescale, units_per_cycle)``.

    >>> vcd_timescale(80_000_000)   # 12.5 ns per cycle
    ('100 ps', 125)
    >>> vcd_timescale(1_000_000)
    ('1 us', 1)
    """
    for name, exp in _UNITS:
        for mult in (100, 10, 1):
            # one period in units of mult * 10**-exp s: 10**exp / (clock_hz * mult), when whole
            units, rest = divmod(10**exp, clock_hz * mult)
            if rest == 0 and units:
                return f"{mult} {name}", units
    # A clock this odd cannot be represented exactly: round to femtoseconds.
    return "1 fs", max(1, round(10**15 / clock_hz))


class PinTrace(Record):
    """Every change of the pins with the cycle it happened at.

    Args:
        clock_hz: cycles per second of the time base (80 MHz for the column's
            Propeller programs).
        changes: ``(cycle, dir_mask, out_mask)`` in time order; the first entry
            is the state at the start of the run.
        end_cycle: the cycle at which the run ended.
        pin_count: number of pins the masks describe (32 on the Propeller,
            16 on the BASIC Stamp).
        pin_names: optional names for pins, e.g. ``{4: "P4"}``.

    >>> t = PinTrace(80_000_000, [(0, 0, 0), (1000, 0x1f, 0), (1608, 0x1f, 1)], 2000)
    >>> print(t.log_text(), end="")
    0 00000000 00000000
    1000 0000001f 00000000
    1608 0000001f 00000001
    >>> t.edge_counts()
    {0: 1}
    """

    _fields = ("clock_hz", "changes", "end_cycle", "pin_count", "pin_names")

    def __init__(self, clock_hz: int, changes: list | None = None, end_cycle: int = 0, pin_count: int = 32,
                 pin_names: dict | None = None):
        if not clock_hz > 0:            # every time in seconds divides by it
            raise ValueError(f"a trace's clock must be above 0 Hz, not {clock_hz!r}")
        self.clock_hz = clock_hz
        self.changes = [] if changes is None else changes
        self.end_cycle = end_cycle
        self.pin_count = pin_count
        self.pin_names = {} if pin_names is None else pin_names

    # ------------------------------------------------------------------ access
    def record(self, cycle: int, dir_mask: int, out_mask: int) -> None:
        """Append a state if it differs from the last one."""
        ch = self.changes
        if ch and ch[-1][1] == dir_mask and ch[-1][2] == out_mask:
            return
        ch.append((cycle, dir_mask, out_mask))

    def state_at(self, cycle: int) -> tuple[int, int]:
        """``(dir, out)`` in force at ``cycle``."""
        state = (0, 0)
        for c, d, o in self.changes:
            if c > cycle:
                break
            state = (d, o)
        return state

    @property
    def seconds(self) -> float:
        """Simulated time covered by the trace."""
        return self.end_cycle / self.clock_hz

    def driven_pins(self) -> list[int]:
        """Pins whose dir bit was ever set, lowest first."""
        mask = 0
        for _, d, _ in self.changes:
            mask |= d
        return [p for p in range(self.pin_count) if mask >> p & 1]

    def pin_levels(self, pin: int) -> list[tuple[int, str]]:
        """The changes of one pin as ``(cycle, '0'|'1'|'z')``."""
        out = []
        last = None
        for c, d, o in self.changes:
            v = "z" if not (d >> pin & 1) else ("1" if o >> pin & 1 else "0")
            if v != last:
                out.append((c, v))
                last = v
        return out

    def edge_counts(self) -> dict[int, int]:
        """Rising plus falling edges of each driven pin (z changes not counted)."""
        counts: dict[int, int] = {}
        pins = (1 << self.pin_count) - 1
        prev = None
        for _, d, o in self.changes:
            level = d & o
            if prev is not None:
                edges = d & prev[0] & (level ^ prev[1]) & pins     # driven before and after, level changed
                while edges:
                    low = edges & -edges
                    p = low.bit_length() - 1
                    counts[p] = counts.get(p, 0) + 1
                    edges ^= low
            prev = (d, level)
        return dict(sorted(counts.items()))

    # ------------------------------------------------------------------ writers
    def log_text(self) -> str:
        buf = io.StringIO()
        self.write_log(buf)
        return buf.getvalue()

    def write_log(self, fp: TextIOBase) -> None:
        """``<cycle> <dir> <out>`` lines, the format of the reference traces."""
        fp.writelines(f"{c} {d:08x} {o:08x}\n" for c, d, o in self.changes)

    def write_vcd(self, fp: TextIOBase, *, module: str = "chip", date: str | None = None,
                  pins: Iterable[int] | None = None) -> None:
        """A value change dump of every pin that was ever driven.

        Args:
            fp: text stream to write to.
            module: the VCD scope name.
            date: text for ``$date`` (left out when ``None``, for reproducible files).
            pins: the pins to include (default: every pin ever driven).
        """
        timescale, per_cycle = vcd_timescale(self.clock_hz)
        pins = list(self.driven_pins() if pins is None else pins)
        ids = {p: _vcd_id(i) for i, p in enumerate(pins)}
        w = fp.write
        if date:
            w(f"$date {date} $end\n")
        w("$version spinemu $end\n")
        w(f"$timescale {timescale} $end\n")
        w(f"$scope module {module} $end\n")
        for p in pins:
            name = self.pin_names.get(p, f"P{p}")
            w(f"$var wire 1 {ids[p]} {name} $end\n")
        w("$upscope $end\n$enddefinitions $end\n")
        last: dict[int, str] = {}
        first = True
        for c, d, o in self.changes:
            vals = []
            for p in pins:
                v = "z" if not (d >> p & 1) else ("1" if o >> p & 1 else "0")
                if last.get(p) != v:
                    vals.append(f"{v}{ids[p]}")
                    last[p] = v
            if first:
                w(f"#{c * per_cycle}\n$dumpvars\n")
                w("".join(x + "\n" for x in vals))
                w("$end\n")
                first = False
            elif vals:
                w(f"#{c * per_cycle}\n")
                w("".join(x + "\n" for x in vals))
        if self.end_cycle and (not self.changes or self.end_cycle > self.changes[-1][0]):
            w(f"#{self.end_cycle * per_cycle}\n")

    def vcd_text(self, **kw) -> str:
        buf = io.StringIO()
        self.write_vcd(buf, **kw)
        return buf.getvalue()


def _vcd_id(n: int) -> str:
    """Short printable VCD identifiers: '!', '"', ... then two characters."""
    chars = [chr(c) for c in range(33, 127)]
    s = ""
    n += 1
    while n:
        n, r = divmod(n - 1, len(chars))
        s = chars[r] + s
    return s


class TraceFormatError(ValueError):
    """A malformed line in a trace log; ``line`` is 1-based, ``text`` the line itself."""

    def __init__(self, message: str, line: int, text: str):
        super().__init__(f"line {line}: {message}")
        self.message, self.line, self.text = message, line, text


def read_log(text: str, clock_hz: int = 80_000_000, pin_count: int = 32) -> PinTrace:
    """Parse ``<cycle> <dir> <out>`` lines (``#`` comments allowed) into a trace.

    Raises:
        TraceFormatError: on a malformed line (with its line number).

    >>> read_log("4 00000000 00000000\\n1000 0000001f 00000000\\n").changes
    [(4, 0, 0), (1000, 31, 0)]
    """
    trace = PinTrace(clock_hz, pin_count=pin_count)
    for n, line in enumerate(text.splitlines(), 1):
        parts = line.split()
        if not parts or parts[0].startswith("#"):
            continue
        try:
            if len(parts) != 3:
                raise ValueError
            c, d, o = int(parts[0]), int(parts[1], 16), int(parts[2], 16)
        except ValueError:
            raise TraceFormatError("expected '<cycle> <dir> <out>' (decimal cycle, hex masks)", n, line) from None
        trace.changes.append((c, d, o))
        trace.end_cycle = max(trace.end_cycle, c)
    return trace
