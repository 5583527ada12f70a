"""Busy cogs: how the run time grows with the number of cogs that never wait (run on demand).

``python tests/benchmarks/bench_cogs.py`` prints, for 1, 2, 4 and 8 busy
cogs, the real-time factor (simulated seconds / seconds) of

* **end to end**: ``python -m spinemu run PROGRAM.spin`` in a subprocess
  (Python start-up, imports, compiling the source, the run, the summary),
  by wall time and by the child's CPU time;
* **the run alone**: ``Chip(image).run()`` in this process, with cogs
  running ahead (the default) and with ``run_ahead=False`` (every hub
  access handed over in cycle order, the scheduling before running ahead;
  ``--no-exact`` skips it, it is slow);

and the cost per busy cog (CPU seconds of the run per cog per simulated
second).  The Spin program starts ``COGS - 1`` cogs on the same method and
runs it in the main cog too: an integer loop over locals, about 0.98
simulated seconds of work per cog, then each cog writes its result to a
hub variable and stops.  The PASM program starts ``COGS`` cogs on an
arithmetic loop that never ends and runs for ``--pasm-seconds`` (0.25 s).

With ``--spinsim`` (default: ``/opt/oracles/spinsim/build/spinsim`` when it
exists) the same images also run on spinsim 0.99 ``-p``, the cycle-exact C
simulator, for comparison.  Each figure is the best of ``--repeat`` runs
(default 3, by CPU time).  ``--corrected-demo`` adds the column's corrected
demo end to end.  The 1-cog row's end-to-end figure is the one-cog CPU-bound
case (start-up and compile included).

Measure a regular install (``pip install .`` into a virtualenv, then run
this script with that virtualenv's Python): the script then imports the
installed spinemu, whose bytecode is cached; from a source tree without an
installed spinemu it falls back to the tree (and, with
PYTHONDONTWRITEBYTECODE, every run compiles spinemu's modules again).
"""
from __future__ import annotations

import argparse
import os
import resource
import shutil
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

import spinemu  # noqa: E402
from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler import compile_source  # noqa: E402

SPIN_BUSY = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  COGS = {cogs}
  N = 25_000

VAR
  long stack[224]
  long results[8]

PUB main | i
  i := 1
  repeat while i < COGS
    cognew(work(i), @stack[(i - 1) * 32])
    i++
  work(0)

PRI work(id) | k, x
  x := id
  repeat k from 1 to N
    x := x * 3 + k ^ (x >> 5)
  results[id] := x
"""

PASM_BUSY = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  COGS = {cogs}

PUB main | i
  repeat i from 1 to COGS
    cognew(@entry, 0)

DAT
        org 0
entry   mov     x, #100
inner   add     y, x
        xor     y, #7 wc
        rcl     z, #1
        sub     w, y
        djnz    x, #inner
        jmp     #entry
x long 0
y long 0
z long 0
w long 0
"""

DEMO_SRC = os.path.join(ROOT, "spin_src", "corrected", "stepper_demo.spin")
DEMO_SECONDS = 1_152_066_952 / 80_000_000
SPINSIM = "/opt/oracles/spinsim/build/spinsim"
CLOCK = 80_000_000


def best_of(n, fn):
    """``(wall, cpu, result)`` of the fastest of ``n`` calls (by CPU time)."""
    best = None
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        result = fn()
        dt, dc = time.perf_counter() - t0, time.process_time() - c0
        if best is None or dc < best[1]:
            best = (dt, dc, result)
    return best


def child(cmd, n):
    """``(wall, child CPU)`` of the fastest of ``n`` runs of ``cmd`` (by CPU)."""
    env = dict(os.environ)
    if SOURCE_TREE:
        env["PYTHONPATH"] = ROOT + os.pathsep + os.environ.get("PYTHONPATH", "")
    best = None
    for _ in range(n):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        # (in another folder: from the checkout, ``-m spinemu`` would import the source tree, not the install)
        subprocess.run(cmd, check=True, capture_output=True, env=env, cwd=tempfile.gettempdir())
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        if best is None or cpu < best[1]:
            best = (wall, cpu)
    return best


