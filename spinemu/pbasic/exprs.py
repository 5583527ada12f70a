"""PBASIC expressions: the operator table, compilation to Python closures,
constant evaluation and the BS2's expression-stack limit.

Semantics (BS2, PBASIC 2.5; README sections 3.1-3.4 of the reference):

* every value is a 16-bit unsigned number; every operation wraps mod 65536;
* binary operators have no precedence: chains are evaluated strictly left
  to right (the parser builds left-leaning trees, so evaluating the tree in
  order *is* the rule); unary operators apply to the operand after them;
* comparisons give $FFFF (true) or 0 and are unsigned; AND/OR/XOR/NOT are
  bitwise on those values.

Operators whose corner cases are not settled (division by zero, shifts of
16 or more, DIG beyond the 5th digit, REV 0, ATN/HYP arithmetic, SIN/COS
table) use the documented defaults and report a warning through
``ctx.warn(pos, message)`` each time the case is hit.

Compiled expressions are closures ``f(m) -> int`` over the machine ``m``;
constant sub-expressions are folded when that hides no warning.  This is a
hot path: closures capture locals, no dictionary lookups at run time.
"""
from __future__ import annotations

import math
from typing import Callable, Optional

from ..diagnostics import CompileError
from . import messages as M
from . import nodes as N

__all__ = ["BINARY", "UNARY", "binary", "unary", "sin_b", "cos_b", "compile_expr",
           "eval_const", "check_depth", "Leaf", "ExprContext", "MASK"]

MASK = 0xFFFF
TRUE = 0xFFFF


# ------------------------------------------------------------------ operator table
# Each entry: name -> (function(a, b) -> value, open_check(a, b) -> message|None).
def _div(a, b):
    return a // b if b else MASK


def _mod(a, b):
    return a % b if b else a


