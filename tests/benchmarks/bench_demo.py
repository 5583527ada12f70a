"""Speed of the chip emulator (run on demand: ``python tests/benchmarks/bench_demo.py``).

Prints:
* the real-time factor (simulated seconds / wall seconds) of the corrected
  stepper demo over its whole run (1_152_058_552 cycles, ~14.4 s at 80 MHz),
  with busy-loop fast-forward on (the default) and off;
* bytecodes per second of the interpreter on a CPU-bound loop (no waits, no
  fast-forward possible: it changes a variable every iteration).

Each figure is the best of ``--repeat`` runs (default 3), in this process;
the CPU time of the process is shown too, since wall time suffers on a
loaded machine.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

from spinemu.chip import Chip  # noqa: E402

DEMO = os.path.join(ROOT, "tests", "data", "article", "corrected_stepper_demo.binary")
CPU_LOOP = os.path.join(ROOT, "tests", "data", "chip", "bench_cpu_loop.binary")


def best_of(n, fn):
    """``(wall seconds, cpu seconds, result)`` of the fastest of ``n`` runs."""
    best = None
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        result = fn()
        dt, dc = time.perf_counter() - t0, time.process_time() - c0
        if best is None or dt < best[0]:
            best = (dt, dc, result)
    return best


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args(argv)
    image = open(DEMO, "rb").read()
    for ff in (True, False):
        dt, dc, r = best_of(a.repeat, lambda: Chip(image, fast_forward=ff).run())
        sim = r.end_cycle / r.trace.clock_hz
        print(f"corrected_stepper_demo, fast_forward={ff}: {r.end_cycle:,} cycles ({sim:.2f} s simulated) "
              f"in {dt:.2f} s wall ({dc:.2f} s CPU): real-time factor {sim / dt:.1f}x ({sim / dc:.1f}x by CPU); "
              f"{r.stats['bytecodes']:,} bytecodes ({r.stats['bytecodes_skipped']:,} skipped)")
    image = open(CPU_LOOP, "rb").read()
    cycles = 200_000_000
    dt, dc, r = best_of(a.repeat, lambda: Chip(image).run(max_cycles=cycles))
    n = r.stats["bytecodes"] - r.stats["bytecodes_skipped"]
    print(f"CPU-bound loop: {n:,} bytecodes in {dt:.2f} s wall ({dc:.2f} s CPU): {n / dt:,.0f} bytecodes/s "
          f"(real-time factor {cycles / r.trace.clock_hz / dt:.1f}x)")


if __name__ == "__main__":
    main()
