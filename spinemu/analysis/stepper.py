"""Stepper-motor coil patterns in pin traces: steps, direction, speed, and
a side-by-side comparison of two traces (e.g. the BS2 original of the
column's demo against its Spin translation).

Both chip models record the same :class:`~spinemu.trace.PinTrace`; this
module only reads traces.  Four pins drive the four coil phases; a
*pattern* is the 4-bit value ``bit i = level of pins[i]`` (the table
``%0011, %0110, %1100, %1001`` of both programs, printed with pins[3] on
the left).  Patterns are placed on the 8 positions of the half-step cycle::

    0001 0011 0010 0110 0100 1100 1000 1001
     0    1    2    3    4    5    6    7

so one move of +2 positions is a forward full step (two-coil ``0011 ->
0110`` or wave ``0001 -> 0010``), +1 a forward half step, negative numbers
go backward; 4 (opposite pattern) or a pattern off the cycle (``0000``,
``0101``...) is not a step (``delta`` None: energising, stalls, glitches).
Drive tables recognised: full-step two-coil, wave, half-step.

Typical use (pins: BS2 P4..P7 are Propeller P1..P4 in the column)::

    a = decode_steps(bs2_trace, [4, 5, 6, 7])
    b = decode_steps(spin_trace, [1, 2, 3, 4])
    print(compare_step_sequences(a, b, names=("BS2", "Spin")).render())
"""
from __future__ import annotations

import re
import statistics
from dataclasses import dataclass, field
from typing import Optional, Sequence

from ..bench.stepper_motor import PHASE, StepperMotor, coil_delta
from ..trace import PinTrace

__all__ = ["PHASE", "Step", "Segment", "StepSequence", "StepComparison", "decode_steps",
           "decode_step_dir", "compare_step_sequences", "compare_stepper_traces", "parse_pins",
           "pattern_text", "render_steps"]
_TWO_COIL = {0b0011, 0b0110, 0b1100, 0b1001}
_ONE_COIL = {0b0001, 0b0010, 0b0100, 0b1000}


def pattern_text(p: Optional[int], width: int = 4) -> str:
    """``0b0110`` -> ``"0110"`` (pins[3] first); None -> ``"----"`` (a coil pin undriven)."""
    return "-" * width if p is None else format(p, f"0{width}b")


def parse_pins(text: str) -> list[int]:
    """Coil pins in coil order: ``"P4..P7"``, ``"4..7"``, ``"4-7"``, ``"1,2,3,4"``, ``"P7..P4"``.

    >>> parse_pins("P4..P7"), parse_pins("1,2,3,4"), parse_pins("p7-p4")
    ([4, 5, 6, 7], [1, 2, 3, 4], [7, 6, 5, 4])
    """
    from .view import parse_pins as _view_parse_pins
    spec = re.sub(r"(?i)p(?=\d)", "", text)
    spec = re.sub(r"(?<=\d)\s*-\s*(?=\d)", "..", spec)
    return _view_parse_pins(spec)


@dataclass(frozen=True)
class Step:
    """One change of the coil pattern.

    Attributes:
        index: 0-based position in the sequence.
        cycle: when it happened, in trace cycles.
        time: the same in seconds.
        pattern: the new pattern.
        previous: the pattern before (None: coils were not all driven).
        delta: half-steps moved (+2 = one forward full step), None if not a step;
            a step/dir pulse moves +2 or -2 (one step of the driver).
        interval: seconds since the previous step (None for the first).
        label: how to show ``pattern`` (step/dir: ``"DIR=1"``); None: the coil pattern's bits.
    """

    index: int
    cycle: int
    time: float
    pattern: int
    previous: Optional[int]
    delta: Optional[int]
    interval: Optional[float]
    label: Optional[str] = None

    @property
    def direction(self) -> Optional[int]:
        if self.delta is None:
            return None
        return (self.delta > 0) - (self.delta < 0)

    @property
    def text(self) -> str:
        return self.label if self.label is not None else pattern_text(self.pattern)


