"""Counter modules CTRA/CTRB: every mode, event-driven, in closed form.

Each cog has two counters (Propeller Manual v1.2, "CTRA, CTRB" and its
counter mode table; AN001 "Propeller Counters").  The CTR register holds the
mode (bits 30..26), the PLL divider (25..23), BPIN (14..9) and APIN (5..0).
Every clock, while the mode's condition holds, ``PHS += FRQ``.  A counter
output reaches its pin only where the cog's DIRA bit is set (the cog drives
``OUTA | counter outputs``); APIN/BPIN values 32..63 name port B, which the
P8X32A does not have: outputs there go nowhere and inputs read 0.

=========  ============================  ==================  ==========  ==========
CTRMODE    mode                          PHS += FRQ when     APIN        BPIN
=========  ============================  ==================  ==========  ==========
%00000     off                           never
%00001     PLL internal (video)          always
%00010     PLL single-ended              always              PLL
%00011     PLL differential              always              PLL         !PLL
%00100     NCO single-ended              always              PHS[31]
%00101     NCO differential              always              PHS[31]     !PHS[31]
%00110     DUTY single-ended             always              carry
%00111     DUTY differential             always              carry       !carry
%01000     POS detector                  A1
%01001     ... with feedback             A1                              !A1
%01010     POSEDGE detector              A1 & !A2
%01011     ... with feedback             A1 & !A2                        !A1
%01100     NEG detector                  !A1
%01101     ... with feedback             !A1                             !A1
%01110     NEGEDGE detector              !A1 & A2
%01111     ... with feedback             !A1 & A2                        !A1
%10000-    LOGIC modes                   bit (A1 + 2*B1) of
%11111     (never, !A&!B, A&!B, ... A|B,  the mode's low four
           always)                       bits
=========  ============================  ==================  ==========  ==========

A1/B1 are the pin levels (as INA reads them) one clock earlier, A2 two
clocks earlier: the counter's inputs are registered, so a pin change at
cycle ``t`` first counts in the update of cycle ``t + 1`` and a feedback
output follows its input one clock later.

How it is computed.  Nothing runs per clock.  Every write to CTR, FRQ or
PHS starts a new *segment* of the counter's history (:class:`_Counter`).
In the accumulating modes PHS is ``PHS0 + FRQ * (t - t0)`` and each output is
a phase signal (:class:`spinemu.chip.phase.Phase`): NCO = bit 31 of the
accumulator, DUTY = the carry of the addition, PLL = bit ``34 - PLLDIV`` of
it (the VCO runs at 16 times the NCO frequency and is divided by
``2**(7 - PLLDIV)``; an ideal, locked PLL: its frequency is exact, the
divider's phase is the accumulator's, there is no jitter or lock time).  In
the input modes PHS is ``PHS0 + FRQ * (clocks the condition held)``, counted
from the pin history (:mod:`spinemu.chip.pinhistory`): pins are piecewise
constant or counter-driven between recorded changes, so a read sums over
pieces in closed form, and only when PHS is read (at the moment the reading
instruction reads it; by then every other cog has run up to that moment:
the scheduler orders register reads by :func:`spinemu.chip.timing.access_offsets`).
Counter outputs reach the trace and the live pin listeners from this
history, as marks where they change (:mod:`spinemu.chip.countermarks`,
folded with the pin record by :mod:`spinemu.chip.pinfold`); WAITPEQ/WAITPNE
wake on them during the run.

PLL outputs.  A PLL output at tens of MHz cannot be a list of edges: an
output whose period is at least :data:`PLL_TRACE_MIN_PERIOD` clocks is
recorded edge by edge like an NCO output; a faster one is held low in the
trace and reported instead (``Chip.counters.pll_outputs()``, the run's
``stats["pll"]`` and a warning).  INA and other counters read every PLL
output as its ideal square wave sampled at each clock.  A PLL whose VCO
would run outside 64-128 MHz (NCO input 4-8 MHz) does not lock on the chip;
a warning says so, and the model still gives the ideal frequency.

Feedback modes with only digital inputs.  A sigma-delta ADC (POS detector
with feedback, an RC network from BPIN and the sensor to APIN) only works
because the capacitor integrates BPIN.  Without a part on the pins APIN
reads what the cogs or the input model put there, so PHS counts the clocks
APIN was high and BPIN shows APIN inverted one clock later: with a constant
input the ADC reads full scale (APIN high: FRQ per clock) or 0, not a
mid-scale value.  A part that models the RC plugs in as the input model and
reads BPIN's drive through :class:`~spinemu.chip.pinhistory.PinHistory`.

Limits.  A feedback counter reads its APIN without feedback outputs (its own
or another counter's): a feedback output wired straight to its own input, or
a chain of feedback counters, is not an oscillator here.  A counter's PHS at
the moment of a register *write* is settled later, when it is next needed,
from the same history.
"""
from __future__ import annotations

