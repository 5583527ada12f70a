"""Random constants: literals in every number format, CON expressions (integer and float), DAT lines.

The generator never computes what an expression is worth (OpenSpin and
spinemu decide that); it only keeps expressions well-formed: integers and
floats are not mixed, divisors are never zero (``(x | 1)`` or a non-zero
literal), float square roots take an absolute value, and float expressions
stay small enough not to overflow.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .rand import Rand

#: binary operators on integer constants (all of Spin's), with how often they are picked
INT_BINARY = {
    "+": 6, "-": 6, "*": 4, "**": 4, "/": 3, "//": 3, "#>": 2, "<#": 2, "<<": 3, ">>": 3, "~>": 3,
    "->": 2, "<-": 2, "><": 4, "&": 3, "|": 3, "^": 3, "AND": 1, "OR": 1, "==": 1, "<>": 1,
    "<": 1, ">": 1, "=<": 1, "=>": 1,
}
INT_UNARY = {"-": 5, "!": 3, "||": 2, "^^": 2, "|<": 2, ">|": 2, "NOT": 1, "+": 1}
FLOAT_BINARY = {"+": 5, "-": 5, "*": 3, "/": 3, "#>": 1, "<#": 1, "==": 1, "<>": 1, "<": 1, ">": 1,
                "=<": 1, "=>": 1, "AND": 1, "OR": 1}
FLOAT_UNARY = {"-": 4, "||": 2, "+": 1}
#: words that are operators; they need spaces around them
WORD_OPS = ("AND", "OR", "NOT")

INTERESTING = [0, 1, 2, 3, 7, 8, 15, 16, 31, 32, 33, 63, 64, 127, 128, 255, 256, 1000, 0x7FFF, 0x8000,
               0xFFFF, 0x10000, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0xFFFFFFFE, 0x80000001]


def underscored(rng: Rand, digits: str) -> str:
    """``digits`` with ``_`` put in after the first digit now and then (``1_000``, ``$7F_FF``)."""
    if len(digits) < 2 or not rng.chance(0.25):
        return digits
    out = [digits[0]]
    for d in digits[1:]:
        if rng.chance(0.3):
            out.append("_" * rng.between(1, 2))
        out.append(d)
    if rng.chance(0.1):
        out.append("_")
    return "".join(out)


def int_value(rng: Rand, small: bool = False) -> int:
    """An unsigned 32-bit value, often one near a boundary."""
    if small:
        return rng.between(0, 40)
    kind = rng.weighted({"interesting": 4, "byte": 3, "word": 2, "long": 2})
    if kind == "interesting":
        return rng.pick(INTERESTING)
    return rng.bits({"byte": 8, "word": 16, "long": 32}[kind])


def int_literal(rng: Rand, value: int) -> str:
    """``value`` (0..2**32-1) written as decimal, ``$hex``, ``%binary``, ``%%quaternary`` or a character."""
    kinds = {"dec": 5, "hex": 4, "bin": 1 if value < 1 << 12 else 0, "quat": 1 if value < 1 << 16 else 0,
             "char": 2 if 32 <= value < 127 and chr(value) not in '"' else 0}
    kind = rng.weighted(kinds)
    if kind == "dec":
        return underscored(rng, str(value))
    if kind == "hex":
        digits = f"{value:X}" if rng.chance(0.5) else f"{value:x}"
        if rng.chance(0.2):
            digits = "0" * rng.between(1, 3) + digits
        return "$" + underscored(rng, digits)
    if kind == "bin":
        return "%" + underscored(rng, f"{value:b}")
    if kind == "quat":
        q = ""
        v = value
        while True:
            q = str(v & 3) + q
            v >>= 2
            if not v:
                break
        return "%%" + underscored(rng, q)
    return f'"{chr(value)}"'


def float_literal(rng: Rand) -> str:
    """A positive float literal: ``1.5``, ``1_000.25``, ``2.5e-3``, ``1e6``, ``3.0E+2``."""
    kind = rng.weighted({"plain": 5, "exp": 2, "int_exp": 1})
    whole = str(rng.pick([0, 1, 2, 3, 10, 100, 1000, 12345, rng.between(0, 99999)]))
    frac = str(rng.between(0, 999))
    if kind == "plain":
        return underscored(rng, whole) + "." + frac
    exp = rng.between(-6, 6)
    sign = "-" if exp < 0 else rng.pick(["", "+"])
    e = rng.pick(["e", "E"])
    if kind == "exp":
        return f"{whole}.{frac}{e}{sign}{abs(exp)}"
    return f"{rng.between(1, 99)}{e}{sign}{abs(exp)}"


def spaced(op: str) -> str:
    return f" {op} "


def unary_text(op: str, operand: str) -> str:
    """``op`` applied to ``operand`` without gluing two operators into one token."""
    if op.upper() in WORD_OPS:
        return f"{op} {operand}"
    if operand[:1] in "-+!|^<>~?@#=*/&\\":
        return f"{op}({operand})"
    return op + operand


@dataclass
class ConstScope:
    """Constants an expression may name: integer names, float names, and child constants ``obj#NAME``."""

    ints: list = field(default_factory=list)
    floats: list = field(default_factory=list)
    child_ints: list = field(default_factory=list)     # "obj#NAME" texts


