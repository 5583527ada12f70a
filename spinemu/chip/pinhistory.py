"""The pins as they were: levels at any past cycle, and how they changed over a stretch of time.

A counter in an input mode (:mod:`spinemu.chip.counters`) adds ``FRQ`` for
every clock in which a condition on its pins held, and a cog reads the sum
at some later cycle; by then the other cogs may have run a little past that
cycle.  So a counter does not look at the pins as they are now but asks
:class:`PinHistory`, which answers from records:

* what each cog drove, from the chip's pin record (``chip.pin_events``:
  DIRA/OUTA as the cog wrote them, appended possibly slightly out of time
  order, sorted here per cog);
* what each cog's counters drove, from their register history (every write
  to CTR/FRQ/PHS starts a new stretch with a closed-form output,
  :class:`spinemu.chip.phase.Phase`);
* what nobody drove, from the input model (``chip.inputs``: ``levels(cycle)``
  and ``next_change(cycle)``, :mod:`spinemu.chip.inputs`).

A pin's level is what INA reads: the OR of ``OUTA | counter outputs`` over
the running cogs whose DIRA bit is set, else the input model's level
(Propeller Manual v1.2, "I/O Pins").  :meth:`PinHistory.pieces` describes a
pin over a range of cycles as a few pieces, each constant or one phase
signal, so a counter sums over millions of clocks in a handful of steps.

Feedback outputs (the POS/NEG detector modes with feedback drive BPIN with
the inverse of APIN one clock earlier) are included in a pin's level, but a
feedback counter itself reads its APIN *without* feedback outputs
(``feedback=False``): this breaks the loop a feedback output on its own
input pin (or a chain of feedback counters) would make.

Parts that hang on the pins (a future RC circuit, say) plug in as the input
model; one that depends on what the chip drives reads :meth:`PinHistory.driven`
or :meth:`PinHistory.pieces` for earlier cycles, which is all a counter's
feedback output needs to have happened.
"""
from __future__ import annotations

from bisect import bisect_right

from .phase import Phase, combine

__all__ = ["PinHistory"]

_OFF = (0, 0, False)


