"""Runtime warnings and compiler hints over a library of real Spin programs.

Usage::

    python tests/benchmarks/warnings_corpus.py --library /opt/oracles/propeller \\
        [--sample 200] [--seed 1] [--cycles 20000000] [--jobs 2] [--show 20]

Compiles a seeded random sample of the library's .spin files as top objects,
runs each that compiles for ``--cycles`` cycles with every runtime check on
(and its debug info), and counts the warnings and hints by kind, with
examples to read: how often each fires on code people published, and whether
those are real mistakes.  It also runs each program with the checks off and
reports any difference in what the chip did (there must be none).  Not part
of the test run (it needs the library, which tests never use).
"""
from __future__ import annotations

import argparse
import collections
import glob
import os
import random
import sys
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", ".."))


def check(args):
    path, cycles = args
    from spinemu.chip import Chip
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError

    try:
        prog = compile_file(path)
    except SpinError:
        return path, None, [], [], False
    except RecursionError:
        return path, None, [], [], False
    hints = [(d.line, d.message.split(":")[0][:60]) for d in prog.warnings]
    try:
        on = Chip(prog.binary, debug_info=prog.debug_info()).run(max_cycles=cycles)
        off = Chip(prog.binary, warn=False).run(max_cycles=cycles)
    except SpinError as e:
        return path, "fault", hints, [str(e).splitlines()[0][:100]], False
    same = on.trace.changes == off.trace.changes and on.hub == off.hub and on.end_cycle == off.end_cycle
    warns = [(w.kind, w.line, w.message[:110]) for w in on.runtime_warnings]
    return path, on.reason, hints, warns, same


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", required=True)
    ap.add_argument("--sample", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cycles", type=int, default=20_000_000)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--show", type=int, default=20)
    a = ap.parse_args(argv)
    files = sorted(glob.glob(os.path.join(a.library, "**", "*.spin"), recursive=True))
    random.Random(a.seed).shuffle(files)
    files = files[:a.sample]
    with ProcessPoolExecutor(a.jobs) as pool:
        results = list(pool.map(check, [(f, a.cycles) for f in files]))
    ran = [r for r in results if r[1] is not None]
    kinds = collections.Counter(k for r in ran for k, _l, _m in r[3] if r[1] != "fault")
    hint_kinds = collections.Counter(m.split("'")[1] if "'" in m else m for r in ran for _l, m in r[2])
    differ = [r[0] for r in ran if r[1] != "fault" and not r[4]]
    print(f"{len(files)} files, {len(ran)} compiled and ran {a.cycles:,} cycles "
          f"({sum(1 for r in ran if r[1] == 'fault')} faulted)")
    print(f"programs with a runtime warning: {sum(1 for r in ran if r[3] and r[1] != 'fault')}")
    for k, n in kinds.most_common():
        print(f"  {k}: {n} places")
    print(f"programs with a compiler hint: {sum(1 for r in ran if r[2])}")
    for k, n in hint_kinds.most_common():
        print(f"  {k}: {n}")
    print(f"runs that differ with the checks off: {len(differ)}" + (f" {differ[:5]}" if differ else ""))
    shown = 0
    for path, reason, hints, warns, _same in ran:
        if reason == "fault" or not warns:
            continue
        for kind, line, msg in warns:
            if shown < a.show:
                print(f"{os.path.relpath(path, a.library)}:{line}: {kind}: {msg}")
                shown += 1


if __name__ == "__main__":
    main()
