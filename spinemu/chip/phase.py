"""Closed-form counting on periodic pin signals: the arithmetic behind the counter modules.

Every pin signal a counter can make is a *phase signal*: a phase that grows
by a constant every clock, wrapped to a modulus, and a set of phases in
which the signal is high.  The NCO output is bit 31 of ``PHS`` (phases
``[2**31, 2**32)`` of ``PHS mod 2**32``), the DUTY output is the carry of
``PHS += FRQ`` (phases ``[0, FRQ)`` right after the addition), a PLL output
is a higher or lower bit of the same accumulator, and a differential output
is the complement.  So "how many clocks was this pin high between two
cycles", "how many rising edges" and "when does it next change" reduce to
counting the ``i`` in a range with ``(x0 + f*i) mod M`` in an interval,
which :func:`floor_sum` answers in ``O(log M)`` steps however long the range
(the classic sum of ``floor((a*i + b) / m)``; see e.g. Graham, Knuth and
Patashnik, *Concrete Mathematics*, section 3.5).

:class:`Phase` is such a signal; :mod:`spinemu.chip.pinhistory` builds pin
levels out of them and constants, :mod:`spinemu.chip.counters` counts on
them.  Nothing here knows about cogs or pins.
"""
from __future__ import annotations

from collections.abc import Iterator

__all__ = ["floor_sum", "Phase", "complement", "intersect", "shift", "combine"]


