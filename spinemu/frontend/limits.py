"""Nesting limits checked right after parsing: blocks (Spin's own) and expressions (spinemu's).

**Blocks.**  OpenSpin 1.00.81 refuses a tenth nested block with "Limit of 8
nested blocks exceeded", at the keyword that opens it.  Observed on the
black box: ``if``/``ifnot``, every ``repeat`` form and ``case`` open a block
for the whole statement (their condition, count, range or selector
included); ``lookup``, ``lookupz``, ``lookdown`` and ``lookdownz`` open one
for their expression; ``elseif`` and ``else`` do not (an ``elseif`` chain
of any length is one block).  Nine levels compile.

**Expressions.**  OpenSpin compiles any depth (ten thousand parentheses,
ten thousand terms in one sum).  spinemu's compiler, constant folder and
translator recurse over the expression tree, and the Python the translator
writes nests as deeply as the Spin; both would fail far past anything a
program needs.  spinemu refuses an expression more than
:data:`MAX_EXPRESSION_DEPTH` levels deep (a documented deviation,
docs/language.md), with the position of the first node past the limit.

Both walks are iterative (explicit stacks), so a deeply nested input is
reported, never a ``RecursionError``.  The expression walk only runs on
lines with more tokens than the limit: an expression cannot be deeper
than the number of tokens it is written with.
"""
from __future__ import annotations

from .. import messages as msg
from .ast import Case, If, Lookup, RepeatCount, RepeatForever, RepeatFrom, RepeatWhile, SpinFile

__all__ = ["MAX_BLOCK_DEPTH", "MAX_EXPRESSION_DEPTH", "block_nesting_errors", "expression_depth_error"]

#: Nested blocks OpenSpin accepts (the tenth is an error).
MAX_BLOCK_DEPTH = 9
#: Levels of expression spinemu accepts (the compiler, folder and translator recurse per level).
MAX_EXPRESSION_DEPTH = 100

_BLOCKS = (If, Case, RepeatForever, RepeatCount, RepeatWhile, RepeatFrom, Lookup)


def _children(node):
    """The child nodes of ``node`` (a node or a list of them), in source order."""
    if isinstance(node, list):
        return [x for x in node if x is not None]
    fields = getattr(node, "__dataclass_fields__", None)
    if fields is None or isinstance(node, SpinFile):
        return []
    out = []
    for f in fields:
        if f == "pos":
            continue
        value = getattr(node, f)
        if isinstance(value, list):
            out.extend(x for x in value if hasattr(x, "__dataclass_fields__") or isinstance(x, list))
        elif hasattr(value, "__dataclass_fields__"):
            out.append(value)
    return out


def block_nesting_errors(method) -> list:
    """``[(message, node)]`` for each block opened past :data:`MAX_BLOCK_DEPTH` in ``method``.

    Only the first such block of each nest is reported (its inner blocks are not).
    """
    errors = []
    stack = [(child, 0) for child in reversed(_children(method.body))]
    while stack:
        node, depth = stack.pop()
        if isinstance(node, _BLOCKS):
            depth += 1
            if depth > MAX_BLOCK_DEPTH:
                errors.append((msg.TOO_MANY_NESTED_BLOCKS.format(limit=MAX_BLOCK_DEPTH), node))
                continue
        stack.extend((child, depth) for child in reversed(_children(node)))
    return errors


def expression_depth_error(node):
    """``(message, node)`` for the first node nested deeper than :data:`MAX_EXPRESSION_DEPTH`, else ``None``.

    Statements and their blocks do not count as levels; only the expressions inside them.
    """
    from .ast import Expr

    stack = [(node, 0)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, Expr):
            depth += 1
            if depth > MAX_EXPRESSION_DEPTH:
                return msg.EXPRESSION_TOO_DEEP.format(limit=MAX_EXPRESSION_DEPTH), item
        stack.extend((child, depth) for child in reversed(_children(item)))
    return None