@dataclass(frozen=True)
class Segment:
    """Consecutive steps in one direction at one speed.

    ``period`` is the median time between steps inside the segment (the
    gap before its first step, e.g. a PAUSE, is not part of it).
    """

    first: int
    last: int
    direction: Optional[int]
    period: Optional[float]
    start: float
    end: float

    @property
    def count(self) -> int:
        return self.last - self.first + 1

    @property
    def speed(self) -> Optional[float]:
        """Steps per second."""
        return 1.0 / self.period if self.period else None

    @property
    def direction_text(self) -> str:
        return {1: "forward", -1: "reverse", 0: "hold", None: "irregular"}[self.direction]

    def describe(self) -> str:
        """One line (under 80 characters) for reports."""
        rng = f"{self.first + 1}-{self.last + 1}"
        per = (f"{self.period * 1e3:7.3f} ms/step {self.speed:6.1f}/s" if self.period
               else "  single step        ")
        return (f"{rng:>9} {self.direction_text:<9}{self.count:4d} steps {per}  "
                f"{self.start:7.3f}-{self.end:.3f} s")


@dataclass
class StepSequence:
    """The steps found on four coil pins (``kind="coils"``) or a step/dir pin pair
    (``kind="step/dir"``, ``pins = (step, dir)``) of one trace."""

    pins: tuple
    clock_hz: int
    steps: list = field(default_factory=list)
    initial: Optional[int] = None
    tolerance: float = 0.1
    kind: str = "coils"

    def __len__(self) -> int:
        return len(self.steps)

    @property
    def patterns(self) -> list[int]:
        return [s.pattern for s in self.steps]

    @property
    def mode(self) -> str:
        """``"full-step (two-coil)"``, ``"wave"``, ``"half-step"``, ``"irregular"`` or ``"none"``."""
        used = {s.pattern for s in self.steps if s.pattern or self.kind != "coils"}   # 0000: coils off
        deltas = {abs(s.delta) for s in self.steps if s.delta is not None}
        if not used:
            return "none"
        if self.kind == "step/dir":
            return "step/dir"
        if used <= _TWO_COIL and deltas <= {2}:
            return "full-step (two-coil)"
        if used <= _ONE_COIL and deltas <= {2}:
            return "wave"
        if used <= set(PHASE) and deltas <= {1}:
            return "half-step"
        return "irregular"

    @property
    def net_half_steps(self) -> int:
        return sum(s.delta or 0 for s in self.steps)

    def holds(self) -> list[Optional[float]]:
        """How long each step's pattern was held before the next step (s); None for the last."""
        st = self.steps
        return [st[i + 1].time - st[i].time for i in range(len(st) - 1)] + ([None] if st else [])

    def segments(self) -> list[Segment]:
        """Split the steps into runs of one direction and one speed.

        A step's speed is how long it is held before the next step (both
        programs write the pattern, then pause).  A new segment starts when
        the direction changes, after a pause (a hold more than twice the
        previous one) and when the hold differs from the segment's first by
        more than ``tolerance`` (relative).  A step of unknown direction (the
        first one, energising the coils) joins the segment that follows.
        """
        st = self.steps
        holds = self.holds()
        dirs = [s.direction for s in st]
        # the direction of a step of unknown direction: that of the next known one
        for i in range(len(st) - 1, -1, -1):
            if dirs[i] is None and i + 1 < len(st):
                dirs[i] = dirs[i + 1]
        segs: list[Segment] = []
        first = 0
        base: Optional[float] = None
        periods: list[float] = []

        def close(last: int) -> None:
            period = statistics.median(periods) if periods else None
            segs.append(Segment(first, last, dirs[first], period, st[first].time, st[last].time))

        for i in range(len(st)):
            h = holds[i]
            run_ends = i + 1 >= len(st) or dirs[i + 1] != dirs[i]
            pause = bool(h is not None and periods and h > 2 * periods[-1])
            if h is not None and not run_ends and not pause:
                if base is None:
                    base = h
                elif abs(h - base) > self.tolerance * base:
                    close(i - 1)
                    first, base, periods = i, h, []
                periods.append(h)
            if run_ends or pause or i + 1 >= len(st):
                close(i)
                first, base, periods = i + 1, None, []
        return segs

    def summary(self, name: str = "trace", max_segments: Optional[int] = None) -> str:
        """Steps, net movement and the segments (the first ``max_segments`` of them)."""
        if self.kind == "step/dir":
            pins = f"P{self.pins[0]} (step), P{self.pins[1]} (dir)"
            net = f"net {self.net_half_steps // 2:+d} steps"
        else:
            pins = ",".join(f"P{p}" for p in self.pins)
            net = f"net {self.net_half_steps / 2:+g} full steps"
        lines = [f"{name}: {len(self.steps)} steps on {pins} ({self.mode}), {net}"]
        segs = self.segments()
        shown = segs if max_segments is None else segs[:max_segments]
        lines += ["  " + seg.describe() for seg in shown]
        if len(shown) < len(segs):
            lines.append(f"  ... {len(segs) - len(shown)} more segments")
        return "\n".join(lines)


