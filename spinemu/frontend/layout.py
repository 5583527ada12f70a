"""The indentation post-lexer: Spin's blocks from the columns of its lines.

Spin (Propeller Manual v1.2, "Indentation is critical") has no block
delimiters.  A block statement (``if ifnot elseif elseifnot else case
repeat`` and every ``case`` match line ``value:``) owns the lines after it
that are indented *more than the statement itself*; the first line at or left
of its column ends the block.  Lines inside a block need not line up with
each other.  ``else``/``elseif`` and a ``while``/``until`` after a ``repeat``
block must be in exactly the column of their ``if``/``repeat`` (OpenSpin
rejects them anywhere else).

The post-lexer ends every line with ``_NL`` and wraps every block statement's
body in ``_INDENT ... _DEDENT`` (even when empty).  A method's own body is a
block whose header is left of column 0, so statements may start in column 0.
Comments never reach this stage, so they cannot disturb the indentation.
"""
from __future__ import annotations

from .lexer import Line, Token
from .. import messages as msg

__all__ = ["layout", "BLOCK_HEADS"]

BLOCK_HEADS = {"IF", "IFNOT", "ELSEIF", "ELSEIFNOT", "ELSE", "CASE", "REPEAT"}
_IF_FAMILY = {"IF", "IFNOT", "ELSEIF", "ELSEIFNOT"}
_CONTINUATIONS = {"ELSE": _IF_FAMILY, "ELSEIF": _IF_FAMILY, "ELSEIFNOT": _IF_FAMILY}
_OPEN = {"LPAR", "LSQB"}
_CLOSE = {"RPAR", "RSQB"}


def _match_colon(tokens: list) -> int:
    """Index of the ``:`` of a case match line (outside brackets), or -1."""
    depth = 0
    for i, tok in enumerate(tokens):
        t = tok.type
        if t in _OPEN:
            depth += 1
        elif t in _CLOSE:
            depth -= 1
        elif t == "COLON" and depth == 0:
            return i
    return -1


def _split_matches(lines: list, indent_at) -> list:
    """Move the statement after a case match's ``value:`` to a line of its own."""
    out = []
    for line in lines:
        colon = _match_colon(line.tokens)
        if colon >= 0 and colon + 1 < len(line.tokens) and line.tokens[0].type not in BLOCK_HEADS:
            rest = line.tokens[colon + 1:]
            out.append(Line(line.tokens[:colon + 1], line.indent))
            out.append(Line(rest, indent_at(rest[0])))
        else:
            out.append(line)
    return out


def _head_kind(line: Line):
    first = line.tokens[0].type
    if first in BLOCK_HEADS:
        return first
    if line.tokens[-1].type == "COLON" and _match_colon(line.tokens) == len(line.tokens) - 1:
        return "MATCH"
    return None


def _mark(type_: str, tok: Token, end: bool = False) -> Token:
    if end:
        return Token(type_, "", tok.line, tok.col + len(tok.value))
    return Token(type_, "", tok.line, tok.col)


def layout(lines: list, errors: list, indent_at=None) -> list:
    """The token stream of a method: header line, then its body with block markers.

    A case match line with a statement after its ``:`` is split in two, the
    statement getting the column where it is written, so that an ``else`` or a
    deeper line lines up with it as if it started its own line.

    Args:
        lines: the method's :class:`Line` objects, header first.
        errors: receives ``(message, token)`` pairs for misplaced else/while lines.
        indent_at: gives a token's column with tabs expanded (default: its column - 1).
    """
    out: list[Token] = []
    header = lines[0]
    lines = [header] + _split_matches(lines[1:], indent_at or (lambda tok: tok.col - 1))
    out.extend(header.tokens)
    out.append(_mark("_NL", header.tokens[-1], end=True))
    out.append(_mark("_INDENT", header.tokens[-1], end=True))
    stack: list = [(-1, "METHOD")]       # (header column, header kind)
    for line in lines[1:]:
        col = line.indent
        first = line.tokens[0]
        closed = None
        while col <= stack[-1][0]:
            closed = stack.pop()
            out.append(_mark("_DEDENT", first))
        want = _CONTINUATIONS.get(first.type)
        if first.type in ("WHILE", "UNTIL") and closed is not None and closed[1] == "REPEAT" \
                and closed[0] != col:
            errors.append((msg.POST_CONDITION_COLUMN.format(word=first.value, col=closed[0] + 1), first))
        if want and closed is not None and (closed[0] != col or closed[1] not in want):
            head = closed[1].lower() if closed[1] in want else "if"
            errors.append((msg.ELSE_COLUMN.format(word=first.value, head=head, col=closed[0] + 1), first))
        out.extend(line.tokens)
        out.append(_mark("_NL", line.tokens[-1], end=True))
        kind = _head_kind(line)
        if kind is not None:
            stack.append((col, kind))
            out.append(_mark("_INDENT", line.tokens[-1], end=True))
    last = lines[-1].tokens[-1]
    for _ in stack:
        out.append(_mark("_DEDENT", last, end=True))
    return out