class ConstGen:
    """Random constant expressions over a :class:`ConstScope`."""

    def __init__(self, rng: Rand, scope: ConstScope):
        self.rng = rng
        self.scope = scope
        #: the constant names the expressions made so far refer to (callers reset it)
        self.used: list = []

    def int_expr(self, depth: int = 2) -> str:
        rng = self.rng
        if depth <= 0 or rng.chance(0.3):
            return self.int_term(depth)
        kind = rng.weighted({"binary": 6, "unary": 2, "paren": 1, "float_to_int": 1})
        if kind == "unary":
            op = rng.weighted(INT_UNARY)
            return unary_text(rng.case(op) if op in WORD_OPS else op, self.int_term(depth - 1, paren=True))
        if kind == "paren":
            return f"({self.int_expr(depth - 1)})"
        if kind == "float_to_int":
            return f"{rng.case(rng.pick(['round', 'trunc']))}({self.float_expr(depth - 1)})"
        op = rng.weighted(INT_BINARY)
        left = self.int_expr(depth - 1)
        right = self.int_expr(depth - 1)
        if op in ("/", "//"):
            right = self.nonzero_divisor(right)
        if op == "><" and rng.chance(0.5):
            right = str(rng.pick([0, 1, 8, 16, 31, 32, 33, 40, 64])) if rng.chance(0.7) else f"-{rng.between(1, 40)}"
        if op == "**" and rng.chance(0.4):
            left = f"-{int_literal(rng, rng.between(1, 1 << rng.between(1, 31)))}"
        text = f"{left}{spaced(rng.case(op) if op in WORD_OPS else op)}{right}"
        # a division keeps its parentheses: a tighter operator after it would change the divisor
        return f"({text})" if rng.chance(0.5) or op in ("/", "//") else text

    def nonzero_divisor(self, text: str) -> str:
        if self.rng.chance(0.5):
            return f"(({text}) >> 1 | 1)"     # odd and positive: not 0, not -1 (OpenSpin crashes on NEGX / -1)
        return int_literal(self.rng, self.rng.pick([1, 2, 3, 7, 10, 255, 0x7FFFFFFF, 0x10000]))

    def int_term(self, depth: int, paren: bool = False) -> str:
        rng = self.rng
        kinds = {"literal": 6, "name": 4 if self.scope.ints else 0, "child": 2 if self.scope.child_ints else 0,
                 "kconst": 1}
        kind = rng.weighted(kinds)
        if kind == "name":
            name = rng.pick(self.scope.ints)
            self.used.append(name)
            return rng.case(name)
        if kind == "child":
            self.used.append("#")
            return rng.pick(self.scope.child_ints)
        if kind == "kconst":
            return rng.case(rng.pick(["TRUE", "FALSE", "POSX", "NEGX"]))
        text = int_literal(rng, int_value(rng))
        if rng.chance(0.15):
            text = "-" + text if text[0] != "-" else text
            if paren:
                text = f"({text})"
        return text

    def float_expr(self, depth: int = 2) -> str:
        rng = self.rng
        if depth <= 0 or rng.chance(0.35):
            return self.float_term()
        kind = rng.weighted({"binary": 5, "unary": 2, "sqrt": 1, "paren": 1})
        if kind == "unary":
            return unary_text(rng.weighted(FLOAT_UNARY), self.float_term())
        if kind == "sqrt":
            return f"^^||{self.float_term()}" if rng.chance(0.5) else f"^^(||{self.float_term()})"
        if kind == "paren":
            return f"({self.float_expr(depth - 1)})"
        op = rng.weighted(FLOAT_BINARY)
        left = self.float_expr(depth - 1)
        right = self.float_term() if op in ("*", "/") else self.float_expr(depth - 1)
        if op == "/":
            right = float_literal(rng)
            if float(right.replace("_", "")) == 0.0:
                right = "2.5"
        text = f"{left}{spaced(rng.case(op) if op in WORD_OPS else op)}{right}"
        return f"({text})" if rng.chance(0.5) or op == "/" else text

    def float_term(self) -> str:
        rng = self.rng
        kind = rng.weighted({"literal": 6, "name": 3 if self.scope.floats else 0, "float": 2, "pi": 1})
        if kind == "name":
            name = rng.pick(self.scope.floats)
            self.used.append(name)
            return rng.case(name)
        if kind == "float":
            inner = int_literal(rng, rng.between(0, 100000))
            return f"{rng.case('float')}({'-' if rng.chance(0.3) else ''}{inner})"
        if kind == "pi":
            return rng.case("PI")
        text = float_literal(rng)
        return "-" + text if rng.chance(0.2) else text
