"""The text of a generated module, line by line, with Spin line numbers, comments and cycle charges.

Every statement line ends with ``# L<n>`` (its Spin source line) and the Spin
comment of that line; Spin comments on lines of their own are carried over as
Python comment lines.  :attr:`Code.spin_lines` maps each Python line to its
Spin line (the side-by-side view aligns on it) and :attr:`Code.charges` holds
the cycles the weaver charges around Python lines (see weave.py).
"""
from __future__ import annotations

import re

from .costs import access_range, chain, store_at

__all__ = ["Code", "COMMENT_COLUMN", "comment_text", "docstring_text"]

COMMENT_COLUMN = 56


def _escape_unprintable(text: str) -> str:
    """Characters Python source cannot hold as they are (NUL, CR, line separators, lone
    surrogates, other control characters) as their backslash escapes; tabs stay."""
    if text.isprintable():
        return text
    return "".join(ch if ch.isprintable() or ch == "\t" else ch.encode("unicode_escape", "backslashreplace")
                   .decode("ascii") for ch in text)


def comment_text(text: str) -> str:
    r"""Spin comment text made safe for the end of a Python ``#`` comment (one line, printable).

    >>> print(comment_text("a\rb\x00c"))
    a\rb\x00c
    """
    return _escape_unprintable(text)


def docstring_text(text: str) -> str:
    r"""Text for one line of a triple-quoted docstring that reads back as ``text``.

    Backslashes are doubled, unprintable characters escaped, and a quote mark
    escaped where it would start or end a triple quote (before another quote
    mark, or last on the line).

    >>> print(docstring_text('say ' + '"' * 3 + 'hi" \\N'))
    say \"\""hi" \\N
    """
    out = _escape_unprintable(text.replace("\\", "\\\\"))
    return re.sub(r'"(?="|$)', r'\\"', out)


class Code:
    """Lines of one module.

    Args:
        spin: the parsed Spin file (``ast.SpinFile``), for its comments and source lines.
    """

    def __init__(self, spin):
        self.spin = spin
        self.lines: list[str] = []
        self.spin_lines: list = []
        self.indent = 0
        self.charges: dict = {}
        self.lookups: dict = {}
        self.call_depths: dict = {}
        self._commented: set = set()
        self._last_spin = 0

    # ------------------------------------------------------------------ lines
    def line(self, text: str, spin_line=None, note: str = "") -> int:
        """Add one line at the current indentation; returns its 1-based number.

        ``note``: said in the trailing comment before the Spin comment.
        """
        out = "    " * self.indent + text if text else ""
        if spin_line is not None:
            tag = f"L{spin_line}"
            note = " ".join(n for n in (note, self.trailing_comment(spin_line)) if n)
            if note:
                tag += f": {note}"
            out = out.ljust(COMMENT_COLUMN - 2) + "  # " + tag if len(out) < COMMENT_COLUMN - 2 \
                else out + "  # " + tag
            self._last_spin = max(self._last_spin, spin_line)
        self.lines.append(out)
        self.spin_lines.append(spin_line)
        return len(self.lines)

    def raw(self, text: str = "") -> int:
        """A line without indentation or tags (module level)."""
        self.lines.append(text)
        self.spin_lines.append(None)
        return len(self.lines)

    def trailing_comment(self, spin_line: int) -> str:
        """The Spin comment at the end of ``spin_line`` (once per line)."""
        if spin_line in self._commented:
            return ""
        self._commented.add(spin_line)
        text = self.spin.source.line(spin_line) or ""
        notes = [c.text.strip() for c in self.spin.comments_at(spin_line)
                 if c.kind in ("'", "''", "{", "{{") and text[: c.col - 1].strip()]
        return comment_text(" ".join(" ".join(n.split()) for n in notes if n))  # a block comment: one line

    def comments_before(self, spin_line: int) -> None:
        """Carry over the Spin comments on lines of their own before ``spin_line``."""
        for n in range(self._last_spin + 1, spin_line):
            for c in self.spin.comments_at(n):
                src = self.spin.source.line(n) or ""
                if src[: c.col - 1].strip():
                    continue
                for part in c.text.splitlines() or [""]:
                    self.line("#" + (" " + comment_text(part.strip()) if part.strip() else ""))
            self._last_spin = max(self._last_spin, n)

    def skip_to(self, spin_line: int) -> None:
        """Mark Spin lines up to ``spin_line`` as handled (their comments went elsewhere)."""
        self._last_spin = max(self._last_spin, spin_line)

    # ------------------------------------------------------------------ charges
    def _slot(self, line: int, slot: str) -> list:
        entry = self.charges.setdefault(line, {})
        return entry.setdefault(slot, [[], 0])

    def charge(self, line: int, slot: str, ops, first: bool = False) -> None:
        """Charge a run of bytecodes ``ops`` at ``slot`` of ``line`` (b: before, a: after, e: else/exit,
        t: each test of a ``while``, p: the statement's own rest, before it stores or returns).

        ``first``: these bytecodes run before the ones charged there already
        (a condition's jump before the first statement of its body).
        """
        run = self._slot(line, slot)[0]
        if first:
            run[:0] = ops
        else:
            run.extend(ops)

    def charge_add(self, line: int, slot: str, cycles: int) -> None:
        """Charge plain cycles (no fetch alignment) at ``slot`` of ``line``."""
        self._slot(line, slot)[1] += cycles

    def charge_mid(self, line: int, ops) -> None:
        """Bytecodes from a register read on, paid by the read itself (see costs.split_read)."""
        self.charges.setdefault(line, {})["mid"] = list(ops)

    def charge_each(self, line: int, runs) -> None:
        """Charge one run before each operand of the ``or`` in the condition of the ``if`` on ``line``
        (a pair of runs: before the operand, and once its value is computed)."""
        self.charges.setdefault(line, {})["each"] = [r if isinstance(r, tuple) else list(r) for r in runs]

    def charge_table(self) -> dict:
        """``{line: (before, after, else[, test[, post]])}``, each ``(aligned, extra[, access])`` or None.

        ``post``: the statement's own bytecodes after its call or read, paid before
        its store (weave.py); ``after``: what the block pays after it (a jump back).

        ``access``: cycles from the fetch of the run's first bytecode to the start of its
        first shared hub access (the moment the run must not pass other cogs).
        """
        table = {}
        for line, entry in sorted(self.charges.items()):
            row = []
            for slot in "baetp":
                ops, extra = entry.get(slot, [[], 0])
                k = chain(ops)
                a = access_range(ops)
                if a is not None and a[0] == a[1]:
                    a = a[0]
                s = store_at(ops) if slot == "b" else None
                if s is not None:           # the run ends storing a hub variable at ``s``
                    a = (a, a, s) if isinstance(a, int) else (a[0], a[1], s)
                row.append(None if k is None and not extra else (k, extra) if a is None else (k, extra, a))
            mid = entry.get("mid")
            if mid:
                b = row[0] or (None, 0)
                row[0] = (b[0], b[1], b[2] if len(b) > 2 else None, chain(mid))
            each = entry.get("each")
            if each:
                row[3] = tuple(((chain(r[0]), 0), (chain(r[1]), 0)) if isinstance(r, tuple) else (chain(r), 0)
                               for r in each)
            while len(row) > 3 and not row[-1]:
                row.pop()
            if any(row):
                table[line] = tuple(row)
        return table

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"