def floor_sum(n: int, m: int, a: int, b: int) -> int:
    """``sum(floor((a*i + b) / m) for i in range(n))`` in ``O(log m)`` steps.

    Args:
        n: the number of terms (``>= 0``).
        m: the divisor (``> 0``).
        a: the step (``>= 0``).
        b: the offset (any integer).

    >>> floor_sum(10, 7, 3, -5) == sum((3 * i - 5) // 7 for i in range(10))
    True
    """
    total = 0
    while n > 0:
        if a >= m:
            total += (a // m) * (n * (n - 1) // 2)
            a %= m
        if b >= m or b < 0:
            total += (b // m) * n
            b %= m
        top = a * n + b             # the terms are floor((a*i + b) / m) < top / m: swap the roles of a and m
        if top < m:
            break
        n, b, m, a = top // m, top % m, a, m
    return total


# ----------------------------------------------------------------------------- phase sets
# A set of phases is a sorted tuple of disjoint half-open intervals (lo, hi) inside [0, M).

def complement(w: tuple, m: int) -> tuple:
    """The phases in ``[0, m)`` not in ``w``."""
    out, at = [], 0
    for lo, hi in w:
        if lo > at:
            out.append((at, lo))
        at = hi
    if at < m:
        out.append((at, m))
    return tuple(out)


def intersect(w1: tuple, w2: tuple) -> tuple:
    out = []
    for lo1, hi1 in w1:
        for lo2, hi2 in w2:
            lo, hi = max(lo1, lo2), min(hi1, hi2)
            if lo < hi:
                out.append((lo, hi))
    return tuple(sorted(out))


def shift(w: tuple, d: int, m: int) -> tuple:
    """``{(p + d) mod m for p in w}``."""
    out = []
    d %= m
    for lo, hi in w:
        lo, hi = lo + d, hi + d
        if hi <= m:
            out.append((lo, hi))
        elif lo >= m:
            out.append((lo - m, hi - m))
        else:
            out.append((lo, m))
            out.append((0, hi - m))
    return _normal(out)


def combine(w1: tuple, w2: tuple, m: int, table: int) -> tuple:
    """The phases at which ``table`` (a truth table) holds of membership in ``w1`` and ``w2``.

    Bit ``x + 2*y`` of ``table`` says whether the result holds where
    membership in ``w1`` is ``x`` and in ``w2`` is ``y`` (the counters' LOGIC
    mode numbering, Propeller Manual v1.2, CTRA/CTRB).
    """
    cuts = sorted({0, m} | {p for lo, hi in w1 + w2 for p in (lo, hi)})
    out = []
    for lo, hi in zip(cuts, cuts[1:]):
        x = _member(w1, lo)
        y = _member(w2, lo)
        if (table >> (x + 2 * y)) & 1:
            out.append((lo, hi))
    return _normal(out)


def _member(w: tuple, p: int) -> int:
    for lo, hi in w:
        if lo <= p < hi:
            return 1
    return 0


def _normal(intervals) -> tuple:
    """Sorted, merged, empty intervals dropped."""
    out = []
    for lo, hi in sorted(intervals):
        if lo >= hi:
            continue
        if out and lo <= out[-1][1]:
            out[-1] = (out[-1][0], max(hi, out[-1][1]))
        else:
            out.append((lo, hi))
    return tuple(out)


class Phase:
    """A signal that is high at cycle ``v`` when ``(base + step*v) mod modulus`` is in ``window``.

    Args:
        base: the phase at cycle 0 (any integer; only its value mod
            ``modulus`` matters).
        step: the phase added every clock (``>= 0``).
        modulus: the phase period (``> 0``).
        window: the phases at which the signal is high, as sorted disjoint
            ``(lo, hi)`` intervals in ``[0, modulus)``.

    Counts are over cycles ``v`` in a half-open range ``(a, b]``.

    >>> nco = Phase(0, 1 << 30, 1 << 32, ((1 << 31, 1 << 32),))   # FRQ = 2**30: period 4
    >>> [nco.at(v) for v in range(8)], nco.count(0, 8), nco.rising(0, 8)
    ([0, 0, 1, 1, 0, 0, 1, 1], 4, 2)
    """

    __slots__ = ("base", "step", "modulus", "window", "_changes")

    def __init__(self, base: int, step: int, modulus: int, window: tuple):
        self.modulus = modulus
        self.step = step % modulus
        self.base = base % modulus
        self.window = window
        self._changes = None        # the phases just after a change (computed on first use)

    def __repr__(self):
        return f"Phase(base={self.base}, step={self.step}, modulus={self.modulus}, window={self.window})"

    def same_phase(self, other: "Phase") -> bool:
        return (self.base, self.step, self.modulus) == (other.base, other.step, other.modulus)

    def with_window(self, window: tuple) -> "Phase":
        return Phase(self.base, self.step, self.modulus, window)

    def constant(self) -> int | None:
        """0 or 1 if the signal never changes, else ``None``."""
        if not self.window:
            return 0
        if self.window == ((0, self.modulus),):
            return 1
        if self.step == 0:
            return self.at(0)
        return None

    def at(self, v: int) -> int:
        return _member(self.window, (self.base + self.step * v) % self.modulus)

    def inverted(self) -> "Phase":
        return self.with_window(complement(self.window, self.modulus))

    def delayed(self, d: int) -> "Phase":
        """The signal ``d`` clocks later: ``delayed(d).at(v) == at(v - d)``."""
        return Phase(self.base - self.step * d, self.step, self.modulus, self.window)

    # counting --------------------------------------------------------------
    def _count_window(self, window: tuple, a: int, b: int) -> int:
        n = b - a
        if n <= 0 or not window:
            return 0
        m, f = self.modulus, self.step
        x0 = self.base + f * (a + 1)
        total = 0
        for lo, hi in window:
            total += floor_sum(n, m, f, x0 - lo) - floor_sum(n, m, f, x0 - hi)
        return total

    def count(self, a: int, b: int) -> int:
        """Cycles in ``(a, b]`` at which the signal is high."""
        return self._count_window(self.window, a, b)

    def _edge_window(self, rising: bool) -> tuple:
        # X(v) = [r(v) in W], X(v - 1) = [r(v) - step in W] = [r(v) in W + step]
        m = self.modulus
        w, before = self.window, shift(self.window, self.step, m)
        if rising:
            return intersect(w, complement(before, m))
        return intersect(complement(w, m), before)

    def rising(self, a: int, b: int) -> int:
        """Cycles ``v`` in ``(a, b]`` with the signal high at ``v`` and low at ``v - 1``."""
        return self._count_window(self._edge_window(True), a, b)

    def falling(self, a: int, b: int) -> int:
        """Cycles ``v`` in ``(a, b]`` with the signal low at ``v`` and high at ``v - 1``."""
        return self._count_window(self._edge_window(False), a, b)

    # enumerating -----------------------------------------------------------
    def changes(self, a: int, b: int) -> Iterator[int]:
        """The cycles ``v`` in ``(a, b]`` at which the signal differs from cycle ``v - 1``, in order."""
        f, m = self.step, self.modulus
        if f == 0 or b <= a:
            return
        window = self._changes
        if window is None:
            window = self._changes = _normal(self._edge_window(True) + self._edge_window(False))
        if not window:
            return
        base = self.base
        lap = (base + f * (a + 1)) // m
        last_lap = (base + f * b) // m
        while lap <= last_lap:
            hits = []
            for lo, hi in window:
                # first v with base + f*v >= lap*m + lo
                v = max(a + 1, -(-(lap * m + lo - base) // f))
                end = lap * m + hi
                while v <= b and base + f * v < end:
                    hits.append(v)
                    v += 1
            yield from sorted(hits)
            lap += 1

    def next_change(self, a: int, horizon: int = 1 << 40) -> int | None:
        """The first cycle after ``a`` (up to ``a + horizon``) at which the signal changes."""
        f, m = self.step, self.modulus
        if f == 0:
            return None
        # whole laps without a hit can only happen for windows narrower than a step: look a lap at a time
        span = max(1, m // f + 2)
        lo = a
        while lo < a + horizon:
            hi = min(a + horizon, lo + span)
            for v in self.changes(lo, hi):
                return v
            lo = hi
        return None
