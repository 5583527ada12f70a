"""Generated multi-cog Spin programs on spinemu and on the reference simulator (run on demand).

``python tests/benchmarks/multicog_reference.py --seeds 0:300`` compiles
multi-cog program SEED (tests/chip/multicog_programs.py: shared counters
under a lock, races without one, producer/consumer through hub RAM, cogs
starting and stopping each other, WAITPEQ/WAITPNE and INA on other cogs'
pins, CNT reads, cogs reading each other's stacks) for every seed in the
range and runs the programs that end by themselves within ``--cycles`` on
spinemu (default timing) and on spinsim 0.99 ``-p`` (Parallax's ROM
interpreter on cycle-exact cogs, a black box at ``--spinsim``): the hub RAM
when every cog has stopped must be identical, except the workers' stack
arrays (a cog stopped by another part way through a bytecode: a known
difference, docs/chip.md "Pins").  Results depend on every cog's timing:
CNT values, INA samples of other cogs' pins, who wins a race.  Programs that
write past hub RAM (an index like ``x ^ z & 15``; the runtime warning
``write-outside-hub``) are not compared: the chip drops such writes, spinsim
keeps them, even over its copy of the ROM interpreter, which cogs started
later then run corrupted.

``--record FILE`` also writes the agreeing seeds with the SHA-256 of the
compared bytes, for the default test run (tests/chip/test_multicog_reference.py),
which needs no spinsim.  Exit status 1 if any program differed.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path[:0] = [ROOT, os.path.join(ROOT, "tests", "chip")]

from multicog_programs import STACK_LONGS, program  # noqa: E402
from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler.program import compile_source  # noqa: E402
from tests.fuzz.oracles import SPINSIM, spinsim_hub  # noqa: E402

#: cycles a program may run on spinemu before it counts as not ending by itself
CYCLES = 20_000_000


def compared(image: bytes, hub: bytes, source: str) -> bytes:
    """The 32 KB of hub RAM without the workers' stack arrays (VAR ``stacks``, after 38 longs)."""
    vbase = int.from_bytes(image[8:10], "little")
    lo = vbase + 4 * 38
    hi = lo + 4 * STACK_LONGS * max(source.count("PRI worker"), 1)
    return hub[:lo] + hub[hi:0x8000]


def spinemu_outcome(seed: int, cycles: int = CYCLES):
    """``(image, compared bytes)`` of program ``seed`` on spinemu, or ``(image, None)`` if it does not end."""
    source = program(seed)
    image = compile_source(source, f"multicog_{seed}.spin").binary
    try:
        result = Chip(image).run(max_cycles=cycles)
    except Exception:                   # a fault (a program poking another cog's stack): not compared
        return image, None
    if result.reason != "all cogs stopped" or any(w.kind == "write-outside-hub" for w in result.runtime_warnings):
        return image, None
    return image, compared(image, bytes(result.hub), source)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="0:300", help="START:END (default 0:300)")
    ap.add_argument("--cycles", type=int, default=CYCLES)
    ap.add_argument("--spinsim", default=SPINSIM)
    ap.add_argument("--record", help="write the agreeing seeds and hashes to this JSON file")
    a = ap.parse_args(argv)
    lo, hi = (int(x) for x in a.seeds.split(":"))
    agree, differ, skipped, recorded = 0, 0, 0, {}
    t0 = time.perf_counter()
    for seed in range(lo, hi):
        image, mine = spinemu_outcome(seed, a.cycles)
        if mine is None:
            skipped += 1
            continue
        try:
            ref = spinsim_hub(image, a.spinsim, timeout=120)
        except subprocess.TimeoutExpired:
            print(f"seed {seed}: spinsim did not end in 120 s", flush=True)
            differ += 1
            continue
        theirs = compared(image, ref, program(seed))
        if mine == theirs:
            agree += 1
            recorded[str(seed)] = hashlib.sha256(mine).hexdigest()
        else:
            first = next(i for i in range(len(mine)) if mine[i] != theirs[i])
            n = sum(x != y for x, y in zip(mine, theirs))
            print(f"seed {seed}: {n} bytes differ, the first at compared offset ${first:04X}", flush=True)
            differ += 1
    print(f"seeds {lo}..{hi - 1}: {agree} identical, {differ} differ, {skipped} not ending by themselves "
          f"within {a.cycles:,} cycles ({time.perf_counter() - t0:.0f} s)")
    if a.record:
        with open(a.record, "w") as fh:
            json.dump({"source": "spinsim 0.99 -p; tests/benchmarks/multicog_reference.py", "cycles": a.cycles,
                       "sha256": recorded}, fh, indent=1, sort_keys=True)
            fh.write("\n")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
