"""Typed syntax tree of a PBASIC 2.5 program, as built by :mod:`.syntax`.

Every node carries a :class:`Pos` (1-based line and column, and the column
just past its end on the start line) so that diagnostics can point at the
user's own text.  Expressions keep the shape the grammar gives them: binary
operators form left-leaning chains because PBASIC evaluates strictly left to
right.

Statements are flat (see ``grammars/pbasic.lark``): a :class:`Stmt` has a
``kind`` (the grammar rule name, e.g. ``"pulsout"``) and positional ``args``
whose meaning each compiler handler knows.  The one nested form is the
single-line IF, whose ``args`` hold lists of statements.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Union

from ..diagnostics import split_lines

__all__ = [
    "Pos", "Num", "Str", "Ref", "Unary", "Binary", "Compare", "Logic", "Not",
    "Expr", "Stmt", "Label", "Word", "Program",
]


@dataclass(frozen=True)
class Pos:
    """Where a node starts (1-based line and column) and how long it is."""

    line: int
    column: int
    length: int = 1

    def span_to(self, other: "Pos") -> "Pos":
        """A position from the start of ``self`` to the end of ``other`` (same line only)."""
        if other.line != self.line:
            return self
        return Pos(self.line, self.column, max(1, other.column + other.length - self.column))


@dataclass(frozen=True)
class Num:
    """A number literal: ``15``, ``$FF``, ``%1010``."""

    value: int
    text: str
    pos: Pos


@dataclass(frozen=True)
class Str:
    """A quoted string: one character is a number, several are a list of bytes."""

    text: str
    pos: Pos


@dataclass(frozen=True)
class Ref:
    """A name with optional modifiers and index: ``arr.LOWNIB(i + 1)``."""

    name: str
    pos: Pos
    mods: tuple = ()          # ((name, Pos), ...)
    index: Optional["Expr"] = None

    @property
    def key(self) -> str:
        return self.name.upper()


@dataclass(frozen=True)
class Unary:
    op: str                   # upper case: "-", "~", "ABS", ...
    operand: "Expr"
    pos: Pos


@dataclass(frozen=True)
class Binary:
    op: str                   # upper case: "+", "*/", "MIN", ...
    left: "Expr"
    right: "Expr"
    pos: Pos                  # position of the operator


@dataclass(frozen=True)
class Compare:
    op: str                   # normalised: "=", "<>", "<", ">", "<=", ">="
    left: "Expr"
    right: "Expr"
    pos: Pos


@dataclass(frozen=True)
class Logic:
    op: str                   # "AND", "OR", "XOR"
    left: "Expr"
    right: "Expr"
    pos: Pos


@dataclass(frozen=True)
class Not:
    operand: "Expr"
    pos: Pos


Expr = Union[Num, Str, Ref, Unary, Binary, Compare, Logic, Not]


@dataclass(frozen=True)
class Word:
    """``WORD item`` in READ/WRITE/DATA lists (``word`` tells whether it was there)."""

    word: bool
    item: object
    pos: Pos


@dataclass
class Stmt:
    """One flat statement: ``kind`` is the grammar rule, ``args`` its parts."""

    kind: str
    pos: Pos
    args: tuple = ()
    text: str = ""            # the source text of the statement (for listings)


@dataclass
class Label:
    name: str
    pos: Pos


@dataclass
class Program:
    """The parsed file: statements and labels in source order."""

    path: str
    source: str
    items: list = field(default_factory=list)   # Stmt | Label
    stamp: str = "BS2"
    language: str = "2.5"

    def source_line(self, line: int) -> Optional[str]:
        lines = split_lines(self.source)
        return lines[line - 1] if 1 <= line <= len(lines) else None
