#!/usr/bin/env python3
"""Record what Parallax's ROM interpreter does with each conformance program.

Usage (from the worktree root; needs OpenSpin and spinsim, which tests never need)::

    python tests/chip/tools/make_conformance.py [--openspin PATH] [--spinsim PATH] [NAME ...]

For each ``tests/data/chip/programs/NAME.spin`` it writes, next to it,

* ``NAME.binary``: the image OpenSpin 1.00.81 makes of it (``openspin -b``);
* ``NAME.expected.json``: what spinsim 0.99 (``-p``: the ROM interpreter on
  cycle-exact cogs, 80 MHz) shows when the program has ended: the SHA-256 of
  the 32 KB hub RAM and every non-zero long of the program's VAR area
  (``spinsim -d``: ``run``, then ``dumph``), and, from the instruction log
  (``-l``), the cycle its last cog stopped and the pin changes (cycle of the
  OUTA/DIRA-writing instruction + 4), for single-cog programs.

Only these results are stored: no log, no simulator or ROM code.
"""
from __future__ import annotations

import argparse
import glob
import hashlib
import json
import os
import re
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
PROGRAMS = os.path.join(ROOT, "tests", "data", "chip", "programs")
sys.path.insert(0, HERE)
import spinsim_log  # noqa: E402


def hub_dump(spinsim: str, image_path: str) -> bytes:
    r = subprocess.run([spinsim, "-p", "-d", image_path], input="run\ndumph 0\nexit\n",
                       capture_output=True, text=True, timeout=1200)
    mem = bytearray(0x8000)
    for a, v in re.findall(r"([0-9a-f]{8}) ([0-9a-f]{8})", r.stdout):
        a = int(a, 16)
        if a < 0x8000:
            mem[a:a + 4] = int(v, 16).to_bytes(4, "little")
    return bytes(mem)


def log_facts(spinsim: str, image_path: str, tmp: str):
    log = os.path.join(tmp, "run.log")
    spinsim_log.run_spinsim_log(spinsim, image_path, log, 40_000_000)
    cogs = spinsim_log.parse_log(log)
    end = 0
    for events in cogs.values():
        for cyc, addr, ins, flag, text in events:
            if flag == " " and " cogstop " in f" {text} ":
                end = max(end, cyc + 4)
    trace = None
    if len(cogs) == 1:
        dira = outa = 0
        trace = []
        for t, cog, reg, value in spinsim_log.pin_writes(cogs[0], 0):
            if reg == 0x1F4:
                outa = value
            else:
                dira = value
            state = [t, dira, dira & outa]
            if not trace or trace[-1][1:] != state[1:]:
                trace.append(state)
        if end and trace and trace[-1][1:] != [0, 0]:
            trace.append([end, 0, 0])           # the cog stopped: its pins float
    return end, trace


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("names", nargs="*")
    a = ap.parse_args(argv)
    names = a.names or sorted(os.path.splitext(os.path.basename(p))[0]
                              for p in glob.glob(os.path.join(PROGRAMS, "*.spin")))
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            src = os.path.join(PROGRAMS, name + ".spin")
            image_path = os.path.join(PROGRAMS, name + ".binary")
            r = subprocess.run([a.openspin, "-q", "-L", PROGRAMS, "-b", src, "-o", image_path],
                               capture_output=True, text=True)
            if r.returncode:
                print(f"{name}: does not compile: {r.stdout}{r.stderr}")
                continue
            image = open(image_path, "rb").read()
            hub = hub_dump(a.spinsim, image_path)
            vbase, dbase = struct.unpack_from("<HH", image, 8)
            var = {f"{addr:04x}": struct.unpack_from("<I", hub, addr)[0]
                   for addr in range(vbase, dbase - 8, 4) if struct.unpack_from("<I", hub, addr)[0]}
            end, trace = log_facts(a.spinsim, image_path, tmp)
            expected = {
                "source": "spinsim 0.99 -p, 80 MHz; see tests/data/README.md",
                "hub_sha256": hashlib.sha256(hub).hexdigest(),
                "var": var,
                "end_cycle": end,
            }
            if trace is not None:
                expected["trace"] = trace
            with open(os.path.join(PROGRAMS, name + ".expected.json"), "w") as f:
                json.dump(expected, f, indent=1)
                f.write("\n")
            print(f"{name}: end cycle {end}, {len(var)} VAR longs, "
                  f"{'no trace' if trace is None else f'{len(trace)} pin changes'}")


if __name__ == "__main__":
    main()
