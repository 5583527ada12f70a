"""Compare two pin traces: same sequence of pin states? how far apart in time?

This is the measure the project is judged by (the same one as the reference
tools): two traces agree when they go through the same sequence of pin
states; the timing error of a matched change is::

    max(0, |t_candidate - t_reference| - slack) / t_reference

counted only for changes after the first millisecond.  The slack (default
16,000 cycles, 200 us at 80 MHz) absorbs fixed start-up offsets such as the
~8,000 clocks the chip spends loading a cog that a simulator may skip.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from ..trace import PinTrace

__all__ = ["TraceComparison", "compare_traces", "state_changes"]


def state_changes(trace: PinTrace, until: Optional[int] = None) -> list[tuple[int, int, int]]:
    """The trace's changes of state, dropping repeats and the idle start state.

    Args:
        trace: the trace.
        until: ignore changes after this cycle.
    """
    out: list[tuple[int, int, int]] = []
    for c, d, o in trace.changes:
        if until is not None and c > until:
            break
        if out and (d, o) == out[-1][1:]:
            continue
        if not out and (d, o) == (0, 0):
            continue
        out.append((c, d, o))
    return out


@dataclass
class TraceComparison:
    """The result of :func:`compare_traces`.

    Attributes:
        reference_changes, candidate_changes: how many state changes each has.
        first_difference: index of the first change whose state differs
            (``None`` if the common prefix agrees).
        identical: same states in the same order, same count.
        worst_error, median_error: timing errors as fractions (0.005 = 0.5 %).
        largest_offset: largest |t_candidate - t_reference| in cycles.
        matched: changes whose timing was compared.
        tolerance: the worst error allowed for :attr:`passed`.
    """

    reference_changes: int
    candidate_changes: int
    first_difference: Optional[int]
    identical: bool
    worst_error: float
    median_error: float
    largest_offset: int
    matched: int
    slack: int
    tolerance: float
    reference_state: Optional[tuple[int, int, int]] = None
    candidate_state: Optional[tuple[int, int, int]] = None

    @property
    def passed(self) -> bool:
        return self.identical and self.worst_error <= self.tolerance

    def render(self) -> str:
        """Report lines in the same words as the reference comparison tool."""
        lines = [f"reference changes: {self.reference_changes}  candidate changes: {self.candidate_changes}"]
        if self.identical:
            lines.append("state sequence: identical")
        elif self.first_difference is None:
            n = min(self.reference_changes, self.candidate_changes)
            how = "stops early" if self.candidate_changes < self.reference_changes else "goes on"
            lines.append(f"state sequence: candidate {how} after {n} matching changes")
        else:
            r, c = self.reference_state, self.candidate_state
            lines.append(
                f"state sequence: first difference at change #{self.first_difference}: "
                f"reference cycle {r[0]} dir {r[1]:08x} out {r[2]:08x} / "
                f"candidate cycle {c[0]} dir {c[1]:08x} out {c[2]:08x}")
        lines.append(
            f"timing error over {self.matched} matched changes: median {self.median_error:.5%}  "
            f"worst {self.worst_error:.5%}  (largest offset {self.largest_offset} cycles, slack {self.slack})")
        verdict = "PASS" if self.passed else "FAIL"
        lines.append(f"{verdict}: sequence {'identical' if self.identical else 'differs'}, "
                     f"worst timing error {self.worst_error:.4%} (tolerance {self.tolerance:.3%})")
        return "\n".join(lines)


def compare_traces(reference: PinTrace, candidate: PinTrace, *, until: Optional[int] = None,
                   slack: int = 16_000, tolerance: float = 0.005,
                   settle_cycles: Optional[int] = None) -> TraceComparison:
    """Compare ``candidate`` with ``reference`` state by state.

    Args:
        reference, candidate: the two traces (same time base).
        until: ignore changes after this cycle.
        slack: cycles of fixed offset forgiven.
        tolerance: worst timing error allowed to pass.
        settle_cycles: changes before this cycle are not timed (default: 1 ms
            of the reference's clock).

    >>> ref = PinTrace(80_000_000, [(0, 0, 0), (100_000, 1, 1), (200_000, 1, 0)])
    >>> cand = PinTrace(80_000_000, [(0, 0, 0), (100_100, 1, 1), (200_050, 1, 0)])
    >>> compare_traces(ref, cand, slack=0).worst_error
    0.001
    """
    settle = reference.clock_hz // 1000 if settle_cycles is None else settle_cycles
    ref = state_changes(reference, until)
    cand = state_changes(candidate, until)
    n = min(len(ref), len(cand))
    first = next((i for i in range(n) if ref[i][1:] != cand[i][1:]), None)
    errors = []
    worst_abs = 0
    for i in range(n if first is None else first):
        t_r, t_c = ref[i][0], cand[i][0]
        worst_abs = max(worst_abs, abs(t_c - t_r))
        if t_r > settle:
            errors.append(max(0, abs(t_c - t_r) - slack) / t_r)
    errors.sort()
    return TraceComparison(
        reference_changes=len(ref), candidate_changes=len(cand), first_difference=first,
        identical=first is None and len(ref) == len(cand),
        worst_error=errors[-1] if errors else 0.0,
        median_error=errors[len(errors) // 2] if errors else 0.0,
        largest_offset=worst_abs, matched=len(errors), slack=slack, tolerance=tolerance,
        reference_state=ref[first] if first is not None else None,
        candidate_state=cand[first] if first is not None else None)