class PinHistory:
    """Pin levels of a chip at past cycles (see the module docstring).

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip` whose record is read.
    """

    def __init__(self, chip):
        self.chip = chip
        self._seen = 0
        self._times: list = [[] for _ in range(8)]
        self._states: list = [[] for _ in range(8)]     # (dira, outa, running)

    # the drive record ---------------------------------------------------------
    def _update(self) -> None:
        events = self.chip.pin_events
        n = len(events)
        if self._seen == n:
            return
        times, states = self._times, self._states
        for k in range(self._seen, n):
            t, _, cog, dira, outa, running = events[k]
            ts, ss = times[cog], states[cog]
            if not ts or t >= ts[-1]:
                ts.append(t)
                ss.append((dira, outa, running))
            else:
                i = bisect_right(ts, t)
                if not running:         # a stop inside a bytecode: the write it made after it never happened
                    del ts[i:], ss[i:]
                ts.insert(i, t)
                ss.insert(i, (dira, outa, running))
        self._seen = n

    def cog_state(self, cog: int, t: int) -> tuple:
        """``(dira, outa, running)`` cog ``cog`` had set at cycle ``t`` (OUTA without counter outputs)."""
        self._update()
        ts = self._times[cog]
        i = bisect_right(ts, t)
        return self._states[cog][i - 1] if i else _OFF

    def drive_times(self, cog: int, a: int, b: int) -> list:
        """Cycles in ``(a, b]`` at which cog ``cog`` changed DIRA/OUTA or started/stopped."""
        self._update()
        ts = self._times[cog]
        return ts[bisect_right(ts, a):bisect_right(ts, b)]

    # levels at one cycle ----------------------------------------------------
    def driven(self, t: int, feedback: bool = True) -> tuple[int, int]:
        """``(dir, out)`` at cycle ``t``: OR over the running cogs of DIRA and of ``DIRA & (OUTA | counters)``."""
        self._update()
        counters = self.chip.counters
        d = o = 0
        for cog in range(8):
            dira, outa, running = self.cog_state(cog, t)
            if running and dira:
                d |= dira
                o |= dira & (outa | counters.outputs_at(cog, t, feedback))
        return d, o

    def levels(self, t: int, feedback: bool = True) -> int:
        """What INA read at cycle ``t`` (driven pins as driven, the others from the input model)."""
        d, o = self.driven(t, feedback)
        return (o | (self.chip.inputs.levels(t) & ~d)) & 0xFFFFFFFF

    def level(self, pin: int, t: int, feedback: bool = True) -> int:
        if not 0 <= pin < 32:
            return 0
        return (self.levels(t, feedback) >> pin) & 1

    # levels over a range ----------------------------------------------------
    def pieces(self, pin: int, a: int, b: int, feedback: bool = True) -> list:
        """Pin ``pin``'s level over the cycles ``(a, b]`` as ``[(s, e, signal), ...]``.

        The pieces cover ``(a, b]`` in order, each the cycles ``(s, e]``;
        ``signal`` is ``0``, ``1`` or a :class:`~spinemu.chip.phase.Phase`
        giving the level at each cycle.  Pins 32-63 (port B, which the
        P8X32A does not have) read 0.
        """
        if b <= a:
            return []
        if not 0 <= pin < 32:
            return [(a, b, 0)]
        self._update()
        bit = 1 << pin
        counters = self.chip.counters
        cuts = set()
        for cog in range(8):
            cuts.update(self.drive_times(cog, a, b))
            for unit in counters.units[cog]:
                cuts.update(unit.starts_in(a, b))
        # the input model's changes; asked again after each drive change, since a part's
        # levels may depend on what the cogs drive
        inputs = self.chip.inputs
        fixed = sorted(cuts)
        for lo, hi in zip([a] + fixed, fixed + [b]):
            t = inputs.next_change(lo)
            while t is not None and t <= hi:
                cuts.add(t)
                t = inputs.next_change(t)
        starts = [a + 1] + sorted(x for x in cuts if a + 1 < x <= b)
        out: list = []
        for s, nxt in zip(starts, starts[1:] + [b + 1]):
            self._compose(pin, bit, s - 1, nxt - 1, feedback, out)
        return _merged(out)

    def _compose(self, pin: int, bit: int, s: int, e: int, feedback: bool, out: list) -> None:
        """Append the pieces of ``(s, e]``, in which no cog, counter or input changed."""
        v = s + 1
        counters = self.chip.counters
        driven = False
        sources = []
        for cog in range(8):
            dira, outa, running = self.cog_state(cog, v)
            if not (running and dira & bit):
                continue
            driven = True
            if outa & bit:
                out.append((s, e, 1))
                return
            for ab in (0, 1):
                seg = counters.segment_at(cog, ab, v)
                sig = seg.pin_signal(pin, v)
                if sig is None:
                    continue
                if sig == "feedback":
                    if feedback and 0 <= seg.apin < 32:
                        sources.append(seg)
                    continue
                if sig == 1:                        # a DUTY differential's BPIN before its first carry
                    out.append((s, e, 1))
                    return
                if sig != 0:
                    sources.append(sig)
        if not driven:
            out.append((s, e, (self.chip.inputs.levels(v) >> pin) & 1))
            return
        lists = []
        phases = []
        for src in sources:
            if isinstance(src, Phase):
                phases.append(src)
            else:                                   # a feedback output: !APIN one clock earlier
                lists.append([(ps + 1, pe + 1, _invert(sig if isinstance(sig, int) else sig.delayed(1)))
                              for ps, pe, sig in self.pieces(src.apin, s - 1, e - 1, feedback=False)])
        merged: list = []                           # same-phase outputs (a differential pair) OR'ed exactly
        for p in phases:
            for i, q in enumerate(merged):
                if q.same_phase(p):
                    merged[i] = q.with_window(combine(q.window, p.window, q.modulus, 0b1110))
                    break
            else:
                merged.append(p)
        lists += [[(s, e, p)] for p in merged]
        if not lists:
            out.append((s, e, 0))
        elif len(lists) == 1:
            out.extend(lists[0])
        else:
            out.extend(enumerate_or(lists, s, e))

    def next_change(self, pin: int, a: int, feedback: bool = True, horizon: int = 1 << 40) -> int | None:
        """The first cycle after ``a`` at which pin ``pin`` differs from the cycle before, as recorded now."""
        span = 1 << 12
        lo = a
        while lo < a + horizon:
            hi = min(a + horizon, lo + span)
            prev = None
            for s, e, sig in self.pieces(pin, lo - 1, hi, feedback):
                first = sig if isinstance(sig, int) else sig.at(s + 1)
                if prev is not None and first != prev and s + 1 > a:
                    return s + 1
                if not isinstance(sig, int):
                    v = sig.next_change(max(s + 1, a), e - max(s + 1, a)) if e > max(s + 1, a) else None
                    if v is not None and v <= e:
                        return v
                    prev = sig.at(e)
                else:
                    prev = sig
            lo = hi
            span *= 2
        return None


def _invert(sig):
    return 1 - sig if isinstance(sig, int) else sig.inverted()


def _merged(pieces: list) -> list:
    """Adjacent constant pieces with the same level joined."""
    out: list = []
    for s, e, sig in pieces:
        if e <= s:
            continue
        if isinstance(sig, Phase):
            c = sig.constant()
            if c is not None:
                sig = c
        if out and isinstance(sig, int) and isinstance(out[-1][2], int) and out[-1][2] == sig:
            out[-1] = (out[-1][0], e, sig)
        else:
            out.append((s, e, sig))
    return out


def enumerate_or(lists: list, s: int, e: int) -> list:
    """The OR of several piece lists over ``(s, e]``, as constant pieces (one per change: the slow path)."""
    return enumerate_fn(lists, s, e, lambda levels: int(any(levels)))


def enumerate_fn(lists: list, s: int, e: int, fn) -> list:
    """``fn(levels)`` of several piece lists over ``(s, e]``, as constant pieces.

    Walks every change of every input: the fallback for two signals whose
    phases are unrelated (two counters at different frequencies on one pin,
    or a LOGIC mode on two of them).
    """
    cuts = set()
    for pieces in lists:
        for ps, pe, sig in pieces:
            cuts.add(ps)
            if isinstance(sig, Phase):
                cuts.update(v - 1 for v in sig.changes(ps, pe))
    cuts = sorted(x for x in cuts if s <= x < e)
    starts = [[ps for ps, _, _ in pieces] for pieces in lists]
    out = []
    for lo, hi in zip(cuts, cuts[1:] + [e]):
        v = lo + 1
        levels = []
        for pieces, st in zip(lists, starts):
            i = bisect_right(st, lo) - 1            # the piece (ps, pe] holding v
            ps, pe, sig = pieces[i] if i >= 0 else (lo, lo, 0)
            levels.append(0 if not ps < v <= pe else sig if isinstance(sig, int) else sig.at(v))
        out.append((lo, hi, fn(levels)))
    return _merged(out)