from bisect import bisect_right
from collections import namedtuple

from .phase import Phase, combine
from .pinhistory import PinHistory, enumerate_fn

__all__ = ["Counters", "PllOutput", "MODE_NAMES", "MODE_NCO", "MODE_DUTY", "MAX_EDGES",
           "PLL_TRACE_MIN_PERIOD", "reads_pins_mode"]

_M = 0xFFFFFFFF
(MODE_OFF, MODE_PLL_INTERNAL, MODE_PLL, MODE_PLL_DIFF, MODE_NCO, MODE_NCO_DIFF, MODE_DUTY,
 MODE_DUTY_DIFF) = range(8)
MODE_ALWAYS = 0b11111

#: the manual's names of the 32 modes
MODE_NAMES = (
    "off", "PLL internal", "PLL single-ended", "PLL differential", "NCO single-ended", "NCO differential",
    "DUTY single-ended", "DUTY differential", "POS detector", "POS detector with feedback",
    "POSEDGE detector", "POSEDGE detector with feedback", "NEG detector", "NEG detector with feedback",
    "NEGEDGE detector", "NEGEDGE detector with feedback", "LOGIC never", "LOGIC !A & !B", "LOGIC A & !B",
    "LOGIC !B", "LOGIC !A & B", "LOGIC !A", "LOGIC A <> B", "LOGIC !A | !B", "LOGIC A & B", "LOGIC A == B",
    "LOGIC A", "LOGIC A | !B", "LOGIC B", "LOGIC !A | B", "LOGIC A | B", "LOGIC always")

_ACCUMULATING = frozenset(range(1, 8)) | {MODE_ALWAYS}           # PHS += FRQ every clock
_PHASE_OUT = frozenset(range(2, 8))                              # outputs from the accumulator
_FEEDBACK = frozenset({0b01001, 0b01011, 0b01101, 0b01111})      # BPIN = !A1
_READS_PINS = frozenset(range(8, 16)) | frozenset(range(17, 31))
_OUTPUTS = _PHASE_OUT | _FEEDBACK
_PLL = frozenset({MODE_PLL_INTERNAL, MODE_PLL, MODE_PLL_DIFF})

#: counter output changes put into one run's trace (and handed to pin listeners) before
#: it stops taking them (a 40 MHz DUTY output would otherwise fill memory); a warning
#: tells when it happens (:mod:`spinemu.chip.countermarks`)
MAX_EDGES = 2_000_000
#: PLL outputs with a period of at least this many clocks (5 MHz at 80 MHz) appear
#: in the trace edge by edge; faster ones are held low there and reported by frequency
PLL_TRACE_MIN_PERIOD = 16

#: one PLL configuration of a run (see :meth:`Counters.pll_outputs`)
PllOutput = namedtuple("PllOutput", "cog counter mode pins frequency_hz vco_hz start_cycle end_cycle traced")


