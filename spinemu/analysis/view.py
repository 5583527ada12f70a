"""Terminal views of a pin trace: a timeline per pin and a table of changes.

The timeline divides a time window into columns; each column of a pin's row
shows what the pin did during that slice::

    ▔  high the whole slice        ▁  low the whole slice
    ┃  it changed inside the slice ·  nobody drove it

Both views return rich renderables (the CLI prints them); ``plain=True``
gives plain text for files, tests and notebooks.
"""
from __future__ import annotations

from collections.abc import Iterable

from ..trace import PinTrace

__all__ = ["timeline_rows", "render_timeline", "render_changes", "format_time", "parse_pins"]

HIGH, LOW, EDGE, FLOAT = "▔", "▁", "┃", "·"


def format_time(cycle: int, clock_hz: int) -> str:
    """A cycle count as a readable time.

    >>> format_time(80_000_000 * 3 // 2, 80_000_000), format_time(4_000, 80_000_000)
    ('1.500000 s', '50.000 us')
    """
    s = cycle / clock_hz
    if s >= 1:
        return f"{s:.6f} s"
    if s >= 1e-3:
        return f"{s * 1e3:.3f} ms"
    return f"{s * 1e6:.3f} us"


def parse_pins(spec: str, pin_count: int = 32) -> list[int]:
    """Pins from text such as ``"0..4"``, ``"1,3,5"`` or ``"4..7,0"``.

    >>> parse_pins("4..1,0")
    [4, 3, 2, 1, 0]
    >>> parse_pins("0..1000000000")
    Traceback (most recent call last):
    ...
    ValueError: pins must be 0..31, got '0..1000000000'

    Raises:
        ValueError: for text that is not a pin list or a pin out of range.
    """
    pins: list[int] = []
    for part in spec.replace(" ", "").split(","):
        if not part:
            continue
        ends = part.split("..", 1)
        if not all(e.isascii() and e.isdigit() for e in ends):
            raise ValueError(f"pins are numbers 0..{pin_count - 1} or ranges like 0..4, got {part!r}")
        a, b = (int(e) for e in ends) if len(ends) == 2 else (int(ends[0]),) * 2
        # check the ends before building the range: '0..1000000000' must not build a billion pins
        if not (0 <= a < pin_count and 0 <= b < pin_count):
            raise ValueError(f"pins must be 0..{pin_count - 1}, got {part!r}")
        step = 1 if b >= a else -1
        pins.extend(range(a, b + step, step))
    if not pins:
        raise ValueError(f"no pins in {spec!r}; expected e.g. 0..4 or 4..7,0")
    return pins


def _level(d: int, o: int, pin: int) -> str:
    if not (d >> pin & 1):
        return FLOAT
    return HIGH if o >> pin & 1 else LOW


def timeline_rows(trace: PinTrace, pins: Iterable[int] | None = None, start: int = 0,
                  end: int | None = None, width: int = 64) -> dict[int, str]:
    """One string of ``width`` symbols per pin for the window ``[start, end)``.

    >>> t = PinTrace(1000, [(0, 0, 0), (10, 1, 0), (50, 1, 1)], end_cycle=100)
    >>> timeline_rows(t, [0], 0, 100, 10)[0]
    '·┃▁▁▁┃▔▔▔▔'
    """
    end = trace.end_cycle if end is None else end
    end = max(end, start + 1)
    pins = list(trace.driven_pins() if pins is None else pins)
    changes = trace.changes
    rows = {}
    for pin in pins:
        cells = []
        i = 0
        state = (0, 0)
        while i < len(changes) and changes[i][0] <= start:
            state = changes[i][1:]
            i += 1
        for col in range(width):
            c1 = start + (end - start) * (col + 1) // width
            level = _level(state[0], state[1], pin)
            changed = False
            while i < len(changes) and changes[i][0] < c1:
                new = _level(changes[i][1], changes[i][2], pin)
                if new != level:
                    changed = True
                level = new
                state = changes[i][1:]
                i += 1
            cells.append(EDGE if changed else level)
        rows[pin] = "".join(cells)
    return rows


def render_timeline(trace: PinTrace, pins: Iterable[int] | None = None, start: int = 0,
                    end: int | None = None, width: int = 64, plain: bool = False):
    """A timeline of the chosen pins, with the window's times underneath.

    Returns:
        A rich ``Table`` (or ``str`` when ``plain``).
    """
    end = trace.end_cycle if end is None else end
    rows = timeline_rows(trace, pins, start, end, width)
    names = {p: trace.pin_names.get(p, f"P{p}") for p in rows}
    edges = trace.edge_counts()
    t0, t1 = format_time(start, trace.clock_hz), format_time(end, trace.clock_hz)
    axis = t0 + " " * max(1, width - len(t0) - len(t1)) + t1
    if plain:
        label_w = max([len(n) for n in names.values()] + [3])
        lines = [f"{names[p]:>{label_w}} {row}  {edges.get(p, 0)} edges" for p, row in rows.items()]
        lines.append(" " * (label_w + 1) + axis)
        return "\n".join(lines)
    from rich.table import Table
    from rich.text import Text

    table = Table(show_header=True, header_style="bold", box=None, pad_edge=False)
    table.add_column("pin", justify="right")
    table.add_column(axis, no_wrap=True)
    table.add_column("edges", justify="right")
    colors = {HIGH: "green", LOW: "blue", EDGE: "yellow", FLOAT: "dim"}
    for p, row in rows.items():
        text = Text()
        for ch in row:
            text.append(ch, style=colors[ch])
        table.add_row(names[p], text, str(edges.get(p, 0)))
    return table


def render_changes(trace: PinTrace, start: int = 0, end: int | None = None, limit: int = 40,
                   plain: bool = False):
    """The first ``limit`` changes inside the window: time, cycle, masks and what moved."""
    end = trace.end_cycle if end is None else end
    rows = []
    prev = None
    for c, d, o in trace.changes:
        if c > end:
            break
        if c >= start:
            moved = []
            if prev is not None:
                for p in range(trace.pin_count):
                    was, now = _level(prev[0], prev[1], p), _level(d, o, p)
                    if was != now:
                        moved.append(f"P{p}{'↑' if now == HIGH else '↓' if now == LOW else 'z'}")
            rows.append((format_time(c, trace.clock_hz), str(c), f"{d:08x}", f"{o:08x}", " ".join(moved)))
            if len(rows) >= limit:
                break
        prev = (d, o)
    if plain:
        return "\n".join("  ".join(r) for r in rows)
    from rich.table import Table

    table = Table(show_header=True, header_style="bold")
    for name in ("time", "cycle", "dir", "out", "changed"):
        table.add_column(name, justify="right" if name in ("cycle",) else "left")
    for r in rows:
        table.add_row(*r)
    return table
