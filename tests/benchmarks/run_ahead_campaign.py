"""Running ahead against the exact hand-over on many generated multi-cog programs (run on demand).

``python tests/benchmarks/run_ahead_campaign.py --seeds 0:1000`` compiles
multi-cog program SEED (tests/chip/multicog_programs.py: shared counters
under a lock, races without one, producer/consumer through hub RAM, cogs
starting and stopping each other, WAITPEQ/WAITPNE on another cog's pin,
cogs reading and writing each other's stacks) for every seed in the range,
runs it for ``--cycles`` cycles with ``Chip(run_ahead=False)`` and with the
default scheduling, and prints every seed whose pin trace, hub RAM, end
cycle, reason, bytecodes per cog, cog events or fault differ, then totals
(programs, how they ended, bytecodes compared).  Exit status 1 if any
differed.  ``-j N`` runs N processes.  The default test run compares a
seeded sample (tests/chip/test_run_ahead.py).
"""
from __future__ import annotations

import argparse
import collections
import multiprocessing
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path[:0] = [ROOT, os.path.join(ROOT, "tests", "chip")]

from schedule_compare import GENERATED_CYCLES, generated_image, outcome  # noqa: E402


def check(job):
    seed, cycles = job
    try:
        image = generated_image(seed)
    except Exception as e:                  # a generated program the compiler refuses: counted, not compared
        return seed, "not compiled: " + str(e).splitlines()[0], [], 0
    want = outcome(image, False, cycles)
    got = outcome(image, True, cycles)
    if isinstance(want, tuple):
        ending, bytecodes = "fault " + want[0], 0
    else:
        ending, bytecodes = want["reason"], sum(want["bytecodes"].values())
    diffs = [] if got == want else [f"exact {summary(want)} / ahead {summary(got)}"]
    return seed, ending, diffs, bytecodes


def summary(o):
    if isinstance(o, tuple):
        return f"{o[0]}: {o[1]}"
    return f"{o['reason']} at {o['end_cycle']}, {len(o['trace'])} pin changes, hub crc {hash(o['hub']) & 0xFFFF:04X}"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="0:1000", help="START:END (default 0:1000)")
    ap.add_argument("--cycles", type=int, default=GENERATED_CYCLES)
    ap.add_argument("-j", type=int, default=1, help="processes")
    a = ap.parse_args(argv)
    lo, hi = (int(x) for x in a.seeds.split(":"))
    jobs = [(s, a.cycles) for s in range(lo, hi)]
    t0 = time.perf_counter()
    endings = collections.Counter()
    bad = []
    total = 0
    with multiprocessing.Pool(a.j) as pool:
        for seed, ending, diffs, bytecodes in pool.imap_unordered(check, jobs):
            endings[ending.split(":")[0]] += 1
            total += bytecodes
            if diffs:
                bad.append(seed)
                print(f"seed {seed}: DIFFERS: {diffs[0]}", flush=True)
    print(f"seeds {lo}..{hi - 1}: {len(jobs)} programs, {len(bad)} differ; endings "
          + ", ".join(f"{k} {v}" for k, v in sorted(endings.items()))
          + f"; {total:,} bytecodes (exact run) compared; {time.perf_counter() - t0:.0f} s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
