"""Diagnostics: the one error family of spinemu and how it is rendered.

Every error the library raises for bad input is a :class:`SpinError` (or a
subclass).  It carries one or more :class:`Diagnostic` records, each with a
path, a 1-based line and column and the source line, and renders in the
GCC layout that editors understand::

    stepper.spin:41:9: error: unknown symbol 'numStep'
        if (numStep-- > 0)
            ^

This module is a shared leaf: it imports nothing from the project.
"""
from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable

from .records import FrozenRecord, Record

__all__ = [
    "Diagnostic",
    "SpinError",
    "ParseError",
    "CompileError",
    "ImageError",
    "EmulationError",
    "UsageError",
    "DiagnosticBag",
    "source_line_at",
    "split_lines",
]


class Diagnostic(FrozenRecord):
    """One message about one place in one file.

    Args:
        message: the text, in the user's words.
        path: the file it is about (``None`` when not about a file).
        line: 1-based line number, or ``None``.
        column: 1-based column number, or ``None``.
        source_line: the text of that line, exactly as in the file.
        severity: ``"error"``, ``"warning"`` or ``"note"``.
        length: how many characters the caret underline covers (at least 1).

    >>> d = Diagnostic("unknown symbol 'numStep'", "stepper.spin", 41, 9,
    ...                "    if (numStep-- > 0)")
    >>> print(d.render())
    stepper.spin:41:9: error: unknown symbol 'numStep'
        if (numStep-- > 0)
            ^
    """

    _fields = ("message", "path", "line", "column", "source_line", "severity", "length")

    def __init__(self, message: str, path: str | None = None, line: int | None = None,
                 column: int | None = None, source_line: str | None = None, severity: str = "error",
                 length: int = 1):
        self.message, self.path, self.line, self.column = message, path, line, column
        self.source_line, self.severity, self.length = source_line, severity, length

    def location(self) -> str:
        """``path:line:col`` (as much of it as is known)."""
        parts = [self.path or "<input>"]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)

    def render(self) -> str:
        """The message, the source line and a caret under the column.

        A line longer than :data:`SHOWN_CHARS` is shown as the stretch around the
        column, with ``...`` where it was cut.
        """
        out = [f"{self.location()}: {self.severity}: {self.message}"]
        if self.source_line is not None and self.column is not None:
            text, column = _window(self.source_line.rstrip("\r\n"), self.column)
            out.append(text)
            # Keep tabs so the caret lines up however the terminal expands them.
            prefix = "".join("\t" if ch == "\t" else " " for ch in text[: column - 1])
            width = max(1, min(self.length, max(1, len(text) - column + 1)))
            out.append(prefix + "^" + "~" * (width - 1))
        return "\n".join(out)


#: Characters of a long source line a diagnostic shows around its column.
SHOWN_CHARS = 160


