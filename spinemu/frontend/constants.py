"""Constant expressions: CON values, DAT data, ``constant()``, the way OpenSpin folds them.

A constant is a 32-bit pattern plus a flag saying whether it is an IEEE-754
single (Spin's floating-point constants).  Integer operators wrap at 32
bits; floating-point operators round to single precision after every step.
Facts observed on OpenSpin 1.00.81 (probe programs, tests/data/compiler):

* comparisons, AND, OR, NOT give -1/0 on integers but 1.0/0.0 on floats;
* ``**`` on constants is the *unsigned* high half of the product, except that
  OpenSpin loses a carry when the two middle 16x16 products overflow 32 bits;
* ``/`` and ``//`` truncate toward zero; division by zero is an error;
* ``x >< n`` reverses the low ``n`` bits (``n`` = 0 gives 0, 32 all bits); the
  count is ``n & $FF``, and past 32 the sign bit of ``x`` fills in from the right;
* ``^^`` of a negative integer is 0;
* ``round(x)`` is ``x + 0.5`` (in single precision) rounded toward zero, so
  ``round(-680.0)`` is -679; ``trunc`` rounds toward zero; both give
  NEGX ($8000_0000) when the result does not fit;
* integers and floats cannot be mixed; the bit operators refuse floats.
"""
from __future__ import annotations

import math
import struct
from typing import Callable, NamedTuple, Optional

from .. import messages as msg
from .ast import (
    Binary, Builtin, Float, KConst, Number, Paren, Str, Unary,
)

__all__ = ["Const", "ConstError", "Undefined", "NotConstant", "evaluate", "KCONST_VALUES", "to_signed",
           "float_bits", "bits_float", "encode_clock"]

MASK = 0xFFFFFFFF
NEGX = 0x80000000


class Const(NamedTuple):
    """A folded constant: ``bits`` (0..2**32-1) and whether it is a float."""

    bits: int
    is_float: bool = False

    @property
    def signed(self) -> int:
        return to_signed(self.bits)


class ConstError(Exception):
    """An error in a constant expression (``node`` says where)."""

    def __init__(self, message: str, node):
        super().__init__(message)
        self.message = message
        self.node = node


class Undefined(ConstError):
    """A name that is not defined at all (reported once per name)."""

    def __init__(self, name: str, node):
        super().__init__(msg.UNDEFINED.format(name=name), node)
        self.name = name


class NotConstant(Exception):
    """The expression is not constant (``node`` is the first non-constant part)."""

    def __init__(self, node):
        super().__init__(node)
        self.node = node


def to_signed(v: int) -> int:
    v &= MASK
    return v - 0x100000000 if v & 0x80000000 else v


def float_bits(f: float) -> int:
    """IEEE single bits of ``f`` (rounded to nearest; overflow gives infinity)."""
    try:
        return struct.unpack("<I", struct.pack("<f", f))[0]
    except OverflowError:
        return 0x7F800000 if f > 0 else 0xFF800000


def bits_float(b: int) -> float:
    return struct.unpack("<f", struct.pack("<I", b & MASK))[0]


#: the built-in constant names (lower case); PI is a float
KCONST_VALUES = {
    "true": Const(MASK), "false": Const(0), "posx": Const(0x7FFFFFFF), "negx": Const(NEGX),
    "pi": Const(0x40490FDB, True),
    "rcfast": Const(0x001), "rcslow": Const(0x002), "xinput": Const(0x004), "xtal1": Const(0x008),
    "xtal2": Const(0x010), "xtal3": Const(0x020), "pll1x": Const(0x040), "pll2x": Const(0x080),
    "pll4x": Const(0x100), "pll8x": Const(0x200), "pll16x": Const(0x400),
}

_FLOAT_OK = {"+", "-", "*", "/", "#>", "<#", "==", "<>", "<", ">", "=<", "=>", "AND", "OR"}
_FLOAT_UNARY_OK = {"-", "||", "^^", "NOT", "+"}


def _reverse(value: int, bits: int) -> int:
    """``value >< bits`` as OpenSpin folds it: ``bits & $FF`` times, shift the low bit of
    ``value`` into the result and ``value`` right arithmetically (so past 32 the result
    fills with sign bits; 0, 256, ... give 0)."""
    n = bits & 0xFF
    if n <= 32:
        return int(f"{value & MASK:032b}"[::-1], 2) >> (32 - n) if n else 0
    v = to_signed(value)
    r = 0
    for _ in range(n):
        r = ((r << 1) | (v & 1)) & MASK
        v >>= 1
    return r


