"""Exact skipping of whole periods of a chip in a steady state.

A stepper driver ticking every millisecond while the main cog counts a pause
down, a PWM loop, a blinking LED: for seconds of simulated time the chip
repeats the same pattern, and every repeat costs the interpreter the same
work.  This module lets the chip skip such repeats without changing a single
result (pin trace, hub RAM, end cycle):

1. **Recording.**  When the chip has been calm for a while (the looks of
   the scheduler's progress hook over :data:`CALM` cycles found every running cog a Spin
   cog that mostly waits or a PASM cog parked in an idle loop (pasm_idle.py:
   it sleeps through the periods, and waking it ends a recording), and no
   other PASM cog, counter output, pin wait, parked busy loop, bench part or
   debugger in the way: :meth:`SteadySkip.eligible`),
   the chip runs on exactly as always, but through the interpreter's own
   handlers with logging hub views (as the busy-loop learner does,
   fastforward.py), wrapped as the chip's are (the runtime checks'
   uninitialized-local handlers, whose record of the locals each frame
   wrote must also come back to where it was).  Every bytecode is recorded with its cog, address, start
   cycle and the hub reads and writes it made, and each time the first cog
   that ran comes back to the bytecode address it started at (the *anchor*),
   the state of every cog is noted.
2. **Finding a period.**  Two stretches of ``n`` anchor intervals, one after
   the other, qualify as periods A and B when they are the same program: the
   same bytecodes of the same cogs at the same cycles relative to their
   start, the same hub addresses accessed, the cogs in the same state at the
   three anchors, the same pin changes, and a length ``P`` that is a multiple
   of 16 (the hub window).  Only the values read and written may differ.
3. **Proving it goes on.**  Take every value as changing by the same amount
   from period to period (``B - A``, modulo 2**32).  Each bytecode whose
   values differ must be one whose effect keeps that form, and it tells for
   how many periods its outcome stays the same: moves, additions,
   subtractions and negation keep it for ever (so do ``*`` and ``<<`` by a
   fixed operand, and ``x & mask``, ``x // c`` and ``x / c`` when ``x``
   moves by multiples of the mask's range or of ``c``, the last two while
   ``x`` keeps its sign); a comparison, a limit (``#>``, ``<#``), a conditional
   jump, a REPEAT step or a zero test keeps its answer until its operand
   crosses the boundary (:func:`~spinemu.chip.pasm_affine.first_change`);
   WAITCNT must wait as long every time (its target moves by ``P``); CNT
   reads must move by ``P``.  Anything else that sees a changing value (a
   product of two changing values, a right shift, an index, a pin write, a
   lock) ends the attempt.  A hub location first read in the period must change by what the
   period wrote to it, and nothing may read it at another size.  By induction
   every later period ``k`` is period A with every value moved by ``k`` times
   its change, for every ``k`` below the bound ``K`` of all the answers.
4. **Skipping.**  At the end of B (period 2 starts), periods 2 .. ``K - 1``
   are applied at once: every hub location the period writes moves by
   ``(K - 2)`` times its change, every cog's time by ``(K - 2) * P``, the pin
   changes of B are repeated at their times, and statistics count the skipped
   bytecodes as executed.  The chip then runs on normally; the period that
   changes an answer runs through the interpreter as usual.

A failed attempt costs its recording (real execution, only slower, some 30
times): recordings are capped (:data:`BUDGET_BYTECODES`,
:data:`BUDGET_INTERVAL`), all of them together may cost :data:`ALLOWANCE`
bytecodes, one per :data:`RATIO` the chip ran and one per :data:`PAYOFF`
their skips saved, and after one that found nothing worth skipping the chip
must be calm for :data:`CALM` cycles again.  A proof that holds but would
skip too little to pay (an inner loop found calm late in its life: its
count ends soon) gives the moment its state changes; no longer period can
pay before it.  The chip then runs on normally to just after that moment
and records once more, so that the same period, found at the start of the
next inner loop, pays; if that one is too short again (a loop of a few
iterations), the recording goes on past the change, where a period that
holds the whole loop can be found.
``Chip(steady_skip=False)`` turns this off (the old/new comparison in the
tests).
"""
from __future__ import annotations

from ..bytecode import TABLE
from . import mathops
from .cog import PARKED, RUNNING, STOPPED
from .control import Halted
from .fastforward import LoggedView, _TrackingChip, cog_state
from .pasm_affine import first_change as _first_change

__all__ = ["SteadySkip", "Reject", "analyse_periods", "LOOK_EVERY"]

N = 1 << 32
M = N - 1
SB = 1 << 31
INFINITE = 1 << 62