def _dig(a, b):
    return (a // 10 ** b) % 10 if b < 5 else 0


def _shl(a, b):
    return (a << b) & MASK if b < 16 else 0


def _shr(a, b):
    return a >> b if b < 16 else 0


def _rev(a, b):
    n = min(b, 16)
    out = 0
    for i in range(n):
        if a >> i & 1:
            out |= 1 << (n - 1 - i)
    return out


def _sx8(v):
    v &= 0xFF
    return v - 256 if v & 0x80 else v


def _atn(x, y):
    ang = math.atan2(_sx8(y), _sx8(x))
    return int(math.floor(ang * 128 / math.pi + 0.5)) & 0xFF


def _hyp(x, y):
    return int(math.floor(math.hypot(_sx8(x), _sx8(y)) + 0.5))


BINARY: dict[str, tuple[Callable, Optional[Callable]]] = {
    "+": (lambda a, b: (a + b) & MASK, None),
    "-": (lambda a, b: (a - b) & MASK, None),
    "*": (lambda a, b: (a * b) & MASK, None),
    "**": (lambda a, b: (a * b) >> 16, None),
    "*/": (lambda a, b: ((a * b) >> 8) & MASK, None),
    "/": (_div, lambda a, b: M.W_DIV_ZERO if b == 0 else None),
    "//": (_mod, lambda a, b: M.W_DIV_ZERO if b == 0 else None),
    "MIN": (lambda a, b: a if a > b else b, None),
    "MAX": (lambda a, b: a if a < b else b, None),
    "DIG": (_dig, lambda a, b: M.W_DIG.format(b) if b > 4 else None),
    "<<": (_shl, lambda a, b: M.W_SHIFT.format(b) if b >= 16 else None),
    ">>": (_shr, lambda a, b: M.W_SHIFT.format(b) if b >= 16 else None),
    "REV": (_rev, lambda a, b: M.W_REV.format(b) if b == 0 or b > 16 else None),
    "&": (lambda a, b: a & b, None),
    "|": (lambda a, b: a | b, None),
    "^": (lambda a, b: a ^ b, None),
    "&/": (lambda a, b: a & ~b & MASK, None),
    "|/": (lambda a, b: (a | ~b) & MASK, None),
    "^/": (lambda a, b: (a ^ ~b) & MASK, None),
    "ATN": (_atn, lambda a, b: M.W_ATN_HYP),
    "HYP": (_hyp, lambda a, b: M.W_ATN_HYP),
}

#: Points of SIN/COS the manual documents (no warning there).
_SIN_KNOWN = {0: 0, 32: 90, 64: 127, 128: 0, 192: (-127) & MASK}
_COS_KNOWN = {0: 127, 64: 0, 128: (-127) & MASK}


def sin_b(x: int) -> int:
    """Sine of binary radians (256 per turn), scaled to +-127, as 16-bit two's complement.

    >>> sin_b(0), sin_b(32), sin_b(64), hex(sin_b(192))
    (0, 90, 127, '0xff81')
    """
    return int(math.floor(127 * math.sin(2 * math.pi * (x & 0xFF) / 256) + 0.5)) & MASK


def cos_b(x: int) -> int:
    """Cosine of binary radians, like :func:`sin_b` (``COS 0`` = 127)."""
    return int(math.floor(127 * math.cos(2 * math.pi * (x & 0xFF) / 256) + 0.5)) & MASK


def _abs(a):
    return (-a) & MASK if a & 0x8000 else a


UNARY: dict[str, tuple[Callable, Optional[Callable]]] = {
    "-": (lambda a: (-a) & MASK, None),
    "~": (lambda a: ~a & MASK, None),
    "ABS": (_abs, None),
    "SQR": (math.isqrt, None),
    "DCD": (lambda a: 1 << (a & 15), None),
    "NCD": (lambda a: a.bit_length(), None),
    "SIN": (sin_b, lambda a: None if (a & 0xFF) in _SIN_KNOWN else M.W_SIN_COS),
    "COS": (cos_b, lambda a: None if (a & 0xFF) in _COS_KNOWN else M.W_SIN_COS),
}

_COMPARE = {
    "=": lambda a, b: TRUE if a == b else 0,
    "<>": lambda a, b: TRUE if a != b else 0,
    "<": lambda a, b: TRUE if a < b else 0,
    ">": lambda a, b: TRUE if a > b else 0,
    "<=": lambda a, b: TRUE if a <= b else 0,
    ">=": lambda a, b: TRUE if a >= b else 0,
}
_LOGIC = {"AND": lambda a, b: a & b, "OR": lambda a, b: a | b, "XOR": lambda a, b: a ^ b}


def binary(op: str, a: int, b: int) -> int:
    """Apply a binary operator to two 16-bit values.

    >>> binary("*/", 100, 0x0180), binary("DIG", 9742, 2), binary("REV", 0b10101101, 4)
    (150, 7, 11)
    """
    if op in _COMPARE:
        return _COMPARE[op](a, b)
    if op in _LOGIC:
        return _LOGIC[op](a, b)
    return BINARY[op][0](a, b)


def unary(op: str, a: int) -> int:
    """Apply a unary operator (``NOT`` included) to a 16-bit value.

    >>> unary("ABS", 0x8000), unary("SQR", 99), unary("NCD", 0), unary("NOT", 1)
    (32768, 9, 0, 65534)
    """
    if op == "NOT":
        return ~a & MASK
    return UNARY[op][0](a)


# ------------------------------------------------------------------ compilation

class Leaf:
    """What a name means to an expression: a constant or a run-time reader."""

    __slots__ = ("const", "read")

    def __init__(self, const: Optional[int] = None, read: Optional[Callable] = None):
        self.const = const
        self.read = read


class ExprContext:
    """What :func:`compile_expr` needs from the compiler.

    Subclasses implement :meth:`leaf` (names -> :class:`Leaf`, raising
    CompileError for bad names) and :meth:`warner` (a position -> a function
    ``(m, message)`` that records a run-time warning).
    """

    def leaf(self, ref: N.Ref) -> Leaf:  # pragma: no cover - interface
        raise NotImplementedError

    def warner(self, pos: N.Pos) -> Callable:  # pragma: no cover - interface
        raise NotImplementedError

    def error(self, message: str, pos: N.Pos) -> CompileError:  # pragma: no cover
        raise NotImplementedError


def compile_expr(e, ctx: ExprContext):
    """Compile an expression node; returns ``(const, None)`` or ``(None, fn)``."""
    if isinstance(e, N.Num):
        if e.value > MASK:
            raise ctx.error(M.CONSTANT_TOO_BIG, e.pos)
        return e.value, None
    if isinstance(e, N.Str):
        if len(e.text) != 1:
            raise ctx.error(M.STRING_AS_NUMBER.format(len(e.text)), e.pos)
        return ord(e.text) & 0xFF, None
    if isinstance(e, N.Ref):
        leaf = ctx.leaf(e)
        return (leaf.const, None) if leaf.read is None else (None, leaf.read)
    if isinstance(e, N.Unary):
        return _compile_unary(e.op, e.operand, e.pos, ctx)
    if isinstance(e, N.Not):
        return _compile_unary("NOT", e.operand, e.pos, ctx)
    if isinstance(e, (N.Binary, N.Compare, N.Logic)):
        return _compile_binary(e, ctx)
    raise TypeError(f"not an expression: {e!r}")


def _compile_unary(op, operand, pos, ctx):
    c, f = compile_expr(operand, ctx)
    if op == "NOT":
        fn, check = (lambda a: ~a & MASK), None
    else:
        fn, check = UNARY[op]
    if c is not None and (check is None or check(c) is None):
        return fn(c), None
    if f is None:
        f = (lambda v: lambda m: v)(c)
    if check is None:
        return None, lambda m: fn(f(m))
    warn = ctx.warner(pos)

    def run(m):
        a = f(m)
        msg = check(a)
        if msg:
            warn(m, msg)
        return fn(a)
    return None, run


def _compile_binary(e, ctx):
    ca, fa = compile_expr(e.left, ctx)
    cb, fb = compile_expr(e.right, ctx)
    op = e.op
    if op in _COMPARE:
        fn, check = _COMPARE[op], None
    elif op in _LOGIC:
        fn, check = _LOGIC[op], None
    else:
        fn, check = BINARY[op]
    if ca is not None and cb is not None and (check is None or check(ca, cb) is None):
        return fn(ca, cb), None
    if check is not None:
        warn = ctx.warner(e.pos)
        ga = fa or (lambda v: lambda m: v)(ca)
        gb = fb or (lambda v: lambda m: v)(cb)

        def run(m):
            a = ga(m)
            b = gb(m)
            msg = check(a, b)
            if msg:
                warn(m, msg)
            return fn(a, b)
        return None, run
    # Specialise the common shapes: variable OP constant, constant OP variable.
    if cb is not None:
        return None, lambda m: fn(fa(m), cb)
    if ca is not None:
        return None, lambda m: fn(ca, fb(m))
    return None, lambda m: fn(fa(m), fb(m))


def as_function(compiled) -> Callable:
    """``(const, fn)`` -> a closure ``f(m)`` in both cases."""
    c, f = compiled
    if f is not None:
        return f
    return lambda m: c


def eval_const(e, lookup: Callable[[str], int], path: str = "<input>",
               source: Optional[str] = None, on_error: Optional[Callable] = None) -> int:
    """Evaluate an expression whose names are constants (``lookup(name) -> value``).

    Division by zero is an error here, as in Parallax's tokenizer (113).
    """
    def err(msg, pos):
        if on_error:
            return on_error(msg, pos)
        return CompileError(msg, path=path, line=pos.line, column=pos.column, length=pos.length)

    def ev(x):
        if isinstance(x, N.Num):
            if x.value > MASK:
                raise err(M.CONSTANT_TOO_BIG, x.pos)
            return x.value
        if isinstance(x, N.Str):
            if len(x.text) != 1:
                raise err(M.STRING_AS_NUMBER.format(len(x.text)), x.pos)
            return ord(x.text) & 0xFF
        if isinstance(x, N.Ref):
            return lookup(x.name) & MASK
        if isinstance(x, N.Unary):
            return unary(x.op, ev(x.operand))
        if isinstance(x, N.Not):
            return unary("NOT", ev(x.operand))
        a, b = ev(x.left), ev(x.right)
        if x.op in ("/", "//") and b == 0:
            raise err(M.DIVIDE_BY_ZERO, leftmost_leaf(x.right).pos)
        return binary(x.op, a, b)
    return ev(e)


def leftmost_leaf(e):
    while isinstance(e, (N.Binary, N.Compare, N.Logic)):
        e = e.left
    while isinstance(e, (N.Unary, N.Not)):
        e = e.operand
    return e


# ------------------------------------------------------------------ stack depth

def check_depth(e, base: int, fail: Callable[[N.Pos], None], limit: int = 8) -> int:
    """Simulate the BS2's evaluation stack; call ``fail(pos)`` at the first
    operand that would be the ``limit + 1``-th pending value.

    ``base`` is how many values the statement already has pending (measured
    per command argument with Parallax's tokenizer; 0 for an assignment).
    Facts: unary operators and parentheses cost nothing, an index is evaluated
    in place, and ``a OP b`` needs ``max(depth(a), 1 + depth(b))``.
    Returns the peak depth.
    """
    peak = base

    def walk(x, level):
        nonlocal peak
        if isinstance(x, (N.Num, N.Str)):
            push(level + 1, x.pos)
        elif isinstance(x, N.Ref):
            if x.index is not None:
                walk(x.index, level)
            else:
                push(level + 1, x.pos)
        elif isinstance(x, (N.Unary, N.Not)):
            walk(x.operand, level)
        else:
            walk(x.left, level)
            walk(x.right, level + 1)

    def push(size, pos):
        nonlocal peak
        if size > limit:
            fail(pos)
        peak = max(peak, size)

    walk(e, base)
    return peak