def _window(line: str, column: int) -> tuple:
    """``(text to show, column in it)``: the line, or the stretch of a long one around ``column``.

    >>> _window("x" * 500, 300)[0][:5], _window("x" * 500, 300)[1]
    ('...xx', 84)
    """
    if len(line) <= SHOWN_CHARS:
        return _visible(line), column
    start = max(0, min(column - 1 - SHOWN_CHARS // 2, len(line) - SHOWN_CHARS))
    lead = "..." if start else ""
    tail = "..." if start + SHOWN_CHARS < len(line) else ""
    return lead + _visible(line[start:start + SHOWN_CHARS]) + tail, column - start + len(lead)


def _visible(text: str) -> str:
    """``text`` with control characters (but tabs), line separators and lone surrogates shown as
    U+FFFD, one for one (the caret stays in its column; an ESC cannot reach the terminal).

    >>> _visible("a\\x1b[2Jb\\tc") == "a\\ufffd[2Jb\\tc"
    True
    """
    if text.isprintable():
        return text
    return "".join("\ufffd" if ch != "\t" and unicodedata.category(ch) in ("Cc", "Cs", "Zl", "Zp") else ch
                   for ch in text)


class SpinError(Exception):
    """Bad input: one or more diagnostics.  The CLI renders it and exits 1.

    Args:
        message: the first (or only) diagnostic's text.
        path, line, column, source_line: where it is, if known.
        diagnostics: several diagnostics at once (``message`` is then ignored
            unless no diagnostics are given).

    >>> e = SpinError("missing object file 'stepper.spin'", path="demo.spin", line=3)
    >>> print(e)
    demo.spin:3: error: missing object file 'stepper.spin'
    """

    exit_status = 1

    def __init__(
        self,
        message: str = "",
        *,
        path: str | None = None,
        line: int | None = None,
        column: int | None = None,
        source_line: str | None = None,
        length: int = 1,
        diagnostics: Iterable[Diagnostic] | None = None,
    ):
        diags = list(diagnostics) if diagnostics else []
        if not diags:
            diags = [Diagnostic(message, path, line, column, source_line, "error", length)]
        self.diagnostics: list[Diagnostic] = diags
        super().__init__(self.render())

    @property
    def first(self) -> Diagnostic:
        return self.diagnostics[0]

    @property
    def message(self) -> str:
        return self.first.message

    @property
    def path(self) -> str | None:
        return self.first.path

    @property
    def line(self) -> int | None:
        return self.first.line

    @property
    def column(self) -> int | None:
        return self.first.column

    def render(self) -> str:
        return "\n".join(d.render() for d in self.diagnostics)

    def __str__(self) -> str:  # pragma: no cover - trivial
        return self.render()


class ParseError(SpinError):
    """The source does not follow the language's grammar."""


class CompileError(SpinError):
    """The source parses but cannot be compiled (unknown name, bad constant...)."""


class ImageError(SpinError):
    """A ``.binary``/``.eeprom`` image that cannot be loaded."""


class EmulationError(SpinError):
    """A run-time fault inside the emulated chip (names cog, address and source line)."""


class UsageError(SpinError):
    """Wrong command-line arguments: exit status 2."""

    exit_status = 2


class DiagnosticBag(Record):
    """Collects diagnostics so that one run can report several errors.

    >>> bag = DiagnosticBag()
    >>> bag.error("unknown symbol 'x'", "a.spin", 2, 3, "  x := 1")
    >>> bag.has_errors
    True
    >>> bag.raise_if_errors(CompileError)
    Traceback (most recent call last):
    ...
    spinemu.diagnostics.CompileError: a.spin:2:3: error: unknown symbol 'x'
      x := 1
      ^
    """

    _fields = ("items",)

    def __init__(self, items: list | None = None):
        self.items: list[Diagnostic] = [] if items is None else items

    def add(self, diag: Diagnostic) -> None:
        self.items.append(diag)

    def error(self, message, path=None, line=None, column=None, source_line=None, length=1) -> None:
        self.items.append(Diagnostic(message, path, line, column, source_line, "error", length))

    def warning(self, message, path=None, line=None, column=None, source_line=None, length=1) -> None:
        self.items.append(Diagnostic(message, path, line, column, source_line, "warning", length))

    @property
    def has_errors(self) -> bool:
        return any(d.severity == "error" for d in self.items)

    @property
    def warnings(self) -> list[Diagnostic]:
        return [d for d in self.items if d.severity == "warning"]

    def raise_if_errors(self, cls: type = SpinError) -> None:
        errors = [d for d in self.items if d.severity == "error"]
        if errors:
            raise cls(diagnostics=errors)


_LINE_BREAK = re.compile(r"\r\n|\r|\n")


def split_lines(text: str) -> list:
    """``text``'s lines as the Spin and PBASIC lexers count them: only CR LF, CR and LF
    end a line (``str.splitlines`` also splits at form feeds, U+2028 and other
    separators, and a caret would then point into the wrong line).

    >>> split_lines("a\\x0cb\\r\\nc\\rd\\n")
    ['a\\x0cb', 'c', 'd']
    """
    lines = _LINE_BREAK.split(text)
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def source_line_at(text: str, line: int) -> str | None:
    """The 1-based ``line`` of ``text`` without its line ending, or ``None``.

    >>> source_line_at("a\\nbc\\n", 2)
    'bc'
    """
    lines = split_lines(text)
    if 1 <= line <= len(lines):
        return lines[line - 1]
    return None
