"""The steady-state skip against running every period, on many generated programs (run on demand).

``python tests/benchmarks/steady_campaign.py --seeds 0:400`` compiles the
clock-paced program SEED (tests/chip/steady_programs.py: counters of every
size crossing thresholds, mod-n table steps, pins, CNT, values passed
between cogs, operators the skip refuses, main loops that end, slow cogs
sleeping through fast ones) for every seed in the range, runs it for
``--cycles`` cycles with ``Chip(steady_skip=False)`` and with the default,
and prints every seed whose pin trace, hub RAM, end cycle, reason,
bytecodes per cog, cog events, runtime warnings or fault differ
(``schedule_compare.run_outcome``), then totals (programs, how
many skipped, periods skipped).  ``--multicog`` takes the multi-cog
programs of the scheduling comparison (tests/chip/multicog_programs.py:
locks, races, cogs starting and stopping each other) instead, ``--pasm``
programs with a PASM cog idle in a loop (steady_programs.pasm_program: a
mailbox, a pin or a CNT deadline it polls, which the skip must sleep through
and wake on time).  Exit status 1
if any differed.  ``-j N`` runs N processes.  The default test run compares a
seeded sample (tests/chip/test_steady.py).
"""
from __future__ import annotations

import argparse
import multiprocessing
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path[:0] = [ROOT, os.path.join(ROOT, "tests", "chip")]

from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler.program import compile_source  # noqa: E402
from schedule_compare import run_outcome  # noqa: E402


def one(job):
    seed, cycles, multicog, pasm = job
    if multicog:
        from schedule_compare import generated_image
        image = generated_image(seed)
    elif pasm:
        from steady_programs import pasm_program
        image = compile_source(pasm_program(seed), f"steady_pasm{seed}.spin").binary
    else:
        from steady_programs import program
        image = compile_source(program(seed), f"steady{seed}.spin").binary
    want = run_outcome(Chip(image, steady_skip=False), cycles)
    chip = Chip(image)
    got = run_outcome(chip, cycles)
    steady = chip._steady
    return seed, got == want, steady.skips if steady else 0, steady.periods if steady else 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="0:400", help="START:END (default 0:400)")
    ap.add_argument("--cycles", type=int, default=400_000_000)
    ap.add_argument("--multicog", action="store_true", help="the scheduling comparison's multi-cog programs")
    ap.add_argument("--pasm", action="store_true", help="programs with a PASM cog idle in a loop")
    ap.add_argument("-j", type=int, default=1, help="processes")
    a = ap.parse_args(argv)
    start, end = (int(x) for x in a.seeds.split(":"))
    jobs = [(s, a.cycles, a.multicog, a.pasm) for s in range(start, end)]
    t0 = time.perf_counter()
    differ = skipped = periods = 0
    pool = multiprocessing.Pool(a.j) if a.j > 1 else None
    results = pool.imap_unordered(one, jobs) if pool else map(one, jobs)
    for seed, same, skips, n in results:
        if not same:
            differ += 1
            print(f"seed {seed}: differs", flush=True)
        skipped += skips > 0
        periods += n
    if pool:
        pool.close()
    print(f"seeds {start}..{end - 1}: {end - start} programs, {differ} differ; {skipped} skipped "
          f"({periods:,} periods); {time.perf_counter() - t0:.0f} s")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