#: cycles between two looks (the scheduler's progress hook), plus a part of a million that changes
#: from look to look, so that the looks do not keep meeting a periodic program at one point of its period
LOOK_EVERY = 10_000_000
#: cycles over which every look must find the chip calm (every cog mostly waiting) before a recording
CALM = 24_000_000
#: cycles of normal running after a recording that found nothing worth it (and CALM looks again)
AFTER_FAILURE = 1 << 24
#: recordings may take this many bytecodes, and one per RATIO the chip ran (a recorded bytecode costs
#: some 30 run normally: this keeps looks that find nothing below some 15 % of the run's time)
ALLOWANCE, RATIO = 4096, 200
#: bytecodes and anchor visits one recording may take at most
BUDGET_BYTECODES = 4096
BUDGET_HITS = 192
#: ... and between two visits of the anchor (more: a cog has left the steady state for a busy loop)
BUDGET_INTERVAL = 512
#: cycles per bytecode since the last look above which a cog counts as mostly waiting
_SLEEPY = 320
#: a skip must save at least this many periods
MIN_SKIP = 2
#: cycles one skip goes at most (a state that lasts for ever, in a run without a cycle limit, is
#: skipped a stretch at a time, not 2**62 cycles of pin changes at once)
MAX_SKIP = 1 << 36
#: bytecodes a skip must save per bytecode recorded (else the recording looks on for a longer period,
#: and one that finds none makes the next look come later)
PAYOFF = 20

_STEADY, _BUDGET, _LOOK = "steady state found", "steady: recording budget spent", "steady: look"
_RETRY = "steady: record again when the state has changed"
#: cycles after the horizon of a proof that did not pay at which the next recording starts
RETRY_AFTER = 2_000

_NAMES = [e.handler for e in TABLE]
#: bytecodes a period may not contain at all (their effects are not in the hub log)
_FORBIDDEN = frozenset({"op_run", "op_waitpeq", "op_waitpne", "op_clkset", "op_cogstop", "op_lockret",
                        "op_waitvid", "op_coginit_result", "op_coginit", "op_locknew_result",
                        "op_locknew", "op_lockset_result", "op_lockclr_result", "op_lockset",
                        "op_lockclr", "op_unknown"})
#: bytecodes looked at even when no value they touch changes (they read the time or registers)
_TIMED = frozenset({"op_waitcnt", "op_push_spr", "op_pop_spr", "op_using_spr", "op_reg", "op_reg_bit",
                    "op_reg_range"})
_MOVES = frozenset({"op_frame_result", "op_frame", "op_frame_result_trap", "op_frame_trap", "op_jmp",
                    "op_call", "op_call_obj", "op_call_obj_x", "op_pop", "op_abort", "op_abort_value",
                    "op_return", "op_return_value", "op_push_mask", "op_push_imm1", "op_push_imm2",
                    "op_push_imm3", "op_push_imm4", "op_push_neg1", "op_push_0", "op_push_1"})
_AFFINE_BINARY = (mathops.add, mathops.sub)
_AFFINE_UNARY = (mathops.neg, mathops.bit_not)
_COMPARE = {mathops.cmp_lt: "lt", mathops.cmp_gt: "gt", mathops.cmp_le: "le", mathops.cmp_ge: "ge",
            mathops.cmp_eq: "eq", mathops.cmp_ne: "ne"}


class Reject(Exception):
    """The recorded periods do not prove that the chip goes on in the same way."""


def _changes(a: int, step: int, lo: int, hi: int) -> int:
    """Periods (from A) for which ``(a + step*k) mod 2**32`` stays in or out of ``[lo, hi)``."""
    lo, hi = max(lo, 0), min(hi, N)
    if lo >= hi or (lo == 0 and hi == N) or not step & M:
        return INFINITE
    return _first_change(a & M, step, lo, hi)


def _zero_test(v: int, d: int) -> int:
    return _changes(v, d, 0, 1)


def _signed_range(v: int, d: int, lo: int, hi: int) -> int:
    """Periods for which ``signed(v)`` stays in or out of ``[lo, hi]`` (bounds any integers)."""
    return _changes((v + SB) & M, d, lo + SB, hi + SB + 1)


def _compare(kind: str, x, y) -> int:
    """Periods for which a signed comparison ``x <kind> y`` keeps its answer: ``x``, ``y`` are
    ``(value in A, change)``."""
    (xa, dx), (ya, dy) = x, y
    if dx and dy:
        if kind in ("eq", "ne") and dx == dy:
            return INFINITE
        raise Reject("a comparison of two changing values")
    if kind in ("eq", "ne"):
        v, d, c = (xa, dx, ya) if dx else (ya, dy, xa)
        return _changes(v, d, c, c + 1)
    sy = ya - N if ya & SB else ya
    sx = xa - N if xa & SB else xa
    if dx:      # x changes, y fixed: x's side of y
        lo, hi = {"lt": (-SB, sy - 1), "le": (-SB, sy), "gt": (sy + 1, SB), "ge": (sy, SB)}[kind]
        return _signed_range(xa, dx, lo, hi)
    lo, hi = {"lt": (sx + 1, SB), "le": (sx, SB), "gt": (-SB, sx - 1), "ge": (-SB, sx)}[kind]
    return _signed_range(ya, dy, lo, hi)


# ---------------------------------------------------------------------------------------- rules
# A rule gets the bytecode (chip, op, pc, sp at its start), its reads and writes as
# [shift, index, value in A, value in B, change mod 2**32] and P; it returns the periods for which
# the bytecode keeps doing the same (INFINITE: for ever) or raises Reject.

def _narrow(reads) -> int:
    """A byte or word read whose value changes is a long on the stack only while it does not wrap."""
    k = INFINITE
    for s, _, va, _, d in reads:
        if d and s < 2:
            k = min(k, _changes(va, d, 0, 1 << (8 << s)))
    return k


