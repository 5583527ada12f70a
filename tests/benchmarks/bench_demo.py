"""Speed of the chip emulator (run on demand: ``python tests/benchmarks/bench_demo.py``).

Prints:
* the real-time factor (simulated seconds / wall seconds, and / CPU seconds)
  of the corrected stepper demo over its whole run (1_152_066_952 cycles,
  ~14.4 s at 80 MHz): as run by default (compiled blocks and busy-loop
  fast-forward), without the fast-forward, and with the interpreter alone;
* bytecodes per second on a CPU-bound loop (no waits, no fast-forward
  possible: it changes a variable every iteration), with and without
  compiled blocks;
* the end-to-end time of ``python -m spinemu run spin_src/corrected/stepper_demo.spin
  --cycles 1600000000 --trace ... --trace-format log`` in a subprocess
  (Python start-up, imports, compilation, the run and the trace file: what
  the team's gap report measures), by wall time and the child's CPU time.

Each figure is the best of ``--repeat`` runs (default 3).  CPU time is the
steadier figure on a loaded machine.  Run it with the Python of a regular
install (``pip install .``) to measure that install; from a source tree
without one it falls back to the tree.
"""
from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
try:                                    # an installed spinemu (``pip install .``: its bytecode is cached)
    import spinemu  # noqa: F401
    SOURCE_TREE = False
except ImportError:                     # else the source tree this script is in
    sys.path.insert(0, ROOT)
    SOURCE_TREE = True

from spinemu.chip import Chip  # noqa: E402

DEMO = os.path.join(ROOT, "tests", "data", "article", "corrected_stepper_demo.binary")
DEMO_SRC = os.path.join(ROOT, "spin_src", "corrected", "stepper_demo.spin")
CPU_LOOP = os.path.join(ROOT, "tests", "data", "chip", "bench_cpu_loop.binary")
DEMO_SECONDS = 1_152_066_952 / 80_000_000


def best_of(n, fn):
    """``(wall seconds, cpu seconds, result)`` of the fastest of ``n`` runs (by CPU time)."""
    best = None
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        result = fn()
        dt, dc = time.perf_counter() - t0, time.process_time() - c0
        if best is None or dc < best[1]:
            best = (dt, dc, result)
    return best


def end_to_end(n: int):
    """``(wall, child CPU)`` of the fastest of ``n`` CLI runs of the corrected demo."""
    env = dict(os.environ)
    if SOURCE_TREE:                     # (with PYTHONDONTWRITEBYTECODE every run compiles spinemu again)
        env["PYTHONPATH"] = ROOT + os.pathsep + os.environ.get("PYTHONPATH", "")
    best = None
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [sys.executable, "-m", "spinemu", "run", DEMO_SRC, "--cycles", "1600000000",
               "--trace", os.path.join(tmp, "demo.log"), "--trace-format", "log"]
        for _ in range(n):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            # (in a folder of its own: from the checkout, ``-m spinemu`` would import the source tree)
            subprocess.run(cmd, check=True, capture_output=True, env=env, cwd=tmp)
            wall = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            if best is None or cpu < best[1]:
                best = (wall, cpu)
    return best


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-cli", action="store_true", help="skip the end-to-end subprocess runs")
    a = ap.parse_args(argv)
    image = open(DEMO, "rb").read()
    for label, kw in (("default", {}), ("fast_forward=False", {"fast_forward": False}),
                      ("compile_blocks=False", {"compile_blocks": False})):
        dt, dc, r = best_of(a.repeat, lambda: Chip(image, **kw).run())
        sim = r.end_cycle / r.trace.clock_hz
        print(f"corrected_stepper_demo, {label}: {r.end_cycle:,} cycles ({sim:.2f} s simulated) "
              f"in {dt:.3f} s wall ({dc:.3f} s CPU): real-time factor {sim / dt:.1f}x ({sim / dc:.1f}x by CPU); "
              f"{r.stats['bytecodes']:,} bytecodes ({r.stats['bytecodes_skipped']:,} skipped, "
              f"{r.stats['busy_loops_learned']} loops learned, {r.stats['blocks_compiled']} blocks compiled)")
    image = open(CPU_LOOP, "rb").read()
    cycles = 200_000_000
    for label, kw in (("default", {}), ("compile_blocks=False", {"compile_blocks": False})):
        dt, dc, r = best_of(a.repeat, lambda: Chip(image, **kw).run(max_cycles=cycles))
        n = r.stats["bytecodes"] - r.stats["bytecodes_skipped"]
        print(f"CPU-bound loop, {label}: {n:,} bytecodes in {dt:.3f} s wall ({dc:.3f} s CPU): "
              f"{n / dt:,.0f} bytecodes/s ({n / dc:,.0f} by CPU; real-time factor {cycles / r.trace.clock_hz / dt:.1f}x)")
    if not a.no_cli:
        wall, cpu = end_to_end(a.repeat)
        print(f"end to end (python -m spinemu run corrected/stepper_demo.spin, {DEMO_SECONDS:.1f} s simulated): "
              f"{wall:.3f} s wall ({cpu:.3f} s CPU): real-time factor {DEMO_SECONDS / wall:.1f}x "
              f"({DEMO_SECONDS / cpu:.1f}x by CPU)")


if __name__ == "__main__":
    main()
