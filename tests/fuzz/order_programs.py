"""Random Spin programs whose expressions have side effects in any operand position (seeded).

A small generator aimed at evaluation order: every expression mixes reads of
locals, VAR longs, bytes, words and array elements with assignments
(``:=``, ``+=`` and the other assignment operators), ``++``/``--``,
``~``/``~~``, ``?``, and calls of methods that change the same variables,
in every operand position (binary operators, call arguments, indexes of
targets, lookup values, case selectors, ``if``/``repeat`` conditions).
Each program stores its results in ``r[]`` and a few pins, then stops; loops
are bounded and there is no recursion, so it always ends.

>>> src = program(1)
>>> src.startswith("'' generated")
True
"""
from __future__ import annotations

import random

__all__ = ["program", "generate"]

_BINARY = ["+", "-", "*", "/", "//", "&", "|", "^", "<<", ">>", "~>", "<-", "->", "><", "#>", "<#", "**",
           "==", "<>", "<", ">", "=<", "=>", "AND", "OR"]
_UNARY = ["-", "!", "||", "^^", "|<", ">|", "NOT"]
_ASSIGN_OPS = ["+=", "-=", "*=", "&=", "|=", "^=", "<<=", ">>=", "#>=", "<#=", "~>=", "/=", "//="]
_LONGS = ["a", "b", "c"]
_LOCALS = ["i", "j", "k"]


class _Gen:
    def __init__(self, seed: int):
        self.rnd = random.Random(seed)
        self.depth = 0

    # ------------------------------------------------------------------ expressions
    def target(self, frame: bool) -> str:
        """A variable to assign (any size; an array index stays inside its array)."""
        r = self.rnd.random()
        if r < 0.25:
            return self.rnd.choice(_LOCALS)
        if r < 0.5:
            return self.rnd.choice(_LONGS)
        if r < 0.6:
            return "bv"
        if r < 0.7:
            return "wv"
        if r < 0.85:
            return f"arr[{self.index(frame)}]"
        if r < 0.92:
            return f"barr[{self.index(frame)}]"
        if frame:
            return f"buf[{self.index(frame)}]"
        return f"long[@arr][{self.index(frame)}]"

    def index(self, frame: bool) -> str:
        return f"({self.expr(frame, 2)}) & 3"

    def leaf(self, frame: bool) -> str:
        r = self.rnd.random()
        if r < 0.3:
            return str(self.rnd.choice([0, 1, 2, 3, 5, 7, 10, 100, -1, -5, 1000, 12345, 31, 32, 255]))
        if r < 0.45:
            return self.rnd.choice(["$7FFF_FFFF", "$8000_0000", "$FF", "%1010", "TRUE", "FALSE", "POSX"])
        return self.target(frame) if self.rnd.random() < 0.9 else self.rnd.choice(["cnt & 0", "ina & 0"])

    def effect(self, frame: bool) -> str:
        t = self.target(frame)
        r = self.rnd.random()
        if r < 0.2:
            return f"({t} := {self.expr(frame)})"
        if r < 0.35:
            return f"({t} {self.rnd.choice(_ASSIGN_OPS)} {self.expr(frame)})"
        if r < 0.55:
            return self.rnd.choice([f"{t}++", f"{t}--", f"++{t}", f"--{t}"])
        if r < 0.65:
            return self.rnd.choice([f"{t}~", f"{t}~~", f"~{t}", f"~~{t}"])
        if r < 0.72:
            return self.rnd.choice([f"?{t}", f"{t}?"])
        if r < 0.9:
            return f"bump({self.expr(frame)})"
        return "tick"

    def expr(self, frame: bool, depth: int = 4) -> str:
        if depth <= 0:
            return self.leaf(frame)
        r = self.rnd.random()
        if r < 0.25:
            return self.leaf(frame)
        if r < 0.45:
            return self.effect(frame)
        if r < 0.8:
            op = self.rnd.choice(_BINARY)
            return f"({self.expr(frame, depth - 1)} {op} {self.expr(frame, depth - 1)})"
        if r < 0.9:
            return f"({self.rnd.choice(_UNARY)} {self.expr(frame, depth - 1)})"
        if r < 0.95:
            items = ", ".join(str(self.rnd.randint(-3, 9)) for _ in range(self.rnd.randint(1, 4)))
            return f"{self.rnd.choice(['lookup', 'lookupz', 'lookdown', 'lookdownz'])}({self.expr(frame, depth - 1)} : {items})"
        return f"twice({self.expr(frame, depth - 1)}, {self.expr(frame, depth - 1)})"

    # ------------------------------------------------------------------ statements
    def statements(self, frame: bool, n: int, indent: str, nest: int = 2) -> list:
        out = []
        for _ in range(n):
            r = self.rnd.random()
            if r < 0.45 or nest == 0:
                out.append(f"{indent}r[{self.rnd.randrange(32)}] := {self.expr(frame)}")
            elif r < 0.6:
                t = self.target(frame)
                op = self.rnd.choice([":="] + _ASSIGN_OPS)
                out.append(f"{indent}{t} {op} {self.expr(frame)}")
            elif r < 0.68:
                e = self.effect(frame)
                out.append(f"{indent}{e[1:-1] if e.startswith('(') else e}")
            elif r < 0.78:
                out.append(f"{indent}if {self.expr(frame, 3)}")
                out += self.statements(frame, 2, indent + "  ", nest - 1)
                out.append(f"{indent}else")
                out += self.statements(frame, 1, indent + "  ", nest - 1)
            elif r < 0.86:
                out.append(f"{indent}repeat ({self.expr(frame, 2)}) & 3")
                out += self.statements(frame, 2, indent + "  ", nest - 1)
            elif r < 0.94:
                out.append(f"{indent}case {self.expr(frame, 3)}")
                for v in self.rnd.sample(range(-2, 6), 2):
                    out.append(f"{indent}  {v}:")
                    out += self.statements(frame, 1, indent + "    ", nest - 1)
                out.append(f"{indent}  other:")
                out += self.statements(frame, 1, indent + "    ", nest - 1)
            else:
                out.append(f"{indent}outa[{self.rnd.randrange(8)}..{self.rnd.randrange(8)}] := {self.expr(frame, 2)}")
        return out


