"""Spin math operators ($E0-$FF) on 32-bit values, as the ROM interpreter computes them.

Every function takes and returns unsigned 32-bit ints (``0 <= v < 2**32``);
signed operators reinterpret their inputs.  Binary operators are called as
``f(x, y)`` for ``x OP y`` (``x`` is the left operand, pushed first); unary
ones as ``f(x)``.

Semantics follow the Propeller Manual v1.2 ("Operators") and were checked
value by value against Parallax's ROM interpreter running on spinsim 0.99
(``tests/data/chip/conformance``):

* shifts and rotates use only the low 5 bits of the count (the ROM hands the
  count to the PASM instruction), so ``x << 32 == x``;
* ``/`` truncates toward zero, ``//`` takes the sign of the dividend; a
  division by zero gives 0 for both (``-2**31 / -1 == -2**31``);
* ``><`` reverses the low ``y`` bits (``y`` mod 32; 0 means all 32);
* ``^^`` is the integer square root of the unsigned value;
* comparisons and the boolean operators give ``TRUE`` (-1) or ``FALSE`` (0).

Hot path: :data:`BINARY` and :data:`UNARY` are indexed by ``opcode & 0x1F``.
"""
from __future__ import annotations

from math import isqrt

__all__ = ["BINARY", "UNARY", "signed", "MASK32"]

MASK32 = 0xFFFFFFFF
TRUE = MASK32


def signed(v: int) -> int:
    """The two's-complement value of a 32-bit pattern."""
    return v - 0x100000000 if v & 0x80000000 else v


def ror(x, y):
    y &= 31
    return ((x >> y) | (x << (32 - y))) & MASK32


def rol(x, y):
    y &= 31
    return ((x << y) | (x >> (32 - y))) & MASK32


def shr(x, y):
    return x >> (y & 31)


def shl(x, y):
    return (x << (y & 31)) & MASK32


def limit_min(x, y):
    return x if signed(x) >= signed(y) else y


def limit_max(x, y):
    return x if signed(x) <= signed(y) else y


def neg(x):
    return -x & MASK32


def bit_not(x):
    return x ^ MASK32


def bit_and(x, y):
    return x & y


def absolute(x):
    return (-x & MASK32) if x & 0x80000000 else x


def bit_or(x, y):
    return x | y


def bit_xor(x, y):
    return x ^ y


def add(x, y):
    return (x + y) & MASK32


def sub(x, y):
    return (x - y) & MASK32


def sar(x, y):
    return (signed(x) >> (y & 31)) & MASK32


def rev(x, y):
    n = (-y) & 31          # the ROM reverses 32 - y bits... of the low end
    bits = 32 - n
    return int(f"{x & ((1 << bits) - 1):0{bits}b}"[::-1], 2) if bits else 0


def log_and(x, y):
    return TRUE if (x and y) else 0


def encode(x):
    return x.bit_length()


def log_or(x, y):
    return TRUE if (x or y) else 0


def decode(x):
    return 1 << (x & 31)


def mul(x, y):
    return (x * y) & MASK32


def mul_high(x, y):
    return ((signed(x) * signed(y)) >> 32) & MASK32


def div(x, y):
    if y == 0:
        return 0
    a, b = signed(x), signed(y)
    q = abs(a) // abs(b)
    return (-q if (a < 0) != (b < 0) else q) & MASK32


def mod(x, y):
    if y == 0:
        return 0
    a, b = signed(x), signed(y)
    r = abs(a) % abs(b)
    return (-r if a < 0 else r) & MASK32


def sqrt(x):
    return isqrt(x)


def cmp_lt(x, y):
    return TRUE if signed(x) < signed(y) else 0


def cmp_gt(x, y):
    return TRUE if signed(x) > signed(y) else 0


def cmp_ne(x, y):
    return TRUE if x != y else 0


def cmp_eq(x, y):
    return TRUE if x == y else 0


def cmp_le(x, y):
    return TRUE if signed(x) <= signed(y) else 0


def cmp_ge(x, y):
    return TRUE if signed(x) >= signed(y) else 0


def log_not(x):
    return 0 if x else TRUE


#: binary operators by ``opcode & 0x1F`` (None where the operator is unary)
BINARY = [ror, rol, shr, shl, limit_min, limit_max, None, None, bit_and, None, bit_or, bit_xor,
          add, sub, sar, rev, log_and, None, log_or, None, mul, mul_high, div, mod, None,
          cmp_lt, cmp_gt, cmp_ne, cmp_eq, cmp_le, cmp_ge, None]
#: unary operators by ``opcode & 0x1F`` (None where the operator is binary)
UNARY = [None] * 32
UNARY[0x06], UNARY[0x07], UNARY[0x09], UNARY[0x11] = neg, bit_not, absolute, encode
UNARY[0x13], UNARY[0x18], UNARY[0x1F] = decode, sqrt, log_not