def decode_steps(trace: PinTrace, pins: Sequence[int], *, min_dwell: float = 0.0,
                 start: float = 0.0, end: Optional[float] = None,
                 tolerance: float = 0.1) -> StepSequence:
    """Find the coil-pattern changes of four pins in a trace.

    Args:
        trace: a pin trace (any clock).
        pins: the four coil pins in coil order (pattern bit i = pins[i]).
        min_dwell: drop patterns held for less than this many seconds
            (intermediate states when pins are switched one at a time).
        start, end: only look at this time window (seconds).
        tolerance: relative change of step interval that starts a new segment.

    Returns:
        StepSequence: the steps; ``initial`` is the pattern before the first step.
    """
    pins = tuple(pins)
    if len(pins) != 4:
        raise ValueError("a stepper needs four coil pins")
    hz = trace.clock_hz
    lo = int(round(start * hz))
    hi = None if end is None else int(round(end * hz))
    coil_mask = sum(1 << p for p in pins)
    states: list[tuple[int, Optional[int]]] = []
    for cycle, d, o in trace.changes:
        if hi is not None and cycle > hi:
            break
        if (d & coil_mask) != coil_mask:
            pat = None
        else:
            pat = sum(((o >> p) & 1) << i for i, p in enumerate(pins))
        if states and states[-1][1] == pat:
            continue
        if states and states[-1][0] == cycle:
            states[-1] = (cycle, pat)        # several writes at the same instant
            if len(states) > 1 and states[-2][1] == pat:
                states.pop()
            continue
        states.append((cycle, pat))
    if min_dwell > 0:
        keep = []
        for i, (c, p) in enumerate(states):
            nxt = states[i + 1][0] if i + 1 < len(states) else None
            if nxt is not None and (nxt - c) / hz < min_dwell:
                continue
            if keep and keep[-1][1] == p:
                continue
            keep.append((c, p))
        states = keep
    seq = StepSequence(pins, hz, tolerance=tolerance)
    prev: Optional[int] = None
    prev_t: Optional[float] = None
    for c, p in states:
        if c < lo:
            prev = p
            continue
        if p is None:
            prev = None
            continue
        if prev is None and not seq.steps and p not in PHASE:
            seq.initial = p
            prev = p
            continue
        t = c / hz
        delta = coil_delta(prev, p)
        if not seq.steps:
            seq.initial = prev
        seq.steps.append(Step(len(seq.steps), c, t, p, prev, delta,
                              None if prev_t is None else t - prev_t))
        prev, prev_t = p, t
    return seq