def _multiply_high(a: int, b: int) -> int:
    """``a ** b`` as OpenSpin folds it: the high long of the unsigned 64-bit product, built
    from 16-bit halves, where the sum of the two middle products drops its carry out of
    bit 31 (so ``$FFFF_FFFF ** $FFFF_FFFF`` is ``$FFFE_FFFE``, not ``$FFFF_FFFE``)."""
    al, ah, bl, bh = a & 0xFFFF, a >> 16, b & 0xFFFF, b >> 16
    middle = (ah * bl + al * bh) & MASK
    return ah * bh + (middle >> 16) + (((middle & 0xFFFF) + ((al * bl) >> 16)) >> 16)


def _int_binary(op: str, a: int, b: int, node) -> int:
    sa, sb = to_signed(a), to_signed(b)
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return sa * sb
    if op == "**":
        return _multiply_high(a, b)
    if op in ("/", "//"):
        if sb == 0:
            raise ConstError(msg.DIVIDE_BY_ZERO, node)
        q = abs(sa) // abs(sb)
        if (sa < 0) != (sb < 0):
            q = -q
        return q if op == "/" else sa - q * sb
    if op == "#>":
        return max(sa, sb)
    if op == "<#":
        return min(sa, sb)
    n = b & 31
    if op == "<<":
        return a << n
    if op == ">>":
        return a >> n
    if op == "~>":
        return sa >> n
    if op == "->":
        return (a >> n) | (a << (32 - n))
    if op == "<-":
        return (a << n) | (a >> (32 - n))
    if op == "><":
        return _reverse(a, sb)
    if op == "&":
        return a & b
    if op == "|":
        return a | b
    if op == "^":
        return a ^ b
    truth = {
        "AND": bool(a) and bool(b), "OR": bool(a) or bool(b), "==": a == b, "<>": a != b,
        "<": sa < sb, ">": sa > sb, "=<": sa <= sb, "=>": sa >= sb,
    }[op]
    return MASK if truth else 0


def _float_binary(op: str, a: int, b: int) -> Const:
    fa, fb = bits_float(a), bits_float(b)
    if op in ("+", "-", "*", "/"):
        try:
            r = {"+": lambda: fa + fb, "-": lambda: fa - fb, "*": lambda: fa * fb,
                 "/": lambda: fa / fb}[op]()
        except ZeroDivisionError:
            r = math.copysign(math.inf, fa) if fa != 0 else math.nan
        except OverflowError:
            r = math.inf
        return Const(float_bits(r), True)
    if op == "#>":
        return Const(a if fa >= fb else b, True)
    if op == "<#":
        return Const(a if fa <= fb else b, True)
    truth = {
        "AND": fa != 0 and fb != 0, "OR": fa != 0 or fb != 0, "==": fa == fb, "<>": fa != fb,
        "<": fa < fb, ">": fa > fb, "=<": fa <= fb, "=>": fa >= fb,
    }[op]
    return Const(0x3F800000 if truth else 0, True)


def _int_unary(op: str, a: int) -> int:
    sa = to_signed(a)
    if op in ("-",):
        return -sa
    if op == "+":
        return a
    if op == "!":
        return ~a
    if op == "||":
        return abs(sa)
    if op == "^^":
        return math.isqrt(sa) if sa > 0 else 0
    if op == "|<":
        return 1 << (a & 31)
    if op == ">|":
        return (a & MASK).bit_length()
    if op == "NOT":
        return 0 if a else MASK
    raise AssertionError(op)


def _float_unary(op: str, a: int) -> Const:
    if op == "-":
        return Const(a ^ 0x80000000, True)
    if op == "+":
        return Const(a, True)
    if op == "||":
        return Const(a & 0x7FFFFFFF, True)
    if op == "^^":
        f = bits_float(a)
        return Const(float_bits(math.sqrt(f)) if f >= 0 else 0x7FC00000, True)
    if op == "NOT":
        return Const(0 if bits_float(a) != 0 else 0x3F800000, True)
    raise AssertionError(op)


def _toward_zero(f: float) -> float:
    return float(math.trunc(f)) if math.isfinite(f) else f


def _to_int(f: float) -> int:
    if math.isnan(f) or not -2147483648.0 <= f < 2147483648.0:
        return NEGX
    return int(f) & MASK


