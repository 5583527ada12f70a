"""The counters' pin outputs as the trace shows them, handed out one stretch of time after another.

A counter output (:mod:`spinemu.chip.counters`) is not written into the pin
record: it follows from the counter's register history.  :class:`CounterMarks`
turns that history into *marks* ``(cycle, cog, counter, mask)``: from
``cycle`` on, counter ``counter`` (0 = A) of cog ``cog`` drives the pins in
``mask`` high (before DIRA gating).  :meth:`CounterMarks.take` hands out the
marks of consecutive intervals ``[start, upto)`` of cycles, so the trace at
the end of a run and live pin listeners during it (:mod:`.pinfold`) fold the
same marks, and each call costs time in proportion to the marks it returns
(plus a few look-ups per counter), however long the run has been.

Which marks: one wherever the counter's trace output changes, that is

* where a stretch of its history starts (a CTR/FRQ/PHS write), with the
  stretch's output at that cycle;
* while its cog runs with DIRA set on one of the counter's pins: every change
  of an accumulator output (NCO, DUTY, a PLL output whose period is at least
  :data:`~spinemu.chip.counters.PLL_TRACE_MIN_PERIOD` clocks; faster PLL
  outputs are held low) and of a feedback output (BPIN = !APIN one clock
  earlier), and the output as it is when the cog starts driving again.

A mark that would repeat the counter's previous mask is left out, so the
marks do not depend on where the intervals are cut.  At most
:data:`~spinemu.chip.counters.MAX_EDGES` marks (:attr:`CounterMarks.limit`)
are handed out in a run, the first ones in time order (a warning says when
later ones are left out).

An interval's marks are final when every register write and every DIRA/OUTA
change before ``upto`` is in the record, and the input model's levels before
``upto`` are settled: the listeners' ``upto`` promises that
(:mod:`.listen`), and so does the end of the run.
"""
from __future__ import annotations

from operator import itemgetter

from .counters import _FEEDBACK, _OUTPUTS, _PHASE_OUT, _PLL, MAX_EDGES, PLL_TRACE_MIN_PERIOD

__all__ = ["CounterMarks", "trace_mask"]

_BY_CYCLE = itemgetter(0)
#: marks one piece of a long interval should bring at most, and the longest piece in cycles
_PIECE_MARKS = 1 << 16
_MAX_SPAN = 1 << 40


def trace_mask(history, seg, t: int) -> int:
    """The pins stretch ``seg`` of a counter drives high at ``t`` as the trace shows them (fast PLL outputs low).

    ``history`` is the chip's :class:`~spinemu.chip.pinhistory.PinHistory`
    (a feedback output is APIN one clock earlier, inverted).
    """
    mode = seg.mode
    if mode in _PLL and seg.pll_period() < PLL_TRACE_MIN_PERIOD:
        return 0
    if mode in _PHASE_OUT:
        return seg.outputs(t)
    if mode in _FEEDBACK and seg.bpin < 32 and not history.level(seg.apin, t - 1, False):
        return 1 << seg.bpin
    return 0


class _Cursor:
    """Where one counter's marks have got to: the stretch in force and the last mask handed out."""

    __slots__ = ("cog", "ab", "unit", "index", "mask")

    def __init__(self, cog: int, ab: int, unit):
        self.cog, self.ab, self.unit = cog, ab, unit
        self.index = 0
        self.mask = 0


