"""Shared helpers for the chip tests (imported as ``chip_helpers``): data paths, trace comparison.

Traces are compared by :mod:`spinemu.analysis.compare` (the rules of the
reference comparison tool): same sequence of pin states, timing error per
change ``max(0, |t_cand - t_ref| - slack) / t_ref`` after the first millisecond.
"""
from __future__ import annotations

import os

from spinemu.analysis.compare import compare_traces, state_changes
from spinemu.trace import PinTrace, read_log

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARTICLE = os.path.join(ROOT, "tests", "data", "article")
PROGRAMS = os.path.join(ROOT, "tests", "data", "chip", "programs")


def read_bytes(path: str) -> bytes:
    with open(path, "rb") as f:
        return f.read()


def trace_states(changes, until=None):
    """``(cycle, dir, out)`` changes without repeats and without the idle start state."""
    return state_changes(PinTrace(80_000_000, list(changes)), until)


def read_trace(path: str):
    with open(path) as f:
        return read_log(f.read()).changes


def compare(ref, cand, slack=16_000):
    """``(same_sequence, worst_error, largest_offset)`` by spinemu.analysis.compare's rules."""
    r = compare_traces(PinTrace(80_000_000, list(ref)), PinTrace(80_000_000, list(cand)), slack=slack)
    return r.identical, r.worst_error, r.largest_offset


def article_image(name: str) -> bytes:
    return read_bytes(os.path.join(ARTICLE, name + ".binary"))


def make_image(code: bytes, *, var_longs: int = 8, locals_bytes: int = 0, clkfreq: int = 80_000_000,
               dat: bytes = b"", methods=()) -> bytes:
    """A one-object image whose first method is ``code`` (for bytecode unit tests).

    ``dat`` is placed right after the object table (OBJ-relative offset 8
    for one method); the code follows it.  ``methods`` adds more methods
    after the first, as ``(code, locals_bytes)`` (method 2, 3, ...).
    """
    from spinemu.image import image_checksum
    dat = dat + bytes(-len(dat) % 4)
    all_methods = [(code, locals_bytes)] + list(methods)
    table = 4 + 4 * len(all_methods)
    offsets = []
    body = dat
    for m_code, _ in all_methods:
        offsets.append(table + len(body))
        body += m_code
    size = table + len(body)
    size += -size % 4
    obj = size.to_bytes(2, "little") + bytes([len(all_methods) + 1, 0])
    for off, (_, loc) in zip(offsets, all_methods):
        obj += off.to_bytes(2, "little") + loc.to_bytes(2, "little")
    obj += body
    obj += bytes(size - len(obj))
    pbase = 0x10
    vbase = pbase + size
    dbase = vbase + 4 * var_longs + 8
    dcurr = dbase + 4 + locals_bytes
    header = bytearray(clkfreq.to_bytes(4, "little") + bytes([0x6F, 0])
                       + b"".join(v.to_bytes(2, "little") for v in (pbase, vbase, dbase, pbase + offsets[0], dcurr)))
    img = bytearray(header + obj)
    img[5] = image_checksum(bytes(img))
    return bytes(img)


def pasm_mismatches(recorded, ours) -> list:
    """Where our PASM instructions differ from spinsim's recorded ones, one line each.

    ``recorded``: ``[first cycle, address, long, executed, value or None, Z or None,
    C or None]`` per instruction (``None``: spinsim's log does not show it);
    ``ours``: the :class:`spinemu.chip.pasm_cog.PasmStep` records of the same cog.
    """
    bad = []
    for k, want in enumerate(recorded):
        if k >= len(ours):
            bad.append(f"step {k}: spinsim ran {want}, spinemu ran no more")
            break
        s = ours[k]
        got = [s.cycle, s.pc, s.word, s.executed, s.result, s.z, s.c]
        if any(w is not None and w != g for w, g in zip(want, got)):
            bad.append(f"step {k}: spinsim {want}, spinemu {got} ({s.text().strip()})")
    return bad