def program(seed: int) -> str:
    """The Spin source of program ``seed``."""
    g = _Gen(seed)
    lines = [f"'' generated by tests/fuzz/order_programs.py, seed {seed}",
             "VAR", "  long r[32], a, b, c, arr[4], calls", "  word wv", "  byte bv, barr[4]",
             "PUB main | i, j, k",
             "  dira[7..0] := $FF",
             f"  a := {g.rnd.randint(-9, 9)}", f"  b := {g.rnd.randint(-9, 9)}", f"  c := {g.rnd.randint(0, 99)}",
             f"  i := {g.rnd.randint(-3, 3)}", f"  j := {g.rnd.randint(0, 5)}", "  k := 0"]
    lines += g.statements(False, 10, "  ")
    lines += ["  framed(a)", "  r[31] := calls"]
    lines += ["PRI framed(x) | i, j, k, buf[4]", "  i := x", "  j := 1", "  k := 2",
              "  buf[0] := 7", "  buf[1] := -1", "  buf[2] := 300", "  buf[3] := 0"]
    lines += g.statements(True, 6, "  ")
    lines += ["  r[30] := buf[0] + buf[1] * 3 + buf[2] * 5 + buf[3] * 7"]
    lines += ["PRI bump(v)", "  calls++", "  a += v", "  barr[v & 3] += 1", "  return a ^ b",
              "PRI tick", "  calls += 10", "  c := c * 3 + 1", "  return c",
              "PRI twice(x, y)", "  b := x", "  return x * 2 - y"]
    return "\n".join(lines) + "\n"


def generate(seed: int):
    """Program ``seed`` as a :class:`tests.fuzz.generator.Program` (one file; results in ``r[]``)."""
    from .generator import Program, Results
    return Program(seed, {"main.spin": program(seed)}, Results("r", 0, 32))