class CounterMarks:
    """The counters' trace marks of a chip, interval after interval (see the module docstring).

    Args:
        counters: the chip's :class:`~spinemu.chip.counters.Counters`.
    """

    #: marks handed out in a run before the rest are left out
    limit = MAX_EDGES

    def __init__(self, counters):
        self.counters = counters
        #: cycles :meth:`take` walks at once (adapted to how many marks they bring)
        self.span = 1 << 16
        self.cursors = [_Cursor(cog, ab, unit) for cog in range(8) for ab, unit in enumerate(counters.units[cog])]
        #: marks before this cycle have been handed out
        self.start = 0
        #: marks handed out so far
        self.count = 0
        self.capped = False

    def take(self, upto: int) -> list:
        """The marks at cycles in ``[self.start, upto)``, in time order (then by cog and counter).

        A long interval is walked in pieces (:attr:`span` cycles, halved
        while a piece brings more than :data:`_PIECE_MARKS` marks, doubled
        while it brings few), so that reaching the cap stops the work, as
        it does for a listener's short intervals.

        Returns:
            ``[(cycle, cog, counter, mask), ...]``; ``self.start`` becomes
            ``upto`` (nothing when ``upto`` is not after it).
        """
        out: list = []
        a = self.start
        while a < upto and not self.capped:
            b = upto if upto - a <= self.span else a + self.span
            piece = self._piece(a, b)
            n = len(piece)
            if n > _PIECE_MARKS and self.span > 1:
                self.span //= 2
            elif n < _PIECE_MARKS // 4 and self.span < _MAX_SPAN:
                self.span *= 2
            if self.count + n > self.limit:
                del piece[self.limit - self.count:]
                self.capped = True
                self.counters.chip.warnings.append(
                    f"counter output edges exceed {self.limit:,}: later counter edges are not recorded in the trace")
            self.count += len(piece)
            out += piece
            a = b
        if upto > self.start:
            self.start = upto
        self.counters.edges_recorded = self.count
        return out

    def _piece(self, a: int, b: int) -> list:
        """Every counter's marks in ``[a, b)``, in order."""
        out: list = []
        several = False
        for cur in self.cursors:
            n = len(out)
            self._counter(cur, a, b, out)
            several |= 0 < n < len(out)
        if several:
            out.sort(key=_BY_CYCLE)             # stable: equal cycles stay in cog, counter order
        return out

    def _counter(self, cur: _Cursor, a: int, b: int, out: list) -> None:
        """Append counter ``cur``'s marks in ``[a, b)``, stretch by stretch."""
        segs = cur.unit.segs
        i = cur.index
        while True:
            seg = segs[i]
            start = seg.t0 if seg.t0 > 0 else 0
            if start >= b:
                break
            nxt = segs[i + 1].t0 if i + 1 < len(segs) else b
            lo, hi = max(a, start), min(b, nxt) - 1     # this window's cycles of the stretch
            if lo <= hi and (lo == start or seg.mode in _OUTPUTS):
                self._stretch(cur, seg, start, lo, hi, out)
            if nxt >= b:
                break
            i += 1
        cur.index = i

    def _mark(self, cur: _Cursor, t: int, mask: int, out: list) -> None:
        if mask != cur.mask:
            cur.mask = mask
            out.append((t, cur.cog, cur.ab, mask))

    def _stretch(self, cur: _Cursor, seg, start: int, a: int, b: int, out: list) -> None:
        """Counter ``cur``'s marks at cycles ``a..b`` of the stretch ``seg`` that starts at ``start``."""
        counters = self.counters
        hist = counters.history
        if seg.mode in _PHASE_OUT and not seg.known:
            counters._settle(cur.unit, seg)
        if a == start:
            self._mark(cur, start, trace_mask(hist, seg, start), out)
        pins = seg.output_mask()
        if not pins or b <= start or (seg.mode in _PLL and seg.pll_period() < PLL_TRACE_MIN_PERIOD):
            return
        # outputs change at cycle x only while the cog drives at x - 1: follow its drive over a-1 .. b
        cog = cur.cog
        y = a - 1 if a > start else start
        dira, _, running = hist.cog_state(cog, y)
        lo = y if running and dira & pins else None
        for x in hist.drive_times(cog, y, b):
            dira, _, running = hist.cog_state(cog, x)
            if running and dira & pins:
                if lo is None:                  # drives again: the output as it is now
                    lo = x
                    self._mark(cur, x, seg.outputs(x) if seg.mode in _PHASE_OUT else trace_mask(hist, seg, x), out)
            elif lo is not None:
                self._changes(cur, seg, lo, x, out)
                lo = None
        if lo is not None:
            self._changes(cur, seg, lo, b, out)

    def _changes(self, cur: _Cursor, seg, lo: int, hi: int, out: list) -> None:
        """Counter ``cur``'s output changes at cycles in ``(lo, hi]`` (its cog drives from ``lo`` on)."""
        cog, ab = cur.cog, cur.ab
        if seg.mode in _PHASE_OUT:
            # each change flips the output between APIN high and BPIN high (or nothing)
            high = 1 << seg.apin if seg.apin < 32 else 0
            low = 1 << seg.bpin if seg.mode & 1 and seg.bpin < 32 else 0
            if high == low:
                return
            mask = cur.mask
            for te in seg.edges(lo, hi):
                mask = low if mask == high else high
                out.append((te, cog, ab, mask))
            cur.mask = mask
            return
        bpin = 1 << seg.bpin                    # feedback: BPIN = !APIN one clock later
        prev = None
        for s, e, sig in self.counters.history.pieces(seg.apin, lo - 2, hi - 1, False):   # APIN over lo-1 .. hi-1
            phase = not isinstance(sig, int)
            if prev is not None and s + 2 > lo:
                self._mark(cur, s + 2, 0 if (sig.at(s + 1) if phase else sig) else bpin, out)
            if phase:
                for te in sig.changes(s + 1, e):
                    self._mark(cur, te + 1, 0 if sig.at(te) else bpin, out)
            prev = sig
