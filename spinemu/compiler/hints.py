"""Compiler hints: things that compile (to the same bytes) but are rarely what was meant.

* ``if x >= 10``: Spin's ``>=`` (and ``<=``) are *assignment* operators:
  ``x >= 10`` sets ``x`` to ``x > 10`` (TRUE or FALSE) and gives that value.
  The comparisons are ``=>`` and ``=<`` (Propeller Manual v1.2, operator
  table).  Hinted wherever the assignment's value is used (a condition, an
  argument, part of a larger expression); ``x >= 10`` alone on a line is left
  alone.
* ``if z<-1``: ``<-`` is rotate-left, so this is ``z <- 1`` (``z`` rotated
  left by one: true for any ``z`` but 0), not ``z < -1``.  Hinted when
  ``<-`` is written directly against its right operand.
* An OBJ file found in a library folder while another library folder later in
  the search order has a different file of the same name
  (:mod:`spinemu.frontend.obj_shadow`; the loader records those).

Hints are :class:`~spinemu.diagnostics.Diagnostic` records of severity
``"warning"`` in ``CompiledProgram.warnings``; the image is the same with or
without them.
"""
from __future__ import annotations

from ..diagnostics import Diagnostic
from .. import messages as msg
from ..frontend.ast import Assign, Binary, ExprStmt, Paren, walk

__all__ = ["source_hints", "program_hints"]

_COMPARES = {">": ("=>", "greater than or equal", ">"), "<": ("=<", "less than or equal", "<")}


def _column_of(text: str, needle: str, start_col: int, end_col: int):
    """1-based column of the last ``needle`` between two columns of ``text`` (or ``None``)."""
    i = text.rfind(needle, max(0, start_col - 1), max(0, end_col - 1) + len(needle) - 1)
    return i + 1 if i >= 0 else None


def _name(node, text: str) -> str:
    """The source text of a simple operand (for messages), else ``x``."""
    end = node.pos.col - 1
    while end < len(text) and (text[end].isalnum() or text[end] in "_.[]#$%"):
        end += 1
    word = text[node.pos.col - 1:end]
    return word or "x"


def source_hints(unit) -> list:
    """The hints for one object file (its AST; ``unit`` is a frontend ObjectUnit)."""
    source = unit.spin.source
    out = []
    for method in unit.spin.methods:
        statement_level = {id(st.expr) for st in walk(method.body) if isinstance(st, ExprStmt)}
        for node in walk(method.body):
            if isinstance(node, Assign) and node.op in _COMPARES and id(node) not in statement_level:
                text = source.line(node.pos.line) or ""
                op = node.op + "="
                col = node.value.pos.line == node.pos.line and \
                    _column_of(text, op, node.pos.col, node.value.pos.col) or node.pos.col
                right, what, cmp = _COMPARES[node.op]
                out.append(Diagnostic(msg.HINT_ASSIGNING_COMPARE.format(
                    op=op, target=_name(node.target, text), cmp=cmp, what=what, right=right),
                    node.pos.path, node.pos.line, col, text, "warning", len(op)))
            elif isinstance(node, Binary) and node.op == "<-" and node.right.pos.line == node.pos.line:
                text = source.line(node.pos.line) or ""
                right = node.right.expr if isinstance(node.right, Paren) else node.right
                col = _column_of(text, "<-", node.pos.col, node.right.pos.col)
                if col is not None and col + 2 == node.right.pos.col and not isinstance(node.right, Paren):
                    out.append(Diagnostic(msg.HINT_ROTATE_NOT_MINUS.format(
                        left=_name(node.left, text), right=_name(right, text)),
                        node.pos.path, node.pos.line, col, text, "warning", 2))
    return out


def program_hints(units) -> list:
    """Hints for every object of a program, in file and line order (OBJ-file hints included)."""
    out = []
    for unit in units:
        out.extend(source_hints(unit))
        out.extend(getattr(unit, "hints", ()))
    seen, unique = set(), []
    for d in sorted(out, key=lambda d: (d.path or "", d.line or 0, d.column or 0)):
        k = (d.path, d.line, d.column, d.message)
        if k not in seen:
            seen.add(k)
            unique.append(d)
    return unique