def decode_step_dir(trace: PinTrace, step_pin: int, dir_pin: int, *, start: float = 0.0,
                    end: Optional[float] = None, tolerance: float = 0.1,
                    min_pulse: float = 1e-6) -> StepSequence:
    """Find the steps of a step/direction driver in a trace.

    A step is a high pulse on ``step_pin`` at least ``min_pulse`` seconds wide,
    forward when ``dir_pin`` is high at its rising edge; the pulses are found by
    the bench's motor model (:class:`~spinemu.bench.stepper_motor.StepperMotor`).
    Each step is recorded with ``delta`` +2 or -2 (one step) and ``pattern`` the
    DIR level, so :meth:`StepSequence.segments` and :func:`render_steps` work as
    for coils.

    Args:
        trace: a pin trace (any clock).
        step_pin, dir_pin: the driver's STEP and DIR inputs.
        start, end: only steps in this time window (seconds).
        tolerance: relative change of step interval that starts a new segment.
        min_pulse: narrower STEP pulses are not steps.
    """
    motion = StepperMotor(step=step_pin, dir=dir_pin, clock_hz=trace.clock_hz,
                          min_pulse=min_pulse, dir_setup=0.0).feed(trace.changes, trace.end_cycle)
    seq = StepSequence((step_pin, dir_pin), trace.clock_hz, tolerance=tolerance, kind="step/dir")
    prev_t: Optional[float] = None
    prev_dir: Optional[int] = None
    for m in motion.steps:
        if m.time < start or (end is not None and m.time > end):
            continue
        level = 1 if m.delta > 0 else 0
        seq.steps.append(Step(len(seq.steps), m.cycle, m.time, level, prev_dir, 2 if m.delta > 0 else -2,
                              None if prev_t is None else m.time - prev_t, label=f"DIR={level}"))
        prev_t, prev_dir = m.time, level
    return seq


@dataclass
class StepComparison:
    """Two step sequences side by side.

    Attributes:
        a, b: the sequences; names: how to call them.
        compared: how many leading steps were compared.
        first_difference: index of the first step whose pattern differs
            (None if all compared steps agree).
        agree: the compared steps have the same patterns (and count).
    """

    a: StepSequence
    b: StepSequence
    names: tuple
    compared: int
    first_difference: Optional[int]
    agree: bool

    @property
    def same_sequence(self) -> bool:
        """Alias of :attr:`agree` (the CLI's exit status)."""
        return self.agree

    @property
    def common_steps(self) -> int:
        """Leading steps with the same pattern in both."""
        return self.compared if self.first_difference is None else self.first_difference

    def timing(self, first: int = 0, last: Optional[int] = None) -> Optional[tuple[float, float]]:
        """Median step interval (s) of A and B over steps ``first..last`` (inner intervals)."""
        last = self.common_steps - 1 if last is None else last
        ia = [s.interval for s in self.a.steps[first + 1:last + 1] if s.interval is not None]
        ib = [s.interval for s in self.b.steps[first + 1:last + 1] if s.interval is not None]
        if not ia or not ib:
            return None
        return statistics.median(ia), statistics.median(ib)

    def render(self) -> str:
        na, nb = self.names
        out = [self.a.summary(na), self.b.summary(nb), ""]
        n = self.common_steps
        if self.agree:
            out.append(f"coil patterns agree for all {self.compared} compared steps")
        else:
            out.append(f"coil patterns agree for the first {n} steps")
        if self.first_difference is not None:
            i = self.first_difference
            sa = self.a.steps[i] if i < len(self.a.steps) else None
            sb = self.b.steps[i] if i < len(self.b.steps) else None
            out.append(f"first difference at step {i + 1}: " + "; ".join(
                f"{nm} {_step_text(s)}" for nm, s in ((na, sa), (nb, sb))))
        elif len(self.a.steps) != len(self.b.steps):
            out.append(f"step counts differ: {na} {len(self.a.steps)}, {nb} {len(self.b.steps)}")
        out.append("")
        out.append("segment by segment (same step numbers):")
        sb_list = self.b.segments()
        for sa in self.a.segments():
            if sa.first >= n:
                break
            for sg in sb_list:
                if sg.last < sa.first or sg.first > min(sa.last, n - 1):
                    continue
                lo, hi = max(sa.first, sg.first), min(sa.last, sg.last, n - 1)
                ratio = (sa.period / sg.period) if sa.period and sg.period else None
                out.append(f"  steps {lo + 1}-{hi + 1} {sa.direction_text}: "
                           f"{na} {_ms(sa.period)} vs {nb} {_ms(sg.period)}"
                           + (f"  ({na}/{nb} = {ratio:.3f})" if ratio else ""))
        for nm, seq in ((na, self.a), (nb, self.b)):
            if n < len(seq.steps):
                tail = [sg for sg in seq.segments() if sg.last >= n]
                out.append(f"  after step {n}, {nm} goes on:")
                out += [f"    {sg.direction_text} {sg.count} steps at {_ms(sg.period)}"
                        for sg in tail[:6]]
                if len(tail) > 6:
                    out.append(f"    ... {len(tail) - 6} more segments")
        return "\n".join(out)


