"""Expressions the debugger evaluates: ``print`` arguments and breakpoint conditions.

A small, safe subset of Python's expression syntax over Spin names (parsed
with :mod:`ast`, never ``eval``): integers (also Spin's ``$FF`` and ``%1010``),
names (a local or parameter of the frame, a VAR/DAT variable, ``obj.name``
for a child object's, ``name[i]`` for an element), ``+ - * // % & | ^ << >>``,
unary ``- ~ not``, comparisons (also Spin's ``<>``, ``=<``, ``=>``, ``==``)
and ``and``/``or``.  The registers ``cnt``, ``ina``, ``outa``, ``dira`` and
``par`` of the cog the expression is evaluated for are names too.

>>> e = Expression("mode & 1 == 1 and n <> 0")
>>> e.evaluate(lambda name, index: {"mode": 3, "n": 5}[name])
True
>>> Expression("%1010 + $10").evaluate(lambda n, i: 0)
26
"""
from __future__ import annotations

import ast
import operator
import re
from typing import Callable, Optional

__all__ = ["Expression", "ExpressionError", "REGISTERS"]

REGISTERS = ("cnt", "ina", "outa", "dira", "par")

_BIN = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.FloorDiv: operator.floordiv,
        ast.Mod: operator.mod, ast.BitAnd: operator.and_, ast.BitOr: operator.or_, ast.BitXor: operator.xor,
        ast.LShift: operator.lshift, ast.RShift: operator.rshift}
_CMP = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
        ast.Gt: operator.gt, ast.GtE: operator.ge}


class ExpressionError(ValueError):
    """An expression the debugger cannot read or evaluate (the message says why)."""


def _spin_to_python(text: str) -> str:
    text = re.sub(r"\$([0-9A-Fa-f_]+)", lambda m: "0x" + m.group(1).replace("_", ""), text)
    text = re.sub(r"(?<![\w)\]])%([01_]+)", lambda m: "0b" + m.group(1).replace("_", ""), text)
    text = text.replace("<>", "!=").replace("=>", ">=").replace("=<", "<=")
    return text


class Expression:
    """A parsed expression; :meth:`evaluate` asks ``lookup(name, index)`` for each variable.

    Raises:
        ExpressionError: the text is not an expression of the supported kind.
    """

    def __init__(self, text: str):
        self.text = text.strip()
        try:
            tree = ast.parse(_spin_to_python(self.text), mode="eval")
        except SyntaxError:
            raise ExpressionError(f"cannot read {self.text!r} as an expression") from None
        self._tree = tree.body
        self.names = []
        self._check(self._tree)

    def _check(self, node) -> None:
        if isinstance(node, (ast.Name, ast.Attribute)):
            self.names.append(_dotted(node))
            return
        if isinstance(node, ast.Subscript):
            self.names.append(_dotted(node.value))
            self._check(node.slice)
            return
        if isinstance(node, ast.Constant):
            if not isinstance(node.value, int):
                raise ExpressionError(f"only whole numbers are supported, not {node.value!r}")
            return
        if isinstance(node, ast.BinOp) and type(node.op) in _BIN:
            self._check(node.left)
            self._check(node.right)
            return
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.Invert, ast.Not, ast.UAdd)):
            self._check(node.operand)
            return
        if isinstance(node, ast.Compare) and all(type(o) in _CMP for o in node.ops):
            self._check(node.left)
            for c in node.comparators:
                self._check(c)
            return
        if isinstance(node, ast.BoolOp):
            for v in node.values:
                self._check(v)
            return
        raise ExpressionError(f"{self.text!r}: {type(node).__name__.lower()} is not supported here")

    def evaluate(self, lookup: Callable[[str, Optional[int]], int]):
        """The value (an int, or a bool for a comparison); ``lookup`` raises ExpressionError for unknown names."""
        return self._eval(self._tree, lookup)

    def _eval(self, node, lookup):
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, (ast.Name, ast.Attribute)):
            return lookup(_dotted(node), None)
        if isinstance(node, ast.Subscript):
            return lookup(_dotted(node.value), int(self._eval(node.slice, lookup)))
        if isinstance(node, ast.BinOp):
            return _BIN[type(node.op)](self._eval(node.left, lookup), self._eval(node.right, lookup))
        if isinstance(node, ast.UnaryOp):
            v = self._eval(node.operand, lookup)
            if isinstance(node.op, ast.USub):
                return -v
            if isinstance(node.op, ast.Invert):
                return ~v
            if isinstance(node.op, ast.Not):
                return not v
            return v
        if isinstance(node, ast.Compare):
            left = self._eval(node.left, lookup)
            for op, right_node in zip(node.ops, node.comparators):
                right = self._eval(right_node, lookup)
                if not _CMP[type(op)](left, right):
                    return False
                left = right
            return True
        values = [self._eval(v, lookup) for v in node.values]
        return all(values) if isinstance(node.op, ast.And) else any(values)


def _dotted(node) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return _dotted(node.value) + "." + node.attr
    raise ExpressionError("expected a name")
