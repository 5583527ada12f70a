"""The generator's random source: one ``random.Random`` per program, seeded, with a few helpers.

Everything the generator decides goes through one :class:`Rand`, and nothing
iterates over a set or a hash-ordered container, so a seed always gives the
same program (on every Python version that keeps ``random.Random``'s
sequence, i.e. every CPython 3).
"""
from __future__ import annotations

import random


class Rand:
    """``random.Random(seed)`` plus the choices the generator makes all the time."""

    def __init__(self, seed: int):
        self.r = random.Random(seed)

    def chance(self, p: float) -> bool:
        return self.r.random() < p

    def pick(self, seq):
        return seq[self.r.randrange(len(seq))]

    def between(self, lo: int, hi: int) -> int:
        """An integer in ``lo..hi`` (both included)."""
        return self.r.randint(lo, hi)

    def weighted(self, table: dict):
        """A key of ``table`` (key -> weight; weights <= 0 are never picked)."""
        items = [(k, w) for k, w in table.items() if w > 0]
        total = sum(w for _, w in items)
        x = self.r.random() * total
        for k, w in items:
            x -= w
            if x < 0:
                return k
        return items[-1][0]

    def shuffle(self, seq: list) -> None:
        self.r.shuffle(seq)

    def bits(self, n: int) -> int:
        return self.r.getrandbits(n)

    def case(self, word: str) -> str:
        """``word`` in a random letter case (Spin names and keywords ignore case), mostly as written."""
        if self.chance(0.85):
            return word
        if self.chance(0.5):
            return word.upper() if self.chance(0.5) else word.lower()
        return "".join(c.upper() if self.chance(0.5) else c.lower() for c in word)
