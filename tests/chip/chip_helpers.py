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


def make_image(code: bytes, *, var_longs: int = 8, locals_bytes: int = 0, clkfreq: int = 80_000_000,
               dat: bytes = b"") -> bytes:
    """A one-object, one-method image whose method is ``code`` (for bytecode unit tests).

    ``dat`` is placed right after the object table (OBJ-relative offset 8);
    the code follows it.
    """
    from spinemu.image import image_checksum
    dat = dat + bytes(-len(dat) % 4)
    code_off = 8 + len(dat)
    body = dat + code
    size = 8 + len(body)
    size += -size % 4
    obj = (size.to_bytes(2, "little") + bytes([2, 0]) + code_off.to_bytes(2, "little")
           + locals_bytes.to_bytes(2, "little") + body)
    obj += bytes(size - len(obj))
    pbase = 0x10
    vbase = pbase + size
    dbase = vbase + 4 * var_longs + 8
    dcurr = dbase + 4 + locals_bytes
    header = bytearray(clkfreq.to_bytes(4, "little") + bytes([0x6F, 0])
                       + b"".join(v.to_bytes(2, "little") for v in (pbase, vbase, dbase, pbase + code_off, dcurr)))
    img = bytearray(header + obj)
    img[5] = image_checksum(bytes(img))
    return bytes(img)
