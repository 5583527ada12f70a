"""Cost of a live pin listener on a program whose counter runs for many seconds (run on demand).

``python tests/benchmarks/bench_listen.py [--seconds 1 2 4 8 16] [--hz 1000 50000] [--repeat 3]``

The program (generated here, compiled by spinemu): CTRA is an NCO at
``--hz`` on P4 for the whole run while the cog toggles P5 about every
millisecond (so the scheduler has something to do every millisecond and a
1 ms listener is called about a thousand times a simulated second).  Each
line: simulated seconds, CPU seconds without a listener and with one
(interval 1 ms, doing nothing), the listener's calls, the trace's changes,
and CPU microseconds per call of the difference.  Linear means the columns
grow with the seconds and the per-call cost stays flat.  CPU time is the
best of ``--repeat`` runs.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler import compile_source  # noqa: E402

CLOCK = 80_000_000
SOURCE = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[4] := 1
  frqa := {frq}
  ctra := %00100 << 26 | 4
  dira[5] := 1
  repeat
    !outa[5]
    waitcnt(cnt + 80_000)
"""


def cpu_run(image: bytes, seconds: float, listen: bool):
    chip = Chip(image, compat="chip")
    calls = [0]
    if listen:
        def listener(changes, upto, present):
            calls[0] += 1
        chip.add_pin_listener(listener, interval_cycles=CLOCK // 1000)
    t = time.process_time()
    result = chip.run(max_cycles=int(seconds * CLOCK))
    return time.process_time() - t, calls[0], len(result.trace.changes)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--hz", type=int, nargs="+", default=[1_000, 50_000])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    print(f"{'NCO Hz':>8} {'sim s':>6} {'plain CPU s':>12} {'listened CPU s':>15} {'calls':>7} "
          f"{'changes':>9} {'us/call':>8}")
    for hz in args.hz:
        image = compile_source(SOURCE.format(frq=round(hz * 2**32 / CLOCK))).binary
        for s in args.seconds:
            plain = min(cpu_run(image, s, False)[0] for _ in range(args.repeat))
            runs = [cpu_run(image, s, True) for _ in range(args.repeat)]
            listened, calls, changes = min(runs)
            print(f"{hz:>8} {s:>6g} {plain:>12.3f} {listened:>15.3f} {calls:>7} {changes:>9} "
                  f"{(listened - plain) / max(calls, 1) * 1e6:>8.1f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