def _fixed(entries, what: str) -> None:
    for e in entries:
        if e[4]:
            raise Reject(f"a changing value used as {what}")


def _moved(reads, writes) -> None:
    """Every changing value written is a value read (truncated to the written size)."""
    for s, _, wa, wb, d in writes:
        if not d:
            continue
        m = (1 << (8 << s)) - 1
        if not any((ra & m, rb & m) == (wa, wb) for _, _, ra, rb, rd in reads if rd):
            raise Reject("a changing value computed by a bytecode that only moves values")


def _rule_move(chip, op, pc, sp, reads, writes, P) -> int:
    _moved(reads, writes)
    return _narrow(reads)


def _mem_fields(chip, op, pc):
    """``(address reads, access)`` of a VAR/LOC or memory bytecode at ``pc``."""
    if _NAMES[op] == "op_var_long":
        return 0, op & 3
    base, indexed = (op >> 2) & 3, 1 if op & 0x10 else 0
    if base:
        n = (2 if chip.mem[(pc + 1) & 0xFFFF] & 0x80 else 1) + indexed
    else:
        n = 1 + indexed
    return n, op & 3


def _rule_memory(chip, op, pc, sp, reads, writes, P) -> int:
    n, access = _mem_fields(chip, op, pc)
    _fixed(reads[:n], "an address or index")
    if access != 2:
        _moved(reads[n:], writes)
        return _narrow(reads[n:])
    # an update: [assignment operator byte] [the variable] [operands of the operator]
    if len(reads) < n + 2 or not writes:
        raise Reject("an update not logged as expected")
    aop_entry, v, rest = reads[n], reads[n + 1], reads[n + 2:]
    _fixed([aop_entry], "an assignment operator")
    b = aop_entry[2] & 0x7F
    k = _narrow([v])
    if b == 0:                                      # WRITE: a move from the stack
        _moved(reads[n + 2:] + [v], writes)
        return min(k, _narrow(rest))
    if 0x20 <= b < 0x40 and not b & 1 or b in (0x18, 0x1C):
        _fixed(rest, "an update operand")           # ++ / -- (pre, post, sized), ~ / ~~
        return k
    if b & 0x40 and not b & 0x20:                   # x op= y: the operator on the variable and the stack
        f = b & 0x1F
        u = mathops.UNARY[f]
        if u is not None:
            if u not in _AFFINE_UNARY:
                raise Reject("a changing value in an update operator that does not keep its form")
            return k
        fn = mathops.BINARY[f]
        y = [e for e in rest if e[0] == 2][:1]
        if not y:
            raise Reject("an update operand not logged as expected")
        if len(set(chip.timing._math[f])) != 1 and not (fn in (mathops.div, mathops.mod) and not y[0][4]):
            raise Reject("a changing value in an operator whose time depends on it")
        return min(k, _narrow(rest), _binary(fn, v, y[0]))
    if b in (0x02, 0x06):                           # REPEAT var FROM .. TO .. [STEP]: its step
        stack = [e for e in rest if e[0] == 2]      # read as: to (top), from, [step]
        _fixed(rest, "a REPEAT bound or step")
        if len(stack) < (3 if b == 0x06 else 2):
            raise Reject("a REPEAT step not logged as expected")
        to, frm = stack[0][2], stack[1][2]
        to, frm = (to - N if to & SB else to), (frm - N if frm & SB else frm)
        step = 1
        if b == 0x06:
            step = stack[2][2]
            step = step - N if step & SB else step
        lo, hi = (frm - step, to - step) if frm <= to else (to + step, frm + step)
        return min(k, _signed_range(v[2], v[4], lo, hi))
    raise Reject("a changing value in an update operator that does not keep its form")


def _rule_math(chip, op, pc, sp, reads, writes, P) -> int:
    f = op & 0x1F
    u = mathops.UNARY[f]
    fn = mathops.BINARY[f]
    if len(set(chip.timing._math[f])) != 1 and not (fn in (mathops.div, mathops.mod) and not reads[1][4]):
        raise Reject("a changing value in an operator whose time depends on it")   # (DIV/MOD: the divisor)
    if u is not None:
        if u in _AFFINE_UNARY:
            return INFINITE
        if u is mathops.log_not:
            return _zero_test(reads[0][2], reads[0][4])
        raise Reject("a changing value in an operator that does not keep its form")
    return _binary(fn, reads[0], reads[1])


