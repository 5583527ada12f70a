"""Compiled blocks at scale: run a library of Spin programs with and without them.

Usage::

    python tests/benchmarks/bench_blocks_corpus.py --library /opt/oracles/propeller \\
        [--cycles 20000000] [--jobs 2] [--limit N] [--compat chip]

Every .spin file that spinemu compiles is run as a top object for
``--cycles`` cycles twice: with ``compile_blocks=False`` (the interpreter
alone) and with the default (hot code as compiled blocks, spinemu/chip/blocks.py).
The two runs must agree on everything a run produces: the pin trace, hub RAM,
the end cycle and reason, the bytecodes per cog, the cog events, or the error
message.  Prints the disagreements and the total CPU time of both.  Not part
of the test run (it needs the library, which tests never use).

With ``--cache`` the comparison is instead between blocks generated afresh
and blocks taken from a code cache (spinemu/chip/codecache.py): a run with
no cache, a run that fills one, and a run of a new chip from the saved cache
must agree.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", ".."))


def _outcome(image: bytes, cycles: int, compat: str, blocks: bool, cache=None):
    from spinemu.chip import Chip
    t = time.process_time()
    try:
        chip = Chip(image, compat=compat, compile_blocks=blocks)
        chip.code_cache = cache
        r = chip.run(max_cycles=cycles)
        out = (r.trace.changes, r.hub, r.end_cycle, r.reason, r.stats["bytecodes_per_cog"], r.cog_events)
        n = r.stats["bytecodes"]
    except Exception as e:          # an emulation fault must be the same fault
        out, n = (type(e).__name__, str(e)), 0
    return out, time.process_time() - t, n


def one(args):
    path, cycles, compat, cached = args
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError
    try:
        image = compile_file(path).binary
    except (SpinError, RecursionError, ValueError):
        return path, None
    if cached:
        import tempfile
        from spinemu.chip.codecache import CodeCache
        with tempfile.TemporaryDirectory() as tmp:
            a, ta, n = _outcome(image, cycles, compat, True)
            first = CodeCache(os.path.join(tmp, "c.marshal"))
            b, _, _ = _outcome(image, cycles, compat, True, first)
            first.save()
            c, tb, _ = _outcome(image, cycles, compat, True, CodeCache(os.path.join(tmp, "c.marshal")))
        return path, (a == b == c, ta, tb, n, a[0] if isinstance(a[0], str) else "")
    a, ta, n = _outcome(image, cycles, compat, False)
    b, tb, _ = _outcome(image, cycles, compat, True)
    return path, (a == b, ta, tb, n, a[0] if isinstance(a[0], str) else "")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", required=True)
    ap.add_argument("--cycles", type=int, default=20_000_000)
    ap.add_argument("--compat", default="chip")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--limit", type=int, default=0)
    ap.add_argument("--cache", action="store_true",
                    help="compare blocks generated afresh with blocks taken from a code cache instead")
    a = ap.parse_args(argv)
    paths = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.library) for f in fs if f.endswith(".spin"))
    if a.limit:
        paths = paths[:a.limit]
    ran = same = 0
    t_off = t_on = 0.0
    bytecodes = 0
    with ProcessPoolExecutor(a.jobs) as ex:
        for path, res in ex.map(one, [(p, a.cycles, a.compat, a.cache) for p in paths], chunksize=4):
            if res is None:
                continue
            ok, ta, tb, n, err = res
            ran += 1
            same += ok
            t_off += ta
            t_on += tb
            bytecodes += n
            if not ok:
                print(f"DIFFERENT: {path}", flush=True)
    print(f"{ran} programs ran for {a.cycles:,} cycles ({a.compat} mode): {same} identical, {ran - same} different")
    if a.cache:
        print(f"CPU time: blocks generated {t_off:.1f} s, taken from the cache {t_on:.1f} s; {bytecodes:,} bytecodes")
    else:
        print(f"CPU time: interpreter {t_off:.1f} s, with compiled blocks {t_on:.1f} s "
              f"({t_off / t_on if t_on else 0:.2f}x); {bytecodes:,} bytecodes")
    return 0 if same == ran else 1


if __name__ == "__main__":
    sys.exit(main())