def _ms(period: Optional[float]) -> str:
    return f"{period * 1e3:.3f} ms/step" if period else "-"


def _step_text(s: Optional[Step]) -> str:
    if s is None:
        return "(no step)"
    d = {1: "forward", -1: "reverse", None: "?", 0: "?"}[s.direction]
    return f"{s.text} {d} at {s.time:.4f} s"


def compare_step_sequences(a, b, c=None, d=None, *, steps: Optional[int] = None,
                           names: tuple = ("A", "B"), min_dwell: float = 0.0) -> StepComparison:
    """Compare the coil-pattern sequences of two step sequences.

    Call it with two :class:`StepSequence` (from :func:`decode_steps`), or
    with ``(trace_a, pins_a, trace_b, pins_b)`` to decode both first.

    Args:
        a, b: the sequences (any clocks; times are in seconds).
        steps: compare only the first ``steps`` steps (e.g. 48 for one
            revolution); default: the length of the shorter sequence.
        names: labels for the report.
        min_dwell: with traces, passed to :func:`decode_steps`.

    Returns:
        StepComparison with ``agree``, ``first_difference`` and :meth:`~StepComparison.render`.
    """
    if isinstance(a, PinTrace):
        a, b = (decode_steps(a, b, min_dwell=min_dwell), decode_steps(c, d, min_dwell=min_dwell))
    n = min(len(a.steps), len(b.steps))
    if steps is not None:
        n = min(n, steps)
    first = None
    for i in range(n):
        if a.steps[i].pattern != b.steps[i].pattern:
            first = i
            break
    if first is None and steps is not None and min(len(a.steps), len(b.steps)) < steps:
        first = min(len(a.steps), len(b.steps))
    agree = first is None
    return StepComparison(a, b, tuple(names), n, first, agree)


def render_steps(seq: StepSequence, clock_hz: Optional[int] = None, limit: int = 20,
                 max_segments: Optional[int] = None) -> str:
    """The segment summary (the first ``max_segments``) and a step table (the first ``limit`` steps), as text.

    ``clock_hz`` is accepted for symmetry with other renderers; the cycles
    shown are those of the decoded trace.
    """
    lines = [seq.summary("steps", max_segments), "", " step       cycle        time  pattern  move   interval"]
    for s in seq.steps[:limit]:
        move = {None: "   ?", 2: "  +1", -2: "  -1", 1: "+1/2", -1: "-1/2", 0: "   0"}.get(s.delta, "   ?")
        iv = f"{s.interval * 1e3:8.3f} ms" if s.interval is not None else "          -"
        lines.append(f"{s.index + 1:5d} {s.cycle:11d} "
                     f"{s.time:10.6f} s   {s.text}   {move}  {iv}")
    if len(seq.steps) > limit:
        lines.append(f"  ... {len(seq.steps) - limit} more steps")
    return "\n".join(lines)


def compare_stepper_traces(trace_a: PinTrace, pins_a: Sequence[int], trace_b: PinTrace,
                   pins_b: Sequence[int], *, steps: Optional[int] = None,
                   names: tuple = ("A", "B"), min_dwell: float = 0.0) -> StepComparison:
    """Decode both traces and compare them (pins map coil i of A to coil i of B)."""
    return compare_step_sequences(decode_steps(trace_a, pins_a, min_dwell=min_dwell),
                                  decode_steps(trace_b, pins_b, min_dwell=min_dwell),
                                  steps=steps, names=names)
