"""Values that change by the same amount every pass of a loop: CNT and what is computed from it.

The idle-loop skipper (:mod:`.pasm_idle`) runs one pass of a PASM loop through
the engine's own handlers, with CNT read as an :class:`Aff`: an ``int`` whose
value is the one of this pass, and which knows how it changes from pass to
pass (by the pass's period).  Arithmetic the handlers do on it that keeps
that form (adding or subtracting a constant, ``& $FFFFFFFF``, the sign-bit
flip of signed compares, negation) gives another :class:`Aff`; every
comparison gives this pass's answer and records, in the :class:`Predicates`
of the pass, the set of values for which the answer stays the same, from
which :func:`first_change` works out exactly how many passes keep every
answer.  Anything else (shifts, masks, multiplication, using the value as
an address or an instruction) raises :class:`Unsupported`, and the loop is
not skipped.

An :class:`Aff` stands for the integer ``V(k) = ((a + b*P*k) mod 2**32) + c``
at pass ``k`` (``P`` the period, not known until the pass ends); one that is
only known modulo ``2**32`` (``exact`` false) allows nothing but ``& M``.
"""
from __future__ import annotations

__all__ = ["Aff", "Predicates", "Unsupported", "first_change", "N"]

N = 1 << 32
M = N - 1
SB = 1 << 31
INFINITE = 1 << 62


class Unsupported(Exception):
    """A pass-dependent value went where its change from pass to pass cannot be followed."""


class Predicates(list):
    """The comparisons of one pass: ``(a, b, lo, hi)``: ``(a + b*P*k) mod 2**32`` in ``[lo, hi)`` keeps
    its answer."""


def _unsupported(self, *args, **kwargs):
    raise Unsupported(f"a CNT-derived value in an operation the skipper does not follow ({self!r})")


class Aff(int):
    """A pass-dependent 32-bit value (see the module docstring).  Create with :meth:`make`."""

    @staticmethod
    def make(a: int, b: int, c: int, exact: bool, log: Predicates) -> "Aff":
        a %= N
        v = int.__new__(Aff, a + c)
        v.v, v.a, v.b, v.c, v.exact, v.log = a + c, a, b, c, exact, log
        return v

    def __repr__(self) -> str:
        return f"Aff({self.v}: a={self.a} b={self.b} c={self.c}{'' if self.exact else ' mod'})"

    # ------------------------------------------------------------------ arithmetic that keeps the form
    def __add__(self, o):
        if o.__class__ is Aff:
            return Aff.make(self.a + self.c + o.a + o.c, self.b + o.b, 0, False, self.log)
        if o.__class__ is not int and o.__class__ is not bool:
            return NotImplemented
        return Aff.make(self.a, self.b, self.c + o, self.exact, self.log) if self.exact \
            else Aff.make(self.a + o, self.b, 0, False, self.log)

    __radd__ = __add__

    def __sub__(self, o):
        if o.__class__ is Aff:
            return Aff.make(self.a + self.c - o.a - o.c, self.b - o.b, 0, False, self.log)
        if o.__class__ is not int and o.__class__ is not bool:
            return NotImplemented
        return self.__add__(-o)

    def __rsub__(self, o):
        if o.__class__ is not int and o.__class__ is not bool:
            return NotImplemented
        return Aff.make(o - self.a - self.c, -self.b, 0, False, self.log)

    def __neg__(self):
        return Aff.make(-self.a - self.c, -self.b, 0, False, self.log)

    def __and__(self, o):
        if o.__class__ is int and o == M:
            return Aff.make(self.a + self.c, self.b, 0, True, self.log)
        raise Unsupported("a CNT-derived value masked")

    __rand__ = __and__

    def __xor__(self, o):
        if o.__class__ is int and o == SB and self.exact and self.c == 0:
            return Aff.make(self.a + SB, self.b, 0, True, self.log)
        raise Unsupported("a CNT-derived value xor-ed")

    __rxor__ = __xor__

    # ------------------------------------------------------------------ comparisons: this pass's answer
    def _residues(self, o) -> int:
        """``o - c``: the comparison with ``o`` as one on the residue ``(a + b*P*k) mod 2**32``."""
        if not self.exact or (o.__class__ is not int and o.__class__ is not bool):
            raise Unsupported("a CNT-derived value compared with another")
        return o - self.c

    def _record(self, lo: int, hi: int) -> None:
        lo, hi = max(lo, 0), min(hi, N)
        if lo < hi and not (lo == 0 and hi == N):
            self.log.append((self.a, self.b, lo, hi))

    def __lt__(self, o):
        x = self._residues(o)
        self._record(0, x)
        return self.v < o

    def __le__(self, o):
        x = self._residues(o)
        self._record(0, x + 1)
        return self.v <= o

    def __gt__(self, o):
        x = self._residues(o)
        self._record(0, x + 1)
        return self.v > o

    def __ge__(self, o):
        x = self._residues(o)
        self._record(0, x)
        return self.v >= o

    def __eq__(self, o):
        x = self._residues(o)
        self._record(x, x + 1)
        return self.v == o

    def __ne__(self, o):
        x = self._residues(o)
        self._record(x, x + 1)
        return self.v != o

    def __bool__(self):
        return self.__ne__(0)

    def __rshift__(self, n):
        if not self.exact or n.__class__ is not int:
            raise Unsupported("a CNT-derived value shifted")
        if n == 32 and 0 <= self.c <= N:            # the carry of an addition
            self._record(N - self.c, N)
        elif n == 31 and self.c == 0:               # the sign bit
            self._record(SB, N)
        else:
            raise Unsupported("a CNT-derived value shifted")
        return self.v >> n

    __hash__ = _unsupported


# everything else int can do would drop the pass dependence without a word: refuse it
for _name in ("__mul__", "__rmul__", "__floordiv__", "__rfloordiv__", "__mod__", "__rmod__", "__divmod__",
              "__rdivmod__", "__pow__", "__rpow__", "__lshift__", "__rlshift__", "__rrshift__", "__or__",
              "__ror__", "__invert__", "__abs__", "__pos__", "__index__", "__int__", "__float__",
              "__truediv__", "__rtruediv__", "__round__", "__trunc__", "__floor__", "__ceil__", "bit_count",
              "bit_length", "to_bytes", "conjugate", "as_integer_ratio", "is_integer", "__format__"):
    if hasattr(int, _name):
        setattr(Aff, _name, _unsupported)
Aff.__format__ = int.__format__         # keep debugging output readable
del _name


def first_change(a: int, step: int, lo: int, hi: int) -> int:
    """Passes before ``(a + step*k) mod 2**32`` may leave or enter ``[lo, hi)`` (at least 1).

    Exact lower bound: for every ``k`` below the result the membership is the
    one of ``k = 0``.  (Past it the loop simply runs again and is looked at
    anew, so a bound that comes early costs time, never exactness.)

    >>> first_change(100, 10, 0, 1000)      # 100, 110, ..., 990 inside; 1000 is not
    90
    >>> first_change(5000, -64, 0, 1 << 31) # counting down to below zero
    79
    """
    step %= N
    if step == 0:
        return INFINITE
    if step > N // 2:                       # moving down: mirror, then it moves up
        a, lo, hi, step = N - 1 - a, N - hi, N - lo, N - step
    if lo <= a < hi:
        d = hi - a                          # to leave through hi
    else:
        d = (lo - a) % N                    # to enter at lo
    return max(1, -(-d // step))