def _binary(fn, x, y) -> int:
    """Periods for which binary operator ``fn`` on ``x``, ``y`` (read entries) keeps its form."""
    if fn in _AFFINE_BINARY:
        return INFINITE
    if fn is mathops.mul or fn is mathops.shl:  # by a fixed factor or shift: (x + k*d) * c
        if y[4] and (fn is mathops.shl or x[4]):
            raise Reject("a changing value multiplied by a changing one")
        return INFINITE
    if fn is mathops.bit_and:           # x & mask: bits below the mask's top stay if x moves by multiples
        v, m = (y, x) if x[4] == 0 else (x, y)
        if m[4] or v[4] % (1 << m[2].bit_length()):
            raise Reject("a changing value masked")
        return INFINITE
    if fn is mathops.div or fn is mathops.mod:
        c = y[2]                        # x / c, x // c: x moving by multiples of c (the sign kept)
        d = x[4] - N if x[4] & SB else x[4]
        if y[4] or not 0 < c < SB or d % c:
            raise Reject("a changing value divided")
        return _changes(x[2], x[4], 0, SB)
    if fn is mathops.limit_min or fn is mathops.limit_max:    # #> and <#: x or y, while x's side of y stays
        return _compare("ge" if fn is mathops.limit_min else "le", (x[2], x[4]), (y[2], y[4]))
    kind = _COMPARE.get(fn)
    if kind is not None:
        return _compare(kind, (x[2], x[4]), (y[2], y[4]))
    if fn is mathops.log_and or fn is mathops.log_or:
        return min(_zero_test(x[2], x[4]), _zero_test(y[2], y[4]))
    raise Reject("a changing value in an operator that does not keep its form")


def _rule_jump(chip, op, pc, sp, reads, writes, P) -> int:
    code = [e for e in reads if e[0] == 0]
    _fixed(code, "a jump offset")
    v = [e for e in reads if e[0] == 2]
    if len(v) != 1:
        raise Reject("a jump not logged as expected")
    s, i, va, vb, d = v[0]
    if _NAMES[op] == "op_djnz":
        return _changes(va, d, 1, 2)
    return _zero_test(va, d)


def _rule_waitcnt(chip, op, pc, sp, reads, writes, P) -> int:
    if len(reads) != 1 or reads[0][4] != P & M:
        raise Reject("a WAITCNT whose wait changes")
    return INFINITE


def _register(chip, op, pc, reads):
    """``(register, access)`` of a register bytecode (access 0 read, 1 write, 2 update)."""
    name = _NAMES[op]
    if name in ("op_push_spr", "op_pop_spr", "op_using_spr"):
        idx = [e for e in reads if e[0] == 2]
        if not idx:
            raise Reject("a register bytecode not logged as expected")
        _fixed(idx[:1], "a register number")
        return 0x1F0 + (idx[0][2] & 0xF), {"op_push_spr": 0, "op_pop_spr": 1, "op_using_spr": 2}[name]
    b = chip.mem[(pc + 1) & 0xFFFF]
    return 0x1E0 + (b & 0x1F), (b >> 5) & 3


def _rule_register(chip, op, pc, sp, reads, writes, P) -> int:
    r, access = _register(chip, op, pc, reads)
    if access and r >= 0x1F8:
        raise Reject("a counter or video register written")
    if r == 0x1F1:                                  # CNT: a full read moves by P, nothing else is followed
        if access or _NAMES[op] not in ("op_push_spr", "op_reg") or len(writes) != 1:
            raise Reject("CNT used other than read whole")
        _fixed(reads[1:] if _NAMES[op] == "op_push_spr" else reads, "a CNT operand")
        if writes[0][4] != P & M:
            raise Reject("a CNT read that does not move with the period")
        return INFINITE
    _fixed(reads, "a register value")
    _fixed(writes, "a register value")
    return INFINITE


_RULES = {"op_var_long": _rule_memory, "op_mem": _rule_memory, "op_math": _rule_math,
          "op_jz": _rule_jump, "op_jnz": _rule_jump, "op_tjz": _rule_jump, "op_djnz": _rule_jump,
          "op_waitcnt": _rule_waitcnt, "op_push_spr": _rule_register, "op_pop_spr": _rule_register,
          "op_using_spr": _rule_register, "op_reg": _rule_register, "op_reg_bit": _rule_register,
          "op_reg_range": _rule_register}
for _name in _MOVES:
    _RULES[_name] = _rule_move
del _name


def analyse_periods(chip, rows_a, rows_b, log, P: int):
    """Check two recorded periods (see the module docstring); returns ``(K, writes)``.

    ``rows_a``, ``rows_b``: per bytecode ``(cog, pc, op, t, sp, log start, log end)``.
    ``K``: periods from A on that provably repeat A with every value moved.
    ``writes``: ``{(shift, index): (value at the end of B, change per period)}``.
    Raises :class:`Reject` when they prove nothing.
    """
    K = INFINITE
    changing: set = set()
    # 1. every bytecode whose values differ (most do not: their logs are equal) keeps its form
    for ra, rb in zip(rows_a, rows_b):
        op = ra[2]
        name = _NAMES[op]
        if name in _FORBIDDEN:
            raise Reject(f"the period contains {name[3:]}")
        la, lb = log[ra[5]:ra[6]], log[rb[5]:rb[6]]
        if la == lb and name not in _TIMED:
            continue
        reads, writes = [], []
        varies = False
        for x, y in zip(la, lb):
            wr, s, i = x[0], x[1], x[2]
            if y[2] != i or y[1] != s or y[0] != wr:
                raise Reject("the periods access different addresses")
            va, vb = (x[4], y[4]) if wr else (x[3], y[3])
            d = (vb - va) & M
            if d:
                varies = True
                changing.add((s, i))
            (writes if wr else reads).append((s, i, va, vb, d))
        if varies or name in _TIMED:
            rule = _RULES.get(name)
            if rule is None:
                raise Reject(f"a changing value in {name[3:]}")
            K = min(K, rule(chip, op, ra[1], ra[4], reads, writes, P))
            if K <= MIN_SKIP:
                raise Reject("an answer changes at once")
    # 2. the hub longs that hold changing values: accessed at one size only; a value read first
    # changes as the period writes it (one only read does not change)
    watched = {(i << s) >> 2 for s, i in changing}
    first: dict = {}            # (shift, index) -> (a read?, its change)
    last: dict = {}             # (shift, index) -> (value written last in B, change)
    sizes: dict = {}
    for ra, rb in zip(rows_a, rows_b):
        for x, y in zip(log[ra[5]:ra[6]], log[rb[5]:rb[6]]):
            s, i = x[1], x[2]
            if (i << s) >> 2 not in watched:
                continue
            key = (s, i)
            sizes.setdefault((i << s) >> 2, set()).add(key)
            m = (1 << (8 << s)) - 1
            if x[0]:
                d = (y[4] - x[4]) & m
                last[key] = (y[4], d)
            else:
                d = (y[3] - x[3]) & m
            if key not in first:
                first[key] = (not x[0], d)
    for keys in sizes.values():
        if len(keys) > 1:
            raise Reject("a changing value accessed at two sizes")
    for key, (was_read, d) in first.items():
        if was_read:
            w = last.get(key)
            if (w[1] if w is not None else 0) != d:
                raise Reject("a value read does not change as the period writes it")
    return K, last


