"""Run a program with and without running ahead and say what differs (imported as ``schedule_compare``).

``Chip(run_ahead=False)`` is the exact hand-over: every hub access in cycle
order.  Running ahead (the default) must change nothing a run produces: pin
trace, hub RAM, end cycle and reason, bytecodes per cog, cog events, or the
fault's message, runtime warnings (kind, cog, place, cycle, count).
"""
from __future__ import annotations

from spinemu.chip import Chip
from spinemu.compiler import compile_source

from multicog_programs import program


def outcome(image: bytes, run_ahead: bool, cycles, compat: str = "spinsim", **kw):
    """Everything one run produces (or the fault it ended with); ``kw`` go to :class:`Chip`."""
    return run_outcome(Chip(image, compat=compat, run_ahead=run_ahead, **kw), cycles)


def run_outcome(chip: Chip, cycles) -> object:
    """Everything the run of ``chip`` for ``cycles`` produces (a dict), or the fault it ended with
    (a ``(type name, message)`` tuple)."""
    try:
        r = chip.run(max_cycles=cycles)
    except Exception as e:          # a fault must be the same fault
        return (type(e).__name__, str(e))
    return {"trace": r.trace.changes, "hub": r.hub, "end_cycle": r.end_cycle, "reason": r.reason,
            "bytecodes": r.stats["bytecodes_per_cog"], "cog_events": r.cog_events,
            "pasm": r.stats.get("pasm_instructions_per_cog"),
            "warnings": [(w.kind, w.cog, w.addr, w.cycle, w.count) for w in r.runtime_warnings]}


def differences(image: bytes, cycles, compat: str = "spinsim") -> list:
    """What differs between the exact hand-over and running ahead (empty: nothing)."""
    want = outcome(image, False, cycles, compat)
    got = outcome(image, True, cycles, compat)
    if got == want:
        return []
    if isinstance(want, tuple) or isinstance(got, tuple):
        return [f"exact: {want if isinstance(want, tuple) else want['reason']}, "
                f"ahead: {got if isinstance(got, tuple) else got['reason']}"]
    out = []
    for k in want:
        if got[k] != want[k]:
            if k == "hub":
                first = next(i for i in range(len(want[k])) if want[k][i] != got[k][i])
                out.append(f"hub differs first at ${first:04X}")
            elif k in ("trace", "cog_events"):
                n = next((i for i, (a, b) in enumerate(zip(want[k], got[k])) if a != b),
                         min(len(want[k]), len(got[k])))
                out.append(f"{k} differs at entry {n}: exact {want[k][n:n + 1]}, ahead {got[k][n:n + 1]}")
            else:
                out.append(f"{k}: exact {want[k]!r}, ahead {got[k]!r}")
    return out


#: cycles a generated program runs (many never end)
GENERATED_CYCLES = 4_000_000


def generated_image(seed: int) -> bytes:
    return compile_source(program(seed), f"multicog_{seed}.spin").binary


def generated_differences(seed: int, cycles: int = GENERATED_CYCLES) -> list:
    """:func:`differences` of generated multi-cog program ``seed``."""
    return differences(generated_image(seed), cycles)