def reads_pins_mode(mode: int) -> bool:
    """Whether PHS in counter mode ``mode`` depends on pin levels (the detector and LOGIC modes)."""
    return mode in _READS_PINS


class _Counter:
    """One stretch of a counter's history: the registers as written at cycle ``t0``.

    ``phs0`` is PHS at ``t0`` (``acc0`` the same value without the 32-bit
    wrap, for PLL dividers); ``known`` is False while it still has to be
    summed from the previous stretch (an input mode, settled on demand).
    """

    __slots__ = ("ctr", "frq", "phs0", "acc0", "t0", "mode", "known", "index", "ck_t", "ck_n", "sig")

    def __init__(self):
        self.ctr = self.frq = self.phs0 = self.acc0 = self.t0 = self.mode = self.index = 0
        self.known = True
        self.ck_t = self.ck_n = 0
        self.sig = None

    @property
    def apin(self) -> int:
        return self.ctr & 63

    @property
    def bpin(self) -> int:
        return (self.ctr >> 9) & 63

    @property
    def plldiv(self) -> int:
        return (self.ctr >> 23) & 7

    def phs(self, t: int) -> int:
        """PHS at cycle ``t`` in an accumulating or idle mode (input modes: see :meth:`Counters.phs`)."""
        if self.mode in _ACCUMULATING:
            return (self.phs0 + self.frq * (t - self.t0)) & _M
        return self.phs0 & _M

    def acc(self, t: int) -> int:
        """The accumulator at ``t`` without the 32-bit wrap (accumulating modes)."""
        if self.mode in _ACCUMULATING:
            return self.acc0 + self.frq * (t - self.t0)
        return self.phs0

    # outputs --------------------------------------------------------------------
    def signal(self) -> Phase | None:
        """APIN's output as a phase signal (accumulator output modes), else ``None``."""
        if self.sig is not None:
            return self.sig
        mode = self.mode
        base = self.acc0 - self.frq * self.t0
        if mode in (MODE_NCO, MODE_NCO_DIFF):
            sig = Phase(base, self.frq, 1 << 32, ((1 << 31, 1 << 32),))
        elif mode in (MODE_DUTY, MODE_DUTY_DIFF):   # carry of the addition that ended at v: PHS(v) < FRQ
            sig = Phase(base, self.frq, 1 << 32, ((0, self.frq),) if self.frq else ())
        elif mode in (MODE_PLL, MODE_PLL_DIFF):
            k = 34 - self.plldiv
            sig = Phase(base, self.frq, 1 << (k + 1), ((1 << k, 1 << (k + 1)),))
        else:
            return None
        if self.known:
            self.sig = sig
        return sig

    def pll_period(self) -> float:
        """Clocks per period of the PLL output (``inf`` when FRQ is 0)."""
        return (1 << (35 - self.plldiv)) / self.frq if self.frq else float("inf")

    def pin_signal(self, pin: int, v: int):
        """What this stretch drives on ``pin`` at cycle ``v``: ``None``, 0, a Phase, or ``"feedback"``."""
        mode = self.mode
        if mode in _PHASE_OUT:
            on_a, on_b = pin == self.apin, mode & 1 and pin == self.bpin
            if on_a and on_b:
                return 1                            # a differential pair on one pin: always one of them
            if on_a:
                if mode >= MODE_DUTY and v <= self.t0:
                    return 0                        # no carry before the first addition
                return self.signal()
            if on_b:
                if mode >= MODE_DUTY and v <= self.t0:
                    return 1
                return self.signal().inverted()
        elif mode in _FEEDBACK and pin == self.bpin:
            return "feedback"
        return None

    def output_mask(self) -> int:
        """The pins (0-31) this stretch can drive."""
        mode, mask = self.mode, 0
        if mode in _PHASE_OUT and self.apin < 32:
            mask |= 1 << self.apin
        if ((mode in _PHASE_OUT and mode & 1) or mode in _FEEDBACK) and self.bpin < 32:
            mask |= 1 << self.bpin
        return mask

    def outputs(self, t: int) -> int:
        """The pin mask this stretch's accumulator outputs drive high at cycle ``t`` (feedback excluded)."""
        mode = self.mode
        if mode not in _PHASE_OUT:
            return 0
        acc = self.acc0 + self.frq * (t - self.t0)
        if mode >= MODE_DUTY:                       # the carry of the addition that ended at t
            level = 1 if t > self.t0 and (acc >> 32) != ((acc - self.frq) >> 32) else 0
        elif mode >= MODE_NCO:
            level = (acc >> 31) & 1
        else:
            level = (acc >> (34 - self.plldiv)) & 1
        if level:
            return 1 << self.apin if self.apin < 32 else 0
        return 1 << self.bpin if mode & 1 and self.bpin < 32 else 0

    def edges(self, t_from: int, t_to: int):
        """Cycles in ``(t_from, t_to]`` (from ``t0`` on) at which :meth:`outputs` changes, in order."""
        if self.mode not in _PHASE_OUT or self.frq == 0:
            return
        sig = self.signal()
        a = max(t_from, self.t0)
        if self.mode >= MODE_DUTY and t_from <= self.t0 < t_to:
            if sig.at(self.t0 + 1):
                yield self.t0 + 1               # from the forced low at t0
            a = self.t0 + 1
        yield from sig.changes(a, t_to)