class _RecordingChip(_TrackingChip):
    """The chip as the recording handlers see it: hub accesses (without the learner's checks for cogs
    running ahead: none runs ahead while a period is recorded) and deferred write-backs are logged."""

    def _view(self, view, shift: int, log: list):
        return LoggedView(view, shift, log)

    def defer_write(self, writer, size, hub_addr, value, t, key, preempt=True):
        self.mem_longs.log.append((1, size, hub_addr >> size, None, value))
        self._chip.defer_write(writer, size, hub_addr, value, t, key, preempt)


class _Recorder:
    """The record of a recording (SteadySkip._record fills it) and the search for the period."""

    def __init__(self, steady, log):
        self.steady, self.log = steady, log
        self.rows: list = []
        # per anchor visit: (row index, t, cog states, pin events so far, every cog's time)
        self.hits: list = []
        self.sigs: list = []        # per anchor interval: its structure (made when first compared)
        self.anchor = None
        self.tried: set = set()
        self.by_snap: dict = {}     # cog states -> the visits (indices into hits) in them
        #: the first change a proof that did not pay found: a longer period can only do better if it
        #: holds that change (the end of an inner loop), so no proof is tried before it
        self.horizon = 0

    def _hit(self, chip, c):
        rows, hits = self.rows, self.hits
        t = c.t
        snap = _snapshot(chip)
        if hits:
            self.sigs.append(None)
        hits.append((len(rows), t, snap, len(chip.pin_events), _times(chip)))
        j = len(hits) - 1
        if snap is None or j < 2 or t < self.horizon:     # (before the horizon no proof can pay: below)
            return
        same = self.by_snap.setdefault(snap, set())    # the earlier visits in this state
        same.add(j)
        tried = self.tried
        for n in range(1, j // 2 + 1):
            if n in tried or j - n not in same or j - 2 * n not in same:
                continue
            P = t - hits[j - n][1]
            if P != hits[j - n][1] - hits[j - 2 * n][1] or P % 16 or P <= 0:
                continue
            roles = _roles(hits[j - 2 * n], hits[j - n], hits[j])
            if roles is None or not self._same_intervals(j - 2 * n, j - n, n):
                continue
            if self.steady.try_skip(chip, self, j, n, P, roles):
                raise Halted(_STEADY)
            tried.add(n)            # (once per length: a failed proof costs more than a missed skip)

    def _sig(self, k: int) -> tuple:
        """The structure of anchor interval ``k``: per bytecode its cog, address, opcode, time from the
        interval's start and number of hub accesses."""
        sig = self.sigs[k]
        if sig is None:
            (start, t0), end = self.hits[k][:2], self.hits[k + 1][0]
            sig = self.sigs[k] = tuple((r[0], r[1], r[2], r[3] - t0, r[6] - r[5]) for r in self.rows[start:end])
        return sig

    def _same_intervals(self, a: int, b: int, n: int) -> bool:
        """Do the ``n`` intervals from ``a`` on have the structure of the ``n`` from ``b`` on?"""
        sig = self._sig
        for i in range(n):
            if sig(a + i) != sig(b + i):
                return False
        return True


def _idle_pasm(k) -> bool:
    """Is cog ``k`` a PASM cog parked in an idle loop (pasm_idle.py)?  It sleeps until its horizon (its
    scheduler key) or until what it reads changes, which ends a recording (it wakes)."""
    return k.state == PARKED and k.engine.__class__ is not str and k.busy is not None


def _asleep_only_idle_pasm(chip) -> bool:
    """Are the chip's parked loops and pin waits all of PASM cogs in idle loops (none of Spin cogs)?"""
    return all(_idle_pasm(k) for k in chip._parked) and all(_idle_pasm(k) for k in chip._pin_waiters)


def _snapshot(chip):
    """Every cog's state (its time apart: :func:`_times`), or None where no period may start."""
    if chip._pend or chip._ahead:
        return None
    out = []
    for k in chip.cogs:
        if k.state == STOPPED:
            out.append((STOPPED, k.dira, k.outa))
        elif _idle_pasm(k):
            out.append((PARKED, id(k.busy), k.key, k.dira, k.outa))
        elif k.state != RUNNING or k.engine.__class__ is not str:
            return None
        else:
            out.append((cog_state(k), k.outb, k.dirb))
    wlog, checks = chip.warning_log, chip.checks
    return (tuple(out), tuple(chip.locks), wlog.total if wlog is not None else 0,
            checks.frames_state() if checks is not None else ())


def _times(chip) -> tuple:
    """Every running cog's time (None for the others)."""
    return tuple(k.t if k.state == RUNNING else None for k in chip.cogs)


def _roles(h0, h1, h2):
    """How each cog's time went over three visits of the anchor: ``(moving, asleep)`` cog ids, or None.

    A cog that takes part in the period is at the same time relative to the
    anchor each time (``moving``: it moves on by ``P`` per period); one that
    sleeps through both periods (a slow loop's long WAITCNT) is at the same
    absolute time (``asleep``: it stays where it is, and the skip must end
    before it wakes).
    """
    moving, asleep = [], []
    for i, (a, b, c) in enumerate(zip(h0[4], h1[4], h2[4])):
        if a is None:
            continue
        if a - h0[1] == b - h1[1] == c - h2[1]:
            moving.append(i)
        elif a == b == c:
            asleep.append(i)
        else:
            return None
    return tuple(moving), tuple(asleep)


class SteadySkip:
    """Looks for steady states in a chip's run and skips their periods (the module docstring)."""

    def __init__(self, chip):
        self.chip = chip
        self.next_look = 0
        self.calm = None            # since when every look found the chip calm
        self.recorded = 0           # bytecodes recorded so far
        self.looks = 0
        self._seen = [(0, 0)] * 8     # per cog: bytecodes and cycle at the last look
        self.handlers = None
        self._wraps = 0             # ... wrapped as the chip's handlers were then (Chip.wrap_handler)
        self.log: list = []
        self.periods = 0            # periods skipped
        self.skips = 0
        self.attempts = 0
        self.saved = 0              # bytecodes the latest skip saved
        self.woken = False          # did it end where a cog sleeping through its periods wakes?
        self.wake_at = INFINITE     # ... and when that cog's turn comes
        self.skipped = 0            # ... and all skips
        self.retry_at = 0           # when to record again after a proof that did not pay (_RETRY)
        self.retrying = False       # ... and whether this recording is that second one
        self.retries = 0
        self._ff_seen = 0           # the busy-loop skipper's count at the last look

    def eligible(self, rate: bool = True) -> bool:
        chip = self.chip
        if (chip.probe is not None or chip.recorder is not None or chip._pend or chip.counters_on
                or chip.pin_listeners or chip._preempt or chip._halt_reason is not None):
            return False
        # (parked busy loops and pin waits only of PASM cogs in idle loops: they sleep through it)
        if not _asleep_only_idle_pasm(chip):
            return False
        if any(rewrap is None for _, rewrap in chip._wraps):  # (a tool's wrapper the recording cannot copy)
            return False
        checks = chip.checks
        for f in chip.pin_hooks:
            if checks is None or f != checks.on_pins:
                return False
        for f in chip.write_hooks:
            if checks is None or f != checks.on_watched_write:
                return False
        if chip.inputs.next_change(chip.now) is not None:
            return False
        # every running cog mostly waiting since the last look: a steady state paced by the clock
        # (one with a busy loop in it would cost its recording more than a skip saves)
        if chip._ff_skipped != self._ff_seen:   # a busy loop was skipped since the last look: not calm
            self._ff_seen = chip._ff_skipped
            return False
        seen = self._seen               # (by each cog's own clock: a cog running ahead is past ``now``)
        self._seen = [(c.bytecodes, c.t) for c in chip.cogs]
        running = False
        for c in chip.cogs:
            if c.state == STOPPED or _idle_pasm(c):
                continue
            if c.state != RUNNING or c.engine.__class__ is not str:
                return False
            running = True
            b0, t0 = seen[c.id]
            if rate and c.bytecodes - b0 > (c.t - t0) // _SLEEPY:
                return False
        return running

    def advance(self, limit: int, progress) -> str:
        """``Chip._schedule(limit, progress)``, looking for steady states on the way.

        The scheduler calls its progress hook between two cogs' turns every
        ten million cycles; there, when the chip may be in a steady state
        (:meth:`eligible`), the hook stops the scheduler for an attempt.
        """
        chip = self.chip

        def look(t: int) -> None:
            if progress is not None:
                progress(t)
            self.looks += 1             # the next look a varying fraction of a million cycles later
            every = LOOK_EVERY + (self.looks * 618_034) % 1_000_000
            if self.woken and t < self.wake_at:     # ... or just after a sleeper's turn that ended a skip
                every = min(every, self.wake_at - t + 100_000)
            if chip._pend or chip._preempt:     # a write-back on its way: this moment is no good, the
                chip.progress_every = min(every, 4_000)     # state may still be (a look soon will tell)
                return
            chip.progress_every = every
            if not self.eligible():
                self.calm = None
                return
            if self.calm is None:
                self.calm = t
            # (recordings may cost a small part of what the chip ran, and as much more as the skips
            # they found have paid back)
            if t - self.calm >= CALM and t >= self.next_look and self.recorded <= \
                    ALLOWANCE + sum(c.bytecodes for c in chip.cogs) // RATIO + self.skipped // PAYOFF:
                raise Halted(_LOOK)

        while True:
            chip._cogs_changed = True           # (each call of the scheduler lists the cogs anew)
            try:
                return chip._schedule(limit, look)
            except Halted as h:
                if h.reason != _LOOK:
                    raise
            reason = self._attempt(limit)
            if reason is not None:
                return reason

    def _attempt(self, limit: int):
        """Record until a period is found and skipped or the budget is spent; a run's end reason
        if the run ended meanwhile, else None."""
        chip = self.chip
        self.attempts += 1
        for c in list(chip._ahead):         # a cog that ran ahead (ahead.py) goes back to the present
            chip._rollback(c, chip.now, 8)
        if self.handlers is None or self._wraps != len(chip._wraps):
            from .spin import build_handlers
            # (wrapped as the chip's handlers are: the runtime checks see the recorded bytecodes too)
            self.handlers = chip.wrap_copy(build_handlers(_RecordingChip(chip, self.log), chip.timing))
            self._wraps = len(chip._wraps)
        self.retrying = False
        while True:
            rec, reason = self._recording(limit)
            if reason != _RETRY:
                break
            # a proof did not pay: the state changes at its horizon (an inner loop ends).  Run on to
            # just after it, as the scheduler does, and record again: found early, the period pays
            self.retries += 1
            self.retrying = True
            reason = chip._schedule(min(self.retry_at + RETRY_AFTER, limit), None)
            if chip.now >= limit or reason != "cycle limit":
                return reason
            if not self.eligible(rate=False):
                reason = _BUDGET
                break
        if reason == _STEADY and self.saved >= PAYOFF * len(rec.rows):
            if self.woken:              # the sleeper's turn comes next, then the same state goes on
                self.next_look = self.wake_at
            else:                       # it ended where an answer changes: the state changes there
                self.next_look = chip.now
                self.calm = None
            return None
        if reason in (_STEADY, _BUDGET):        # nothing found, or too little to pay for the recording
            self.next_look = chip.now + AFTER_FAILURE
            self.calm = None
            return None
        return reason

    def _recording(self, limit: int):
        """One recording with the recording handlers in place: ``(recorder, reason)``."""
        chip = self.chip
        log = self.log
        log.clear()
        rec = _Recorder(self, log)
        real = chip._handlers
        chip.handlers[:] = self.handlers
        chip._handlers = self.handlers
        try:
            try:
                reason = self._record(rec, limit)
            except Halted as h:
                reason = h.reason
        finally:
            chip._handlers = real
            chip.handlers[:] = real
            chip._cogs_changed = True
            log.clear()
        self.recorded += len(rec.rows)
        return rec, reason

    def _record(self, rec: "_Recorder", limit: int):
        """Run the chip one bytecode at a time in the scheduler's exact order, recording each.

        The scheduler's own loop (Scheduler._schedule) for the states a
        recording starts from: Spin cogs only, none parked, ahead or waiting
        on pins, no pin listeners or input changes.  It returns None (the
        scheduler goes on) as soon as anything else comes up, at the cycle
        limit, or when every cog has stopped; "reboot" as the scheduler
        would; a recorder's Halted ends it too.
        """
        from .control import CogStopped, RebootRequested, Reschedule
        chip = self.chip
        cogs, mem, acc, wide = chip.cogs, chip.mem, chip.access_at, chip.access_wide
        rows, log, hits = rec.rows, rec.log, rec.hits
        H = chip.handlers
        anchor = anchor_pc = None
        stop = min(BUDGET_BYTECODES, BUDGET_INTERVAL + 1)     # (before the first visit of the anchor)
        running: list = []
        sleeper = INFINITE
        chip._cogs_changed = True
        chip.run_limit = limit
        while True:
            if chip._cogs_changed:
                chip._cogs_changed = False
                running = [k for k in cogs if k.state == RUNNING]
                if any(k.engine.__class__ is not str for k in running) \
                        or any(k.running and k.state != RUNNING and not _idle_pasm(k) for k in cogs) \
                        or not _asleep_only_idle_pasm(chip):
                    return None
                # a PASM cog in an idle loop: its horizon is its next event (the scheduler's to run)
                sleeper = min((chip._key(k) for k in cogs if _idle_pasm(k)), default=INFINITE)
            c = None
            ck = 0
            for k in running:
                pc = k.pc
                op = mem[pc]
                key = k.t + 12
                key += ((k.hub_phase - key) & 15) + acc[op] + (wide[op] & (mem[(pc + 1) & 0xFFFF] >> 3))
                if c is None or key < ck:
                    c, ck = k, key
            pa = chip._pend_at
            if pa < limit and (c is None or pa < ck or pa == ck and chip._pend_id < c.id):
                chip._apply_pending()
                continue
            if c is None or ck >= limit or ck >= sleeper:
                return None
            pc = c.pc
            t = c.t
            chip.now = t
            if pc == anchor_pc and c is anchor:
                rec._hit(chip, c)
                # the budget: bytecodes in all, anchor visits, bytecodes until the next visit
                stop = 0 if len(hits) >= BUDGET_HITS else min(BUDGET_BYTECODES, len(rows) + BUDGET_INTERVAL + 1)
            elif anchor is None:
                anchor, anchor_pc = c, pc
                rec.anchor = (c.id, pc)
            if len(rows) >= stop:
                raise Halted(_BUDGET)
            op = mem[pc]
            row = [c.id, pc, op, t, c.sp, len(log), 0]
            rows.append(row)
            # the bytecode, as Scheduler._run_spin runs it with the limit just past its access
            tf = t + 12
            tf += (c.hub_phase - tf) & 15
            chip.rmw_limit = ck + 1
            c.pc = pc + 1
            try:
                t = tf + H[op](c, op, t)
            except Reschedule as e:
                t = tf + e.rest
            except CogStopped:
                c.bytecodes += 1
                row[6] = len(log)
                continue
            except RebootRequested:
                c.bytecodes += 1
                c.t = tf
                chip._reboot_key = tf + chip.access_offset(pc)
                chip.now = c.t
                chip._pend.clear()
                chip._pend_at = 1 << 62
                return "reboot"
            except IndexError:
                raise chip.fault(c, pc, "stack or address out of hub range") from None
            c.bytecodes += 1
            if c.state == RUNNING:
                c.t = t
            if chip._preempt:                   # (a write-back waits: the handlers come back)
                chip._end_preemption()
            row[6] = len(log)

    def try_skip(self, chip, rec: _Recorder, j: int, n: int, P: int, roles) -> bool:
        """Periods A = anchor intervals [j-2n, j-n), B = [j-n, j) qualify: skip if they prove enough."""
        hits, rows = rec.hits, rec.rows
        a0, a1, b1 = hits[j - 2 * n][0], hits[j - n][0], hits[j][0]
        ev = chip.pin_events
        pa, pb, pc = hits[j - 2 * n][3], hits[j - n][3], hits[j][3]
        ta, tb = hits[j - 2 * n][1], hits[j - n][1]
        events_a = [(e[0] - ta,) + e[2:] for e in ev[pa:pb]]
        events_b = [(e[0] - tb,) + e[2:] for e in ev[pb:pc]]
        if events_a != events_b:
            return False
        try:
            K, writes = analyse_periods(chip, rows[a0:a1], rows[a1:b1], rec.log, P)
        except Reject:
            return False
        t_now = hits[j][1]
        moving, asleep = roles
        room = (chip.run_limit - t_now) // P - 2 if chip.run_limit < INFINITE else INFINITE
        wake = INFINITE
        self.wake_at = INFINITE
        sleepers = list(asleep) + [k.id for k in chip.cogs if _idle_pasm(k)]
        for i in sleepers:                      # the skip ends two periods before a sleeper wakes
            self.wake_at = min(self.wake_at, chip._key(chip.cogs[i]))
            wake = min(wake, (self.wake_at - t_now) // P - 2)
        skip = min(K - 2, room, wake, MAX_SKIP // P)
        if skip < MIN_SKIP or skip * (b1 - a1) < PAYOFF * len(rows) and skip < room:
            # too little.  The state changes at the horizon (an inner loop ends).  Found early, the
            # same period would pay: record again just after it; if this is that new recording, a
            # longer period holding the change may do (a short inner loop), so record on past it
            horizon = t_now + (max(skip, 0) + 2) * P
            if not self.retrying and not chip._parked:  # (running on to a moment unparks idle PASM cogs)
                self.retry_at = horizon
                raise Halted(_RETRY)
            rec.horizon = max(rec.horizon, horizon)
            return False
        self.woken = skip == wake               # (the same state goes on after the sleeper's turn)
        self._apply(chip, skip, P, writes, rows[a1:b1], ev[pb:pc], moving)
        return True

    def _apply(self, chip, m: int, P: int, writes, rows_b, events_b, moving) -> None:
        """Advance the chip by ``m`` periods of ``P`` cycles (it is at the end of period B); the cogs
        ``moving`` take part in the period, the others sleep through it."""
        views = (chip.mem, chip.mem_words, chip.mem_longs)
        for (s, i), (v, d) in writes.items():
            if d:
                views[s][i] = (v + m * d) & ((1 << (8 << s)) - 1)
        per_cog = [0] * 8
        for r in rows_b:
            per_cog[r[0]] += 1
        for i in moving:
            c = chip.cogs[i]
            c.t += m * P
            c.bytecodes += m * per_cog[i]
        for k in range(1, m + 1):               # period B's pin changes, a period later each time
            off = k * P
            for e in events_b:
                chip._seq += 1
                chip.pin_events.append((e[0] + off, chip._seq) + e[2:])
        for e in events_b:                  # the cogs' latest pin changes, as other cogs see them
            c = chip.cogs[e[2]]
            c.pin_hist.append((e[0] + m * P, e[3], e[4], e[5]))
            if len(c.pin_hist) > 8:
                del c.pin_hist[:4]
        chip.now += m * P
        self.periods += m
        self.skips += 1
        self.saved = m * len(rows_b)
        self.skipped += self.saved
