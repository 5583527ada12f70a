"""``python -m tests.fuzz``: generate programs and run the differential checks on them.

    python -m tests.fuzz --seed 42                  # print program 42 and its first disagreement
    python -m tests.fuzz --seeds 0:10000 --jobs 2   # a campaign: a summary and the failing seeds
    python -m tests.fuzz --seeds 0:200 --check reference

With ``--seed`` the program is printed, then each check's verdict; with
``--seeds A:B`` only failing seeds are printed (``--log FILE`` writes one line
per seed).  Exit status 1 when any check disagreed.
"""
from __future__ import annotations

import argparse
import sys
import time
from concurrent.futures import ProcessPoolExecutor

from . import oracles
from .checks import CHECKS
from .generator import generate


def run_checks(seed: int, checks: list, options: dict) -> list:
    """``[(check name, message or None)]`` for the program of ``seed``, stopping at the first disagreement."""
    program = generate(seed)
    ctx = dict(options)
    out = []
    for name in checks:
        try:
            verdict = CHECKS[name](program, ctx)
        except Exception as exc:  # a crash is a disagreement too: report it with the seed
            verdict = f"{type(exc).__name__}: {exc}"
        out.append((name, verdict))
        if verdict:
            break
    return out


def _one(args):
    seed, checks, options = args
    t = time.perf_counter()
    return seed, run_checks(seed, checks, options), time.perf_counter() - t


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tests.fuzz", description=__doc__.split("\n\n")[0])
    group = ap.add_mutually_exclusive_group(required=True)
    group.add_argument("--seed", type=int, help="print this seed's program and the first disagreement")
    group.add_argument("--seeds", help="a campaign over seeds A:B (B excluded)")
    ap.add_argument("--check", default="compile",
                    help=f"comma-separated checks, in order (available: {', '.join(CHECKS)}; default compile)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--openspin", default=oracles.OPENSPIN)
    ap.add_argument("--spinsim", default=oracles.SPINSIM)
    ap.add_argument("--log", help="campaign: write 'seed check verdict' per seed to this file")
    ap.add_argument("--show", type=int, default=20, help="campaign: print at most this many failures")
    ap.add_argument("--reduce", action="store_true",
                    help="with --seed: also print the program shrunk to the lines that still disagree")
    a = ap.parse_args(argv)
    checks = [c.strip() for c in a.check.split(",") if c.strip()]
    unknown = [c for c in checks if c not in CHECKS]
    if unknown:
        ap.error(f"unknown check {', '.join(unknown)} (available: {', '.join(CHECKS)})")
    options = {"openspin_exe": a.openspin, "spinsim_exe": a.spinsim}
    needs = {"compile": [("OpenSpin", a.openspin, "--openspin")], "reference": [("spinsim", a.spinsim, "--spinsim")]}
    for check in checks:
        for tool, exe, flag in needs.get(check, []):
            if not oracles.available(exe):
                ap.error(f"the {check} check needs {tool}, not found at {exe} (give {flag} PATH)")

    if a.seed is not None:
        print(generate(a.seed).text())
        failed = False
        for name, verdict in run_checks(a.seed, checks, options):
            print(f"--- {name}: {'agree' if not verdict else 'DISAGREE'}")
            if verdict:
                print(verdict)
                failed = True
                if a.reduce:
                    from .reduce import reduce
                    small = reduce(generate(a.seed), CHECKS[name], lambda: dict(options))
                    print(f"--- reduced ({name}):")
                    print(small.text())
                    print(CHECKS[name](small, dict(options)))
        return 1 if failed else 0

    lo, hi = (int(x) for x in a.seeds.split(":"))
    jobs = [(s, checks, options) for s in range(lo, hi)]
    failures = []
    t0 = time.perf_counter()
    log = open(a.log, "w") if a.log else None
    with ProcessPoolExecutor(a.jobs) if a.jobs > 1 else _Serial() as pool:
        for seed, verdicts, secs in pool.map(_one, jobs, chunksize=4):
            bad = [(n, v) for n, v in verdicts if v]
            if log:
                for n, v in verdicts:
                    log.write(f"{seed} {n} {'agree' if not v else 'DISAGREE ' + v.splitlines()[0]}\n")
            if bad:
                failures.append((seed, bad[0]))
                if len(failures) <= a.show:
                    print(f"seed {seed}: {bad[0][0]}: {bad[0][1].splitlines()[0]}", flush=True)
    if log:
        log.close()
    n = hi - lo
    print(f"{n} programs (seeds {lo}..{hi - 1}), checks {', '.join(checks)}: {n - len(failures)} agree, "
          f"{len(failures)} disagree ({time.perf_counter() - t0:.0f} s)")
    if failures:
        print("failing seeds:", " ".join(str(s) for s, _ in failures[:200]))
    return 1 if failures else 0


class _Serial:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    @staticmethod
    def map(fn, items, chunksize=1):
        return map(fn, items)


if __name__ == "__main__":
    sys.exit(main())
