"""Runtime warnings: the classic Propeller mistakes a run can see, reported at the Spin line.

A run (of any engine) calls :meth:`WarningLog.warn` when a program does
something that works on the chip but is almost never meant:

=====================  ==================================================================
kind                   what
=====================  ==================================================================
``waitcnt-passed``     ``waitcnt`` for a count that has already passed: the cog stalls
                       until CNT comes round again (up to 2**32 cycles, 53.7 s at 80 MHz)
``stack-overflow``     a cog's stack grows past the array given to ``cognew``
``no-free-cog``        ``cognew`` when all eight cogs run: it returns -1, nothing starts
``pin-conflict``       one cog drives a pin low while another drives it high (the pins
                       OR the cogs' outputs, so it stays high)
``write-outside-hub``  a hub write through a pointer past hub RAM ($8000 and up: lost)
``write-into-code``    a hub write into the program's own code or object tables
``uninitialized``      a local read before it is assigned (it holds leftover stack)
=====================  ==================================================================

Each place warns once (further hits are counted); places are hub addresses,
turned into ``file:line:col`` by the ``locate`` function the engine passes.
With ``werror`` the first warning raises :class:`RuntimeWarningError`
instead, which stops the run.  The message texts are written here, from
plain numbers and names, so that every engine says the same thing.

This module is a shared leaf: it imports nothing from the project but
:mod:`spinemu.diagnostics`.

>>> log = WarningLog()
>>> w = log.warn("no-free-cog", no_free_cog("the Spin method blink"), cog=0, addr=0x40, cycle=100)
>>> w.kind, w.count, log.warn("no-free-cog", "again", cog=0, addr=0x40, cycle=200) is None, w.count
('no-free-cog', 1, True, 2)
"""
from __future__ import annotations

from collections.abc import Callable

from .diagnostics import Diagnostic, EmulationError
from .records import Record

__all__ = ["KINDS", "RunWarning", "WarningLog", "RuntimeWarningError", "waitcnt_passed", "stack_overflow",
           "no_free_cog", "pin_conflict", "write_outside_hub", "write_into_code", "uninitialized_local",
           "format_seconds"]

KINDS = ("waitcnt-passed", "stack-overflow", "no-free-cog", "pin-conflict", "write-outside-hub",
         "write-into-code", "uninitialized")


class RunWarning(Record):
    """One warning: what, where (cog, hub address, source place), when, and how often.

    Attributes:
        kind: one of :data:`KINDS`.
        message: the text, in the user's words.
        cog: the cog that did it.
        addr: hub address of the bytecode (or instruction) that did it; -1 when the engine has none.
        cycle: when it happened first.
        path, line, column, source_line: the Spin place, when known.
        count: how many times this place did it.
    """

    _fields = ("kind", "message", "cog", "addr", "cycle", "path", "line", "column", "source_line", "count")

    def __init__(self, kind: str, message: str, cog: int, addr: int, cycle: int, path: str | None = None,
                 line: int | None = None, column: int | None = None, source_line: str | None = None,
                 count: int = 1):
        self.kind, self.message, self.cog, self.addr, self.cycle = kind, message, cog, addr, cycle
        self.path, self.line, self.column, self.source_line = path, line, column, source_line
        self.count = count

    def diagnostic(self, severity: str = "warning") -> Diagnostic:
        """As a :class:`Diagnostic`: ``file:line:col: warning: ...`` with the source line and a caret."""
        text = f"{self.message} [cog {self.cog}, cycle {self.cycle:,}]"
        if self.path is None and self.addr >= 0:
            text += f" (bytecode at ${self.addr:04X})"
        return Diagnostic(text, self.path or "<image>", self.line, self.column, self.source_line, severity)

    def render(self) -> str:
        return self.diagnostic().render()

    def location(self) -> str:
        return self.diagnostic().location()


class RuntimeWarningError(EmulationError):
    """A runtime warning while warnings are errors (``-Werror``); ``.warning`` is the :class:`RunWarning`."""

    def __init__(self, warning: RunWarning):
        self.warning = warning
        d = warning.diagnostic("error")
        super().__init__(diagnostics=[Diagnostic(d.message + " (warnings are errors)", d.path, d.line, d.column,
                                                 d.source_line, "error")])


