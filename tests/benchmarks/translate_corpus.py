"""Spin-to-Python at scale: translate library files and run them on both engines.

Usage::

    python tests/benchmarks/translate_corpus.py --library /opt/oracles/propeller \\
        [--sample 311] [--seed 1] [--cycles 3000000] [--compat spinsim] [--jobs 2]

Every .spin file under ``--library`` that spinemu compiles is translated
(a failure to translate is reported).  A random ``--sample`` of them (fixed
``--seed``) is run as a top object on the bytecode engine and on the Python
engine for ``--cycles`` cycles, and compared the way the test suite does
(tests/translate/crosscheck.py): same pin states, same timing, same end
cycle, hub RAM identical outside the cogs' stacks.  Files whose bytecode run
faults must fault on the Python engine too.  Not part of the test run (it
needs the library, which tests never use).
"""
from __future__ import annotations

import argparse
import glob
import os
import random
import sys
from concurrent.futures import ProcessPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)


def _translate(path: str):
    from spinemu.diagnostics import SpinError
    from spinemu.translate import TranslateError
    from spinemu.translate.program import translate_program
    try:
        translate_program(path)
    except TranslateError as exc:
        return path, "untranslated", str(exc)
    except SpinError:
        return path, "rejected", ""            # the compiler rejects it: not a candidate
    except Exception as exc:                    # a crash is what this run looks for
        return path, "crash", f"{type(exc).__name__}: {exc}"
    return path, "ok", ""


def _run(job):
    path, cycles, compat = job
    from spinemu import translate
    from spinemu.diagnostics import EmulationError
    from tests.translate.crosscheck import crosscheck, run_bytecode
    try:
        bytecode_run = run_bytecode(path, cycles, compat)
    except EmulationError as exc:
        try:
            translate.run_translated(path, max_cycles=cycles, compat=compat)
        except EmulationError as exc2:
            same = exc.message.split(":")[0] == exc2.message.split(":")[0]
            return path, "same fault" if same else "different fault", f"{exc.message} / {exc2.message}"
        return path, "different fault", f"bytecode: {exc.message}; Python engine ran"
    try:
        result = crosscheck(path, cycles, compat, bytecode_run)
    except Exception as exc:
        return path, "crash", f"{type(exc).__name__}: {exc}"
    if result.ok and result.bytecode.end_cycle == result.python.end_cycle:
        return path, "agree", ""
    return path, "differ", result.describe()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--library", required=True)
    ap.add_argument("--sample", type=int, default=311)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cycles", type=int, default=3_000_000)
    ap.add_argument("--compat", choices=["spinsim", "chip"], default="spinsim")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = ap.parse_args(argv)
    files = sorted(glob.glob(os.path.join(args.library, "**", "*.spin"), recursive=True))
    with ProcessPoolExecutor(args.jobs) as pool:
        translated = list(pool.map(_translate, files, chunksize=8))
    ok = [p for p, status, _ in translated if status == "ok"]
    bad = [(p, s, m) for p, s, m in translated if s in ("untranslated", "crash")]
    print(f"{len(files)} files; {len(ok)} compile and translate; {len(bad)} compile but do not translate")
    for p, s, m in bad:
        print(f"  {s}: {os.path.relpath(p, args.library)}: {m}")
    sample = sorted(random.Random(args.seed).sample(ok, min(args.sample, len(ok))))
    with ProcessPoolExecutor(args.jobs) as pool:
        runs = list(pool.map(_run, [(p, args.cycles, args.compat) for p in sample]))
    counts: dict = {}
    for p, status, msg in runs:
        counts[status] = counts.get(status, 0) + 1
        if status not in ("agree", "same fault"):
            print(f"  {status}: {os.path.relpath(p, args.library)}\n    " + msg.replace("\n", "\n    "))
    print(f"sample of {len(sample)} run for {args.cycles:,} cycles ({args.compat} mode): "
          + ", ".join(f"{n} {s}" for s, n in sorted(counts.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
