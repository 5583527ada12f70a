"""Counter modules CTRA/CTRB (placeholder until the counter model lands)."""
from __future__ import annotations


class Counters:
    def __init__(self, chip):
        self.chip = chip

    def write(self, c, which: int, v: int, t: int) -> None:
        name = ("ctra", "ctrb", "frqa", "frqb", "phsa", "phsb")[which]
        setattr(c, name, v)

    def phs(self, c, ab: int, t: int) -> int:
        return c.phsb if ab else c.phsa