class WarningLog:
    """Collects runtime warnings, one per place.

    Args:
        locate: ``hub address -> (path, line, col)`` (or ``(path, line)``), or ``None``.
        source_line: ``(path, line) -> text`` for the caret line, or ``None``.
        werror: raise :class:`RuntimeWarningError` at the first warning.
        sink: called with each new :class:`RunWarning` as it happens (the CLI
            prints it to stderr at once).
        enabled: the kinds to report (default: all of :data:`KINDS`).
    """

    def __init__(self, locate: Callable | None = None, source_line: Callable | None = None,
                 werror: bool = False, sink: Callable | None = None, enabled=KINDS):
        self.locate = locate
        self.source_line = source_line
        self.werror = werror
        self.sink = sink
        self.enabled = frozenset(enabled)
        self.items: list = []
        self._places: dict = {}
        #: warnings reported so far, repeats included (the fast-forward parks no loop that warns)
        self.total = 0

    def wants(self, kind: str) -> bool:
        return kind in self.enabled

    def warn(self, kind: str, message: str, cog: int, addr: int, cycle: int) -> RunWarning | None:
        """Report ``message`` for the bytecode at ``addr``; returns the new warning, or ``None`` if that
        place has warned about ``kind`` before (its count goes up).

        Raises:
            RuntimeWarningError: when warnings are errors.
        """
        if kind not in self.enabled:
            return None
        self.total += 1
        where = None
        if self.locate is not None and addr >= 0:
            try:
                where = self.locate(addr & 0xFFFF)
            except Exception:  # a broken map must not hide the warning
                where = None
        place = (kind, tuple(where) if where else (addr & 0xFFFF if addr >= 0 else ("cog", cog)))
        seen = self._places.get(place)
        if seen is not None:
            seen.count += 1
            return None
        w = RunWarning(kind, message, cog, addr & 0xFFFF if addr >= 0 else -1, cycle)
        if where:
            w.path, w.line = where[0], where[1]
            w.column = where[2] if len(where) > 2 else None
            if self.source_line is not None:
                w.source_line = self.source_line(w.path, w.line)
        self._places[place] = w
        self.items.append(w)
        if self.werror:
            raise RuntimeWarningError(w)
        if self.sink is not None:
            self.sink(w)
        return w


# ----------------------------------------------------------------------------- message texts
def format_seconds(seconds: float) -> str:
    """``53.69 s``, ``1.25 ms``, ``310 us``.

    >>> format_seconds(53.687), format_seconds(0.00125), format_seconds(0.00031)
    ('53.69 s', '1.25 ms', '310 us')
    """
    if seconds >= 1:
        return f"{seconds:.2f} s"
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.2f} ms"
    return f"{seconds * 1e6:.0f} us"


def waitcnt_passed(target: int, late: int, stall: int, clock_hz: int) -> str:
    """``waitcnt(target)`` issued ``late`` cycles after the target: the cog stalls ``stall`` cycles.

    >>> print(waitcnt_passed(80_000, 1_200_000, 4_293_847_296, 80_000_000))  # doctest: +NORMALIZE_WHITESPACE
    waitcnt for a count that passed 1,200,000 cycles ago: the cog stalls 53.67 s (4,293,847,296 cycles
    at 80 MHz) until CNT comes round again; the target 80,000 looks like a delay, not a time: is '+ cnt'
    missing?
    """
    mhz = f"{clock_hz / 1e6:g} MHz" if clock_hz else "the image's clock"
    stall_time = format_seconds(stall / clock_hz) if clock_hz else f"{stall:,} cycles"
    text = (f"waitcnt for a count that passed {late:,} cycles ago: the cog stalls {stall_time} "
            f"({stall:,} cycles at {mhz}) until CNT comes round again; ")
    if target < late:
        return text + f"the target {target:,} looks like a delay, not a time: is '+ cnt' missing?"
    return text + ("the delay is shorter than the code between reading CNT (or the last target) and "
                   "this wait; in a 'c += delay' loop, the loop takes longer than the delay")


def stack_overflow(cog: int, array: str, where: str, array_addr: int, array_bytes: int, method: str,
                   callee: str, needs: int, over: int) -> str:
    """A cog's stack passes the end of the array given to cognew."""
    return (f"cog {cog}'s stack grew past the end of {array} ({where}, {array_bytes} bytes at "
            f"${array_addr:04X}) that cognew gave to {method}: calling {callee} needs it up to "
            f"${needs:04X}, {over} bytes past its end; give {method} a larger stack array")


def no_free_cog(what: str) -> str:
    """cognew with all eight cogs running."""
    return (f"cognew found no free cog (all 8 are running): it returns -1 and {what} does not start")


def pin_conflict(pins: list, low_cog: int, high_cog: int) -> str:
    """Pins that one cog drives low while another drives them high."""
    names = ", ".join(f"P{p}" for p in pins)
    it = "it" if len(pins) == 1 else "them"
    return (f"{names}: cog {low_cog} drives {it} low while cog {high_cog} drives {it} high; the pins OR "
            f"the cogs' outputs, so {it} stay{'s' if len(pins) == 1 else ''} high")


def write_outside_hub(size: int, addr: int) -> str:
    """A write to $8000-$FFFF (ROM: the write is lost)."""
    kind = {1: "byte", 2: "word", 4: "long"}.get(size, "a")
    return (f"{kind} write to ${addr:04X}, past the end of hub RAM ($0000-$7FFF is RAM, the rest ROM): "
            f"the write is lost; a bad pointer?")


def write_into_code(size: int, addr: int, what: str) -> str:
    """A write into method code, strings or an object table."""
    kind = {1: "byte", 2: "word", 4: "long"}.get(size, "a")
    return (f"{kind} write to ${addr:04X} changes the program's own code ({what}); a bad pointer, or an "
            f"array written past its end?")


def uninitialized_local(name: str, method: str, value: int) -> str:
    """A local read before it is assigned (it holds what the stack held)."""
    return (f"local '{name}' of {method} is read before it is assigned: Spin does not clear locals, it "
            f"holds leftover stack ({value} here); assign it first")
