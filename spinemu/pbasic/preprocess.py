"""Editor directives and conditional compilation, before parsing.

* ``' {$STAMP BS2}`` and ``' {$PBASIC 2.5}`` live in comments (manual ch. 3,
  "Compiler directives").  Without ``$STAMP`` Parallax's tokenizer refuses the
  file (error 156); without ``$PBASIC`` the language is PBASIC 2.0.
* PBASIC 2.5 conditional compilation (manual ch. 3, "Conditional
  compilation"): ``#DEFINE name {= expr}``, ``#IF cond #THEN`` / ``#ELSE`` /
  ``#ENDIF``, ``#SELECT expr`` / ``#CASE v, ...`` / ``#CASE #ELSE`` /
  ``#ENDSELECT`` and ``#ERROR "text"``.  Facts checked against Parallax's
  tokenizer: an undefined symbol is 0, ``#DEFINE x`` without a value is
  ``-1``, ``$PBASIC`` is 250, ``BS2`` is 2 (``BS1`` 1 ... ``BS2PX`` 7), and
  the expressions follow PBASIC's own left-to-right rules.

Directive lines and the lines of inactive branches are replaced by empty
lines, so every remaining line keeps its number and columns.
"""
from __future__ import annotations

import re
from typing import Callable, Optional

from ..diagnostics import ParseError, source_line_at, split_lines
from . import messages as M

__all__ = ["Directives", "scan_directives", "conditional_compile", "STAMP_IDS"]

STAMP_IDS = {"BS1": 1, "BS2": 2, "BS2E": 3, "BS2SX": 4, "BS2P": 5, "BS2PE": 6, "BS2PX": 7}

_DIRECTIVE = re.compile(r"\{\$(STAMP|PBASIC|PORT)\s+([^}]*)\}", re.IGNORECASE)
_PP_LINE = re.compile(r"^([ \t]*)#([A-Za-z]+)\b(.*)$")


class Directives:
    """What the ``{$...}`` comments say."""

    def __init__(self) -> None:
        self.stamp: Optional[str] = None
        self.stamp_pos: tuple[int, int] = (1, 1)
        self.language = "2.0"
        self.port: Optional[str] = None

    @property
    def is_25(self) -> bool:
        return self.language == "2.5"


def scan_directives(text: str, path: str) -> Directives:
    """Find ``{$STAMP}``, ``{$PBASIC}`` and ``{$PORT}`` inside comments.

    Raises:
        ParseError: no ``$STAMP``, a Stamp other than the BS2, or an unknown
            PBASIC version.
    """
    d = Directives()
    for n, line in enumerate(split_lines(text), 1):
        quote = _comment_start(line)
        if quote < 0:
            continue
        for m in _DIRECTIVE.finditer(line, quote):
            key, value = m.group(1).upper(), m.group(2).strip()
            col = m.start() + 1
            if key == "STAMP" and d.stamp is None:
                d.stamp = value.split(",")[0].strip().upper()
                d.stamp_pos = (n, col)
                if d.stamp != "BS2":
                    raise ParseError(M.WRONG_STAMP.format(d.stamp), path=path, line=n,
                                     column=col, source_line=line, length=len(m.group(0)))
            elif key == "PBASIC":
                if value not in ("2.0", "2.5"):
                    raise ParseError(M.PBASIC_VERSION.format(value), path=path, line=n,
                                     column=col, source_line=line, length=len(m.group(0)))
                d.language = value
            elif key == "PORT":
                d.port = value
    if d.stamp is None:
        raise ParseError(M.NO_STAMP, path=path, line=1, column=1,
                         source_line=source_line_at(text, 1))
    return d


def _comment_start(line: str) -> int:
    """Index of the ``'`` that starts a comment, or -1 (quotes in strings skipped)."""
    in_str = False
    for i, ch in enumerate(line):
        if ch == '"':
            in_str = not in_str
        elif ch == "'" and not in_str:
            return i
    return -1