def evaluate(node, resolve: Callable, char_bytes: Optional[Callable] = None) -> Const:
    """Fold ``node`` to a :class:`Const`.

    Args:
        node: an expression node.
        resolve: called with nodes this module does not fold itself (names,
            ``obj#NAME``, ``$``, ``@label``); returns a Const or raises
            :class:`NotConstant`/:class:`ConstError`.
        char_bytes: turns a string literal into its bytes (default: Latin-1).

    Raises:
        NotConstant: the expression uses something that is not constant.
        ConstError: the expression is constant but invalid.

    >>> from spinemu.frontend import parse_source
    >>> e = parse_source("CON\\n  X = (1 << 4) + $F\\n").cons[0].value
    >>> evaluate(e, lambda n: None)
    Const(bits=31, is_float=False)
    """
    return _Folder(resolve, char_bytes).fold(node)


class _Folder:
    def __init__(self, resolve, char_bytes):
        self.resolve = resolve
        self.char_bytes = char_bytes or (lambda s: s.encode("latin-1", "replace"))

    def fold(self, node) -> Const:
        t = type(node)
        if t is Number:
            if node.value > MASK:
                text = node.text if len(node.text) <= 40 else node.text[:20] + "..." + node.text[-4:]
                raise ConstError(msg.CONSTANT_TOO_BIG.format(value=text), node)
            return Const(node.value)
        if t is Float:
            return Const(float_bits(node.value), True)
        if t is Paren:
            return self.fold(node.expr)
        if t is KConst:
            return KCONST_VALUES[node.name]
        if t is Str:
            data = self.char_bytes(node.text)
            if len(data) != 1:
                raise ConstError(msg.STRING_TOO_LONG if data else msg.EMPTY_STRING, node)
            return Const(data[0])
        if t is Unary:
            return self.unary(node)
        if t is Binary:
            return self.binary(node)
        if t is Builtin and node.name in ("constant", "float", "round", "trunc") and node.args \
                and len(node.args) == 1:
            return self.builtin(node)
        result = self.resolve(node)
        if result is None:
            raise NotConstant(node)
        return result

    def unary(self, node) -> Const:
        a = self.fold(node.operand)
        op = node.op
        if a.is_float:
            if op not in _FLOAT_UNARY_OK:
                raise ConstError(msg.FLOAT_NOT_ALLOWED, node)
            return _float_unary(op, a.bits)
        return Const(_int_unary(op, a.bits) & MASK)

    def binary(self, node) -> Const:
        a = self.fold(node.left)
        b = self.fold(node.right)
        op = node.op
        if a.is_float != b.is_float:
            raise ConstError(msg.INTEGER_AND_FLOAT, node.right)
        if a.is_float:
            if op not in _FLOAT_OK:
                raise ConstError(msg.FLOAT_NOT_ALLOWED, node)
            return _float_binary(op, a.bits, b.bits)
        return Const(_int_binary(op, a.bits, b.bits, node) & MASK)

    def builtin(self, node) -> Const:
        a = self.fold(node.args[0])
        name = node.name
        if name == "constant":
            return a
        if name == "float":
            if a.is_float:
                raise ConstError(msg.FLOAT_NOT_ALLOWED, node.args[0])
            return Const(float_bits(float(a.signed)), True)
        if not a.is_float:
            raise ConstError(msg.INTEGER_AND_FLOAT, node.args[0])
        f = bits_float(a.bits)
        if name == "round":
            return Const(_to_int(_toward_zero(bits_float(float_bits(f + 0.5)))))
        return Const(_to_int(_toward_zero(f)))


def encode_clock(mode: int) -> Optional[int]:
    """The CLK register value for a ``_clkmode`` setting, or ``None`` if invalid.

    >>> hex(encode_clock(0x408)), encode_clock(0x001), hex(encode_clock(0x004))
    ('0x6f', 0, '0x22')
    """
    src = mode & 0x3F
    pll = mode >> 6
    if mode & ~0x7FF or bin(src).count("1") != 1 or bin(pll).count("1") > 1:
        return None
    if src & 0x3:  # RCFAST, RCSLOW
        return None if pll else (0 if src == 1 else 1)
    osc = {0x04: 0, 0x08: 1, 0x10: 2, 0x20: 3}[src]
    if not pll:
        return 0x20 | (osc << 3) | 2
    return 0x60 | (osc << 3) | (3 + pll.bit_length() - 1)
