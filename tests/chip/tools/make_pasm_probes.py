#!/usr/bin/env python3
"""Record what spinsim does with the PASM probe programs (tests/data/chip/pasm/*.spin).

Usage (from the worktree root; needs OpenSpin and spinsim, which tests never need)::

    python tests/chip/tools/make_pasm_probes.py [--openspin PATH] [--spinsim PATH] [NAME ...]

For each ``tests/data/chip/pasm/NAME.spin`` (spinemu's own probe programs;
each ends with every cog stopped) it writes, next to it,

* ``NAME.binary``: the image OpenSpin 1.00.81 makes of it (``openspin -b``);
* ``NAME.expected.json``: what spinsim 0.99 ``-p`` (cycle-exact cogs, 80 MHz)
  shows: for every cog that runs PASM, each instruction it executed (first
  cycle, cog address, long, whether its condition held, the value it wrote,
  Z and C when it had ``wz``/``wc``; from the instruction log, ``-l``), the
  pin changes of all cogs (an OUTA/DIRA write at its cycle + 4, a stopped
  cog floating at the COGSTOP's cycle + 4), the cycle the last cog stopped,
  and the SHA-256 of the 32 KB hub RAM then (``-d``: ``run``, ``dumph``).

Which cogs run PASM is taken from spinemu's own run of the image (their
starts say "PASM"); only spinsim's output is recorded, no log, no ROM code.
"""
from __future__ import annotations

import argparse
import glob
import hashlib
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
PROBES = os.path.join(ROOT, "tests", "data", "chip", "pasm")
sys.path.insert(0, HERE)
sys.path.insert(0, ROOT)
import spinsim_log  # noqa: E402
from make_conformance import hub_dump  # noqa: E402

from spinemu.chip import Chip  # noqa: E402

#: instructions kept per cog (the probes' interesting part comes first)
MAX_STEPS = 1500
#: instructions spinsim may execute (all cogs) before a probe counts as not ending
MAX_INSTRUCTIONS = 2_000_000


def pasm_cogs(image: bytes) -> list:
    """Cogs every start of which is PASM in spinemu's run of ``image``."""
    result = Chip(image).run(max_cycles=50_000_000)
    starts: dict = {}
    for _cycle, cog, kind, detail in result.cog_events:
        if kind == "start":
            starts.setdefault(cog, set()).add(detail.startswith("PASM"))
    return sorted(k for k, kinds in starts.items() if kinds == {True})


def record(name: str, openspin: str, spinsim: str, tmp: str) -> dict:
    src = os.path.join(PROBES, name + ".spin")
    image_path = os.path.join(PROBES, name + ".binary")
    r = subprocess.run([openspin, "-q", "-b", src, "-o", image_path], capture_output=True, text=True)
    if r.returncode:
        raise SystemExit(f"{name}: does not compile: {r.stdout}{r.stderr}")
    image = open(image_path, "rb").read()
    log = os.path.join(tmp, name + ".log")
    subprocess.run([spinsim, "-p", "-l", log, f"-{MAX_INSTRUCTIONS}", image_path],
                   capture_output=True, timeout=1200, check=False)
    cogs = spinsim_log.parse_log(log)
    end = max(line[0] for lines in cogs.values() for line in lines) + 4
    steps = {str(k): spinsim_log.pasm_steps(cogs.get(k, []))[:MAX_STEPS] for k in pasm_cogs(image)}
    pins = [list(p) for p in spinsim_log.pin_trace(cogs) if p[0] <= end]
    hub = hub_dump(spinsim, image_path)
    return {"source": "spinsim 0.99 -p, 80 MHz; see tests/data/README.md",
            "end_cycle": end, "hub_sha256": hashlib.sha256(hub).hexdigest(),
            "pins": pins, "steps": steps}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("names", nargs="*")
    a = ap.parse_args(argv)
    names = a.names or sorted(os.path.splitext(os.path.basename(p))[0]
                              for p in glob.glob(os.path.join(PROBES, "*.spin")))
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            expected = record(name, a.openspin, a.spinsim, tmp)
            with open(os.path.join(PROBES, name + ".expected.json"), "w") as f:
                json.dump(expected, f, separators=(",", ":"))
                f.write("\n")
            counts = {k: len(v) for k, v in expected["steps"].items()}
            print(f"{name}: end cycle {expected['end_cycle']}, instructions per cog {counts}, "
                  f"{len(expected['pins'])} pin changes")


if __name__ == "__main__":
    main()