def conditional_compile(text: str, path: str, directives: Directives,
                        evaluate: Callable[..., int]) -> str:
    """Apply ``#DEFINE/#IF/#SELECT/#ERROR`` and return the remaining source.

    Args:
        text: the whole source.
        path: for diagnostics.
        directives: the ``{$...}`` settings (``$STAMP``, ``$PBASIC`` values).
        evaluate: ``evaluate(expr_text, line, column, symbols, source) -> int`` parses
            and evaluates one PBASIC condition over constant symbols.

    Raises:
        ParseError: unbalanced or unknown directives, ``#ERROR``.
    """
    if "#" not in text:
        return text
    lines = text.split("\n")
    symbols = dict(STAMP_IDS)
    # '$' cannot start a PBASIC name: '$STAMP' is read as '_STAMP' (same width).
    symbols["_STAMP"] = STAMP_IDS.get(directives.stamp or "BS2", 2)
    symbols["_PBASIC"] = 250 if directives.is_25 else 200
    # stack of [kind, active_now, parent_active, taken, start_line, select_value]
    stack: list[list] = []
    out = []

    def active() -> bool:
        return all(frame[1] for frame in stack)

    def fail(msg: str, n: int, col: int, length: int = 1):
        raise ParseError(msg, path=path, line=n, column=col,
                         source_line=lines[n - 1], length=length)

    for n, line in enumerate(lines, 1):
        m = _PP_LINE.match(line)
        if not m or _comment_start(line) != -1 and _comment_start(line) < len(m.group(1)):
            out.append(line if active() else "")
            continue
        word = m.group(2).upper()
        rest = _strip_comment(m.group(3))
        col = len(m.group(1)) + 1
        rest_col = col + 1 + len(m.group(2)) + (len(m.group(3)) - len(m.group(3).lstrip()))
        ev = lambda s, c=rest_col: evaluate(_dollar(s), n, c, symbols, text) & 0xFFFF  # noqa: E731
        if word == "DEFINE":
            if active():
                name, _, value = rest.partition("=")
                name = name.strip().upper()
                symbols[name] = ev(value) if value.strip() else 0xFFFF
        elif word == "IF":
            cond, sep, _ = rest.upper().rpartition("#THEN")
            if not sep:
                fail(M.PP_UNBALANCED.format("#IF", "#THEN"), n, col, 3)
            on = active() and ev(rest[:len(cond)]) != 0
            stack.append(["IF", on, active(), on, n, None])
        elif word == "ELSE":
            if not stack or stack[-1][0] != "IF":
                fail(M.PP_UNBALANCED.format("#ELSE", "#IF"), n, col, 5)
            f = stack[-1]
            f[1] = not f[3]
            f[3] = True
        elif word == "ENDIF":
            if not stack or stack[-1][0] != "IF":
                fail(M.PP_UNBALANCED.format("#ENDIF", "#IF"), n, col, 6)
            stack.pop()
        elif word == "SELECT":
            value = ev(rest) if active() else 0
            stack.append(["SELECT", False, active(), False, n, value])
        elif word == "CASE":
            if not stack or stack[-1][0] != "SELECT":
                fail(M.PP_UNBALANCED.format("#CASE", "#SELECT"), n, col, 5)
            f = stack[-1]
            if f[3]:
                f[1] = False
            elif rest.strip().upper() == "#ELSE":
                f[1] = f[3] = True
            else:
                hit = f[2] and any(ev(item) == f[5] for item in _split_commas(rest))
                f[1] = f[3] = hit
        elif word == "ENDSELECT":
            if not stack or stack[-1][0] != "SELECT":
                fail(M.PP_UNBALANCED.format("#ENDSELECT", "#SELECT"), n, col, 10)
            stack.pop()
        elif word == "ERROR":
            if active():
                msg = rest.strip().strip('"')
                fail(M.PP_ERROR.format(msg), n, col, len(line.rstrip()) - col + 1)
        else:
            fail(M.PP_UNKNOWN.format("#" + m.group(2)), n, col, len(m.group(2)) + 1)
        out.append("")
    if stack:
        kind, start = stack[-1][0], stack[-1][4]
        end = "#ENDIF" if kind == "IF" else "#ENDSELECT"
        fail(M.PP_UNBALANCED.format("#" + kind, end), start, 1, len(kind) + 1)
    return "\n".join(out)


def _dollar(s: str) -> str:
    return re.sub(r"\$(?=STAMP|PBASIC|PORT)", "_", s, flags=re.IGNORECASE)


def _strip_comment(s: str) -> str:
    i = _comment_start(s)
    return s if i < 0 else s[:i]


def _split_commas(s: str) -> list[str]:
    parts, depth, cur, in_str = [], 0, "", False
    for ch in s:
        if ch == '"':
            in_str = not in_str
        if not in_str and ch == "(":
            depth += 1
        elif not in_str and ch == ")":
            depth -= 1
        if ch == "," and depth == 0 and not in_str:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    return [p for p in parts if p.strip()]
