"""Shared helpers for the chip tests (imported as ``chip_helpers``): data paths, a trace comparison.

The comparison re-implements the rules of the team's compare_traces.py (tests
never read /work/shared): same sequence of pin states, timing error per change
``max(0, |t_cand - t_ref| - slack) / t_ref`` for changes after 80_000 cycles.
"""
from __future__ import annotations

import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARTICLE = os.path.join(ROOT, "tests", "data", "article")
PROGRAMS = os.path.join(ROOT, "tests", "data", "chip", "programs")


def read_bytes(path: str) -> bytes:
    with open(path, "rb") as f:
        return f.read()


def trace_states(changes, until=None):
    """``(cycle, dir, out)`` changes without repeats and without the idle start state."""
    out = []
    for c, d, o in changes:
        if until is not None and c > until:
            break
        if out and (d, o) == out[-1][1:]:
            continue
        if not out and (d, o) == (0, 0):
            continue
        out.append((c, d, o))
    return out


def read_trace(path: str):
    with open(path) as f:
        return [(int(a), int(b, 16), int(c, 16)) for a, b, c in (line.split() for line in f if line.strip())]


def compare(ref, cand, slack=16_000):
    """``(same_sequence, worst_error, largest_offset)`` as compare_traces.py computes them."""
    n = min(len(ref), len(cand))
    first_diff = next((i for i in range(n) if ref[i][1:] != cand[i][1:]), None)
    same = first_diff is None and len(ref) == len(cand)
    worst = 0.0
    largest = 0
    for i in range(n if first_diff is None else first_diff):
        tr, tc = ref[i][0], cand[i][0]
        largest = max(largest, abs(tc - tr))
        if tr > 80_000:
            worst = max(worst, max(0, abs(tc - tr) - slack) / tr)
    return same, worst, largest


def article_image(name: str) -> bytes:
    return read_bytes(os.path.join(ARTICLE, name + ".binary"))