class _Unit:
    """One counter's history: its stretches in time order."""

    __slots__ = ("segs", "starts", "cur")

    def __init__(self):
        first = _Counter()
        self.segs = [first]
        self.starts = [-1 << 62]
        self.cur = first

    def at(self, t: int) -> _Counter:
        """The stretch in force at cycle ``t``."""
        cur = self.cur
        if t >= cur.t0:
            return cur
        return self.segs[bisect_right(self.starts, t) - 1]

    def starts_in(self, a: int, b: int) -> list:
        """Cycles in ``(a, b]`` at which this counter's outputs switch stretch (and a DUTY's first carry)."""
        if self.cur.t0 + 1 <= a:
            return []
        out = []
        for seg in self.segs[max(bisect_right(self.starts, a - 1), 1):]:
            if seg.t0 > b:
                break
            if seg.t0 > a:
                out.append(seg.t0)
            if seg.mode in (MODE_DUTY, MODE_DUTY_DIFF) and a < seg.t0 + 1 <= b:
                out.append(seg.t0 + 1)
        return out


class Counters:
    """The sixteen counters of a chip: register writes, PHS reads, pin outputs, the trace's counter edges."""

    def __init__(self, chip):
        self.chip = chip
        self.units = [(_Unit(), _Unit()) for _ in range(8)]
        self.history = PinHistory(chip)
        self.edges_recorded = 0
        self.warned = set()
        #: some counter has been in a feedback mode (pin waiters then also look one clock later)
        self.feedback_on = False

    # register access (from spinemu.chip.registers) -------------------------
    def write(self, c, which: int, v: int, t: int) -> None:
        """CTRA(0)/CTRB(1)/FRQA(2)/FRQB(3)/PHSA(4)/PHSB(5) of cog ``c`` := ``v`` at cycle ``t``."""
        unit = self.units[c.id][which & 1]
        old = unit.cur
        t = max(t, old.t0)
        new = _Counter()
        new.ctr, new.frq, new.mode, new.t0 = old.ctr, old.frq, old.mode, t
        kind = which >> 1
        if kind == 2:
            new.phs0 = new.acc0 = v
        elif t <= old.t0:                       # a second write in the same cycle
            new.phs0, new.acc0, new.known = old.phs0, old.acc0, old.known
        elif old.mode in _READS_PINS or not old.known:
            new.known = False                   # summed from the pin history when needed
        else:
            new.acc0 = old.acc(t)
            new.phs0 = new.acc0 & _M
        if kind == 0:
            new.ctr = v
            new.mode = (v >> 26) & 31
        elif kind == 1:
            new.frq = v
        if t <= old.t0 and len(unit.segs) > 1:
            new.index = old.index
            unit.segs[-1] = new
        else:
            new.index = len(unit.segs)
            unit.segs.append(new)
            unit.starts.append(t)
        unit.cur = new
        setattr(c, ("ctra", "ctrb", "frqa", "frqb", "phsa", "phsb")[which], v)
        mode = new.mode
        if mode in _OUTPUTS:
            self.chip.counters_on = True
            if mode in _FEEDBACK:
                self.feedback_on = True
                if new.apin == new.bpin and ("fb-loop", c.id) not in self.warned:
                    self.warned.add(("fb-loop", c.id))
                    self.chip.warnings.append(
                        f"cog {c.id} set counter mode %{mode:05b} ({MODE_NAMES[mode]}) with APIN = BPIN = "
                        f"P{new.apin}: the feedback output is computed from the pin without it, not as an oscillator")
        if self.chip._pin_waiters:
            self.chip._wake_pin_waiters(t)

    def phs(self, c, ab: int, t: int) -> int:
        """PHSA (``ab`` 0) or PHSB (1) of cog ``c`` as read at cycle ``t``.

        In an input mode this sums the pin history up to ``t``; the caller
        reads at the moment the instruction reads (every other cog has run
        up to it; see :meth:`reads_pins`).
        """
        unit = self.units[c.id][ab]
        seg = unit.cur
        if t < seg.t0:
            seg = unit.at(t)
        if seg.mode in _READS_PINS:
            return self._input_phs(unit, seg, t, True) & _M
        if not seg.known:
            self._settle(unit, seg)
        return seg.phs(t)

    def reads_pins(self, c) -> bool:
        """Whether a PHS read of cog ``c`` depends on pins (a counter in a detector or LOGIC mode).

        Engines that let a cog run ahead of the others must bring every
        other cog up to the reading cycle before such a read.
        """
        a, b = self.units[c.id]
        return a.cur.mode in _READS_PINS or b.cur.mode in _READS_PINS

    def segment_at(self, cog: int, ab: int, t: int) -> _Counter:
        """The stretch of counter ``ab`` (0 = A) of cog ``cog`` in force at cycle ``t``, its PHS settled."""
        unit = self.units[cog][ab]
        seg = unit.at(t)
        if not seg.known:
            self._settle(unit, seg)
        return seg

    # PHS in the input modes ------------------------------------------------------
    def _settle(self, unit: _Unit, seg: _Counter) -> None:
        """Work out ``seg.phs0`` from the stretches before it (they ended in an input mode)."""
        pending = []
        while not seg.known:
            pending.append(seg)
            seg = unit.segs[seg.index - 1]
        for nxt in reversed(pending):
            prev = unit.segs[nxt.index - 1]
            if prev.mode in _READS_PINS:
                value = self._input_phs(unit, prev, nxt.t0, False)
            else:
                value = prev.acc(nxt.t0)
            nxt.acc0, nxt.phs0, nxt.known, nxt.sig = value, value & _M, True, None

    def _input_phs(self, unit: _Unit, seg: _Counter, t: int, checkpoint: bool) -> int:
        if not seg.known:
            self._settle(unit, seg)
        if seg.frq == 0:
            return seg.phs0
        if t >= seg.ck_t > seg.t0:
            n = seg.ck_n + self.condition_count(seg, seg.ck_t, t)
        else:
            n = self.condition_count(seg, seg.t0, t)
        if checkpoint and t > seg.ck_t:
            seg.ck_t, seg.ck_n = t, n
        return seg.phs0 + seg.frq * n

    def condition_count(self, seg: _Counter, a: int, b: int) -> int:
        """Clocks ``u`` in ``(a, b]`` at which ``seg``'s mode condition held (on the pins at ``u - 1``, ``u - 2``)."""
        if b <= a:
            return 0
        mode = seg.mode
        hist = self.history
        if mode < 16:
            neg = mode & 4
            if not mode & 2:                        # POS / NEG: A1 (or !A1)
                high = sum((e - s) * sig if isinstance(sig, int) else sig.count(s, e)
                           for s, e, sig in hist.pieces(seg.apin, a - 1, b - 1))
                return (b - a) - high if neg else high
            # POSEDGE / NEGEDGE: A changed between u-2 and u-1
            pieces = hist.pieces(seg.apin, a - 2, b - 1)
            n = 0
            prev = None
            for s, e, sig in pieces:
                if prev is not None:
                    before = prev if isinstance(prev, int) else prev.at(s)
                    now = sig if isinstance(sig, int) else sig.at(s + 1)
                    if (now and not before) if not neg else (before and not now):
                        n += 1
                if not isinstance(sig, int):
                    n += sig.falling(s + 1, e) if neg else sig.rising(s + 1, e)
                prev = sig
            return n
        table = mode & 15
        if table in (0, 15):
            return 0 if table == 0 else b - a
        return self._logic_count(table, hist.pieces(seg.apin, a - 1, b - 1), hist.pieces(seg.bpin, a - 1, b - 1))

    @staticmethod
    def _logic_count(table: int, pa: list, pb: list) -> int:
        """Cycles at which ``table`` (bit A + 2B) holds, over two piece lists covering the same range."""
        n = 0
        i = j = 0
        s = pa[0][0]
        while i < len(pa) and j < len(pb):
            ea, sa = pa[i][1], pa[i][2]
            eb, sb = pb[j][1], pb[j][2]
            e = min(ea, eb)
            ca, cb = isinstance(sa, int), isinstance(sb, int)
            if ca and cb:
                n += e - s if (table >> (sa + 2 * sb)) & 1 else 0
            elif ca or cb:
                if cb:                              # A varies, B is constant: table as a function of A
                    p, g0, g1 = sa, (table >> (2 * sb)) & 1, (table >> (1 + 2 * sb)) & 1
                else:                               # B varies, A is constant
                    p, g0, g1 = sb, (table >> sa) & 1, (table >> (sa + 2)) & 1
                if g0 == g1:
                    n += e - s if g0 else 0
                else:
                    high = p.count(s, e)
                    n += high if g1 else (e - s) - high
            elif sa.same_phase(sb):
                n += sa.with_window(combine(sa.window, sb.window, sa.modulus, table)).count(s, e)
            else:
                pieces = enumerate_fn([[(s, e, sa)], [(s, e, sb)]], s, e,
                                      lambda lv: (table >> (lv[0] + 2 * lv[1])) & 1)
                n += sum(pe - ps for ps, pe, lv in pieces if lv)
            s = e
            if ea == e:
                i += 1
            if eb == e:
                j += 1
        return n

    # pins ------------------------------------------------------------------
    def outputs(self, c, t: int) -> int:
        """Pins cog ``c``'s counters drive high at ``t`` (before DIRA gating)."""
        return self.outputs_at(c.id, t, True)

    def outputs_at(self, cog: int, t: int, feedback: bool = True) -> int:
        """:meth:`outputs` by cog number, from the counters' history; ``feedback=False`` leaves feedback outputs out."""
        out = 0
        for unit in self.units[cog]:
            seg = unit.cur
            if t < seg.t0:
                seg = unit.at(t)
            mode = seg.mode
            if mode in _PHASE_OUT:
                if not seg.known:
                    self._settle(unit, seg)
                out |= seg.outputs(t)
            elif mode in _FEEDBACK and feedback and seg.bpin < 32:
                if not self.history.level(seg.apin, t - 1, False):
                    out |= 1 << seg.bpin
        return out

    def flush(self, c, t: int) -> None:
        """Kept for engines that call it before changing pins: counter outputs reach the trace and the
        pin listeners from the counters' history (:mod:`spinemu.chip.countermarks`), so there is nothing to do."""

    def next_edge(self, t: int, mask: int = 0xFFFFFFFF) -> int | None:
        """The first counter output change of any running cog after ``t`` on a pin it drives (for WAITPEQ/WAITPNE).

        ``mask``: only pins in it count (the pins the waiting cogs watch).
        """
        best = None
        for c in self.chip.cogs:
            if c.state == "stopped" or not c.dira & mask:
                continue
            for ab, unit in enumerate(self.units[c.id]):
                seg = self.segment_at(c.id, ab, t + 1)
                if not seg.output_mask() & c.dira & mask:
                    continue
                nxt = None
                if seg.index + 1 < len(unit.segs):
                    nxt = unit.segs[seg.index + 1].t0
                horizon = (nxt if nxt is not None else t + (1 << 40)) - t
                if seg.mode in _PHASE_OUT:
                    te = next(seg.edges(t, t + horizon), None)
                else:
                    te = self.history.next_change(seg.apin, t - 1, False, horizon)
                    te = te + 1 if te is not None else None
                for cand in (te, nxt):
                    if cand is not None and cand > t and (best is None or cand < best):
                        best = cand
        return best

    # PLL report ------------------------------------------------------------------
    def pll_outputs(self, end: int | None = None) -> list:
        """Every stretch of a run in which a counter was in a PLL mode with FRQ set, as :data:`PllOutput`.

        ``pins`` lists the pins the PLL drives (none for PLL internal, which
        only feeds the video generator; a pin is driven only while its DIRA
        bit is set); ``traced`` says whether its edges are in the trace.
        """
        clock = self.chip.clock_hz or 0
        out = []
        for cog in range(8):
            for ab, unit in enumerate(self.units[cog]):
                for i, seg in enumerate(unit.segs):
                    if seg.mode not in _PLL or not seg.frq:
                        continue
                    stop = unit.segs[i + 1].t0 if i + 1 < len(unit.segs) else end
                    pins = () if seg.mode == MODE_PLL_INTERNAL else tuple(
                        p for p in (seg.apin, seg.bpin if seg.mode == MODE_PLL_DIFF else None)
                        if p is not None and p < 32)
                    vco = 16 * seg.frq * clock / (1 << 32)
                    freq = vco / (1 << (7 - seg.plldiv))
                    traced = bool(pins) and seg.pll_period() >= PLL_TRACE_MIN_PERIOD
                    entry = PllOutput(cog, "AB"[ab], MODE_NAMES[seg.mode], pins, freq, vco, seg.t0, stop, traced)
                    if out and out[-1][:6] == entry[:6] and out[-1].end_cycle == entry.start_cycle:
                        out[-1] = out[-1]._replace(end_cycle=stop)
                    else:
                        out.append(entry)
        return out

    def end_warnings(self, end: int) -> list:
        """Warnings about the run's PLL outputs (faster than the trace shows, or a VCO that would not lock)."""
        msgs = []
        for p in self.pll_outputs(end):
            where = f"cog {p.cog} CTR{p.counter} ({p.mode}" + (
                f" on {', '.join(f'P{x}' for x in p.pins)}" if p.pins else "") + ")"
            if not 64e6 <= p.vco_hz <= 128e6:
                msgs.append(f"{where}: PLL VCO at {p.vco_hz / 1e6:.3f} MHz is outside 64-128 MHz, where the chip's "
                            f"PLL locks; modelled as an ideal {p.frequency_hz / 1e6:.6f} MHz output")
            if p.pins and not p.traced:
                msgs.append(f"{where}: PLL output at {p.frequency_hz / 1e6:.6f} MHz from cycle {p.start_cycle}; "
                            f"faster than the trace shows (period under {PLL_TRACE_MIN_PERIOD} clocks), "
                            "so the trace holds the pin low")
        return msgs