def spinemu_cmd(path, *extra):
    return [sys.executable, "-m", "spinemu", "run", path, "--no-progress", *extra]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cogs", default="1,2,4,8", help="numbers of busy cogs (default 1,2,4,8)")
    ap.add_argument("--no-exact", action="store_true", help="skip the run with run_ahead=False")
    ap.add_argument("--no-pasm", action="store_true", help="skip the busy PASM cogs")
    ap.add_argument("--pasm-seconds", type=float, default=0.25)
    ap.add_argument("--spinsim", default=SPINSIM if os.path.exists(SPINSIM) else None,
                    help="spinsim binary to compare with (default: the oracle's, if present)")
    ap.add_argument("--corrected-demo", action="store_true", help="the column's corrected demo end to end")
    a = ap.parse_args(argv)
    counts = [int(x) for x in a.cogs.split(",")]
    print(f"spinemu from {os.path.dirname(spinemu.__file__)}")
    with tempfile.TemporaryDirectory() as tmp:
        print(f"busy Spin cogs (0.98 simulated s of work each), best of {a.repeat}:")
        print(" cogs | end to end: wall (x real time), CPU (x)  | run alone, CPU (x)  | per cog per sim. s "
              "| exact hand-over, CPU (x) | spinsim -p, wall (x), CPU (x)")
        for cogs in counts:
            src = os.path.join(tmp, f"busy{cogs}.spin")
            with open(src, "w") as f:
                f.write(SPIN_BUSY.format(cogs=cogs))
            image = compile_source(SPIN_BUSY.format(cogs=cogs), src).binary
            _, dc, r = best_of(a.repeat, lambda: Chip(image).run())
            sim = r.end_cycle / CLOCK
            wall, cpu = child(spinemu_cmd(src), a.repeat)
            line = (f" {cogs:4} | {wall:6.3f} s ({sim / wall:5.2f}x), {cpu:6.3f} s ({sim / cpu:5.2f}x) "
                    f"| {dc:6.3f} s ({sim / dc:6.2f}x) | {dc / cogs / sim:8.4f} s")
            if not a.no_exact:
                _, de, r2 = best_of(1, lambda: Chip(image, run_ahead=False).run())
                assert (r2.hub, r2.end_cycle, r2.trace.changes) == (r.hub, r.end_cycle, r.trace.changes)
                line += f" | {de:6.3f} s ({sim / de:5.2f}x)"
            if a.spinsim:
                binary = os.path.join(tmp, f"busy{cogs}.binary")
                with open(binary, "wb") as f:
                    f.write(image)
                ws, cs = child([a.spinsim, "-p", binary], 1)
                line += f" | {ws:6.3f} s ({sim / ws:5.2f}x), CPU {cs:6.3f} s ({sim / cs:5.2f}x)"
            print(line, flush=True)
        if not a.no_pasm:
            cycles = int(a.pasm_seconds * CLOCK)
            print(f"\nbusy PASM cogs ({a.pasm_seconds} simulated s), best of {a.repeat}:")
            print(" cogs | end to end: wall (x), CPU (x) | run alone, CPU (x) | per cog per sim. s | instructions/s")
            for cogs in counts:
                src = os.path.join(tmp, f"pasm{cogs}.spin")
                with open(src, "w") as f:
                    f.write(PASM_BUSY.format(cogs=cogs))
                image = compile_source(PASM_BUSY.format(cogs=cogs), src).binary
                _, dc, r = best_of(a.repeat, lambda: Chip(image).run(max_cycles=cycles))
                sim = cycles / CLOCK
                wall, cpu = child(spinemu_cmd(src, "--cycles", str(cycles)), a.repeat)
                print(f" {cogs:4} | {wall:6.3f} s ({sim / wall:5.2f}x), {cpu:6.3f} s ({sim / cpu:5.2f}x) "
                      f"| {dc:6.3f} s ({sim / dc:5.2f}x) | {dc / cogs / sim:8.4f} s "
                      f"| {r.stats['pasm_instructions'] / dc:,.0f}", flush=True)
        if a.corrected_demo:
            out = os.path.join(tmp, "demo.log")
            wall, cpu = child(spinemu_cmd(DEMO_SRC, "--cycles", "1600000000", "--trace", out,
                                          "--trace-format", "log"), a.repeat)
            print(f"\ncorrected demo end to end ({DEMO_SECONDS:.1f} s simulated, trace file written): "
                  f"{wall:.3f} s wall ({DEMO_SECONDS / wall:.1f}x), {cpu:.3f} s CPU ({DEMO_SECONDS / cpu:.1f}x)")
    if shutil.which("nproc"):
        load = os.getloadavg()[0]
        print(f"\n(load average {load:.1f} on {os.cpu_count()} cores: wall times grow with the load, "
              "CPU times much less)")


if __name__ == "__main__":
    main()
