"""Translation differential: generated Spin programs on the bytecode engine and on the Python engine.

For each seed the generator's program runs on both engines (compat mode
``spinsim``); they agree when the pin traces are identical (every change at
the same cycle), the end cycle is the same, and hub RAM is identical outside
the cogs' stacks (VAR, DAT, code, free RAM: tests/translate/crosscheck.py).
A program that faults must fault on both engines with the same message; a
construct the translator does not handle (``TranslateError``) is counted
apart.

Reproduce a seed (prints the program and the first disagreement)::

    python -m tests.fuzz.translation --seed 17

Run a campaign (seeds ``start .. start + count - 1``)::

    python -m tests.fuzz.translation --start 0 --count 10000 --jobs 2
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
from dataclasses import dataclass

from spinemu import translate
from spinemu.diagnostics import EmulationError, SpinError
from spinemu.translate import TranslateError
from tests.fuzz.order_programs import program as order_program
from tests.translate.crosscheck import crosscheck, run_bytecode

#: chip cycles a generated program may run (they end long before)
MAX_CYCLES = 20_000_000

GENERATORS = {"order": order_program}


@dataclass
class Outcome:
    """What one program did: ``kind`` is ``agree``, ``differ``, ``untranslated`` or ``invalid``."""

    seed: int
    kind: str
    detail: str = ""


def compare(path: str, max_cycles: int = MAX_CYCLES) -> str:
    """Run the Spin program at ``path`` on both engines; "" when they agree, else the first difference.

    Raises:
        TranslateError: the translator does not handle the program.
        SpinError: the program does not compile.
    """
    try:
        bytecode_run = run_bytecode(path, max_cycles)
    except EmulationError as fault:
        try:
            translate.run_translated(path, max_cycles=max_cycles)
        except EmulationError as other:
            if fault.message.split(":")[0] == other.message.split(":")[0]:
                return ""
            return f"both fault, differently: {fault.message} / {other.message}"
        return f"the bytecode engine faults ({fault.message}), the Python engine does not"
    result = crosscheck(path, max_cycles, bytecode_run=bytecode_run)
    b, p = result.bytecode, result.python
    if b.trace.changes != p.trace.changes:
        for k, (x, y) in enumerate(zip(b.trace.changes, p.trace.changes)):
            if x != y:
                return f"pin change {k}: bytecode {x}, Python {y}"
        return f"pin changes: bytecode {len(b.trace.changes)}, Python {len(p.trace.changes)}"
    if b.end_cycle != p.end_cycle:
        return f"end cycle: bytecode {b.end_cycle}, Python {p.end_cycle}"
    if result.hub_differences:
        vbase = b.hub[8] | b.hub[9] << 8
        shown = []
        for a, x, y in result.hub_differences[:6]:
            where = f"VAR+{a - vbase}" if a >= vbase else f"${a:04X}"
            shown.append(f"{where}: {x} vs {y}")
        return f"hub RAM differs at {len(result.hub_differences)} bytes (bytecode vs Python): {', '.join(shown)}"
    return ""


def run_seed(seed: int, generator: str = "order", keep_dir: str = None) -> Outcome:
    """Generate program ``seed`` and compare the engines on it."""
    src = GENERATORS[generator](seed)
    folder = keep_dir or tempfile.mkdtemp(prefix="spinemu-fuzz-")
    path = os.path.join(folder, f"fuzz_{seed}.spin")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(src)
    try:
        detail = compare(path)
    except TranslateError as exc:
        return Outcome(seed, "untranslated", str(exc).splitlines()[0])
    except SpinError as exc:
        return Outcome(seed, "invalid", str(exc).splitlines()[0])
    finally:
        if keep_dir is None:
            os.remove(path)
            os.rmdir(folder)
    return Outcome(seed, "differ" if detail else "agree", detail)


def _run(args) -> Outcome:
    seed, generator = args
    try:
        return run_seed(seed, generator)
    except Exception as exc:  # noqa: BLE001 - a crash of either engine is a finding too
        return Outcome(seed, "differ", f"{type(exc).__name__}: {exc}")


def campaign(start: int, count: int, generator: str = "order", jobs: int = 1, out=sys.stdout) -> dict:
    """Run seeds ``start .. start + count - 1``; the outcomes by kind."""
    seeds = [(s, generator) for s in range(start, start + count)]
    by_kind: dict = {}
    if jobs > 1:
        import multiprocessing
        with multiprocessing.Pool(jobs) as pool:
            results = pool.imap(_run, seeds, chunksize=4)
            by_kind = _collect(results, out)
    else:
        by_kind = _collect(map(_run, seeds), out)
    return by_kind


def _collect(results, out) -> dict:
    by_kind: dict = {}
    for n, o in enumerate(results, 1):
        by_kind.setdefault(o.kind, []).append(o)
        if o.kind in ("differ", "invalid"):
            print(f"seed {o.seed}: {o.kind}: {o.detail}", file=out, flush=True)
        if n % 500 == 0:
            print(f"... {n} programs: " + ", ".join(f"{k} {len(v)}" for k, v in sorted(by_kind.items())),
                  file=out, flush=True)
    return by_kind


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tests.fuzz.translation", description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, help="show program SEED and what the engines did")
    ap.add_argument("--start", type=int, default=0, help="first seed of a campaign")
    ap.add_argument("--count", type=int, default=100, help="programs in a campaign")
    ap.add_argument("--jobs", type=int, default=1, help="processes")
    ap.add_argument("--generator", choices=sorted(GENERATORS), default="order")
    args = ap.parse_args(argv)
    if args.seed is not None:
        print(GENERATORS[args.generator](args.seed))
        o = run_seed(args.seed, args.generator)
        print(f"seed {o.seed}: {o.kind}" + (f": {o.detail}" if o.detail else ""))
        return 0 if o.kind == "agree" else 1
    by_kind = campaign(args.start, args.count, args.generator, args.jobs)
    print(f"seeds {args.start}..{args.start + args.count - 1}: " +
          ", ".join(f"{k} {len(v)}" for k, v in sorted(by_kind.items())))
    return 0 if not by_kind.get("differ") else 1


if __name__ == "__main__":
    sys.exit(main())
