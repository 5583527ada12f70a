"""The caches of ``spinemu run`` on programs nobody here wrote (run on demand).

Usage::

    python tests/benchmarks/cache_campaign.py --seed 1 --sample 40 [--library DIR] [--cycles N]

Picks ``--sample`` random ``.spin`` files of the library and runs each three
times with the ``spinemu`` of this Python, in the file's own folder, with a
fresh cache folder: once with ``--no-cache``, then twice with the caches (the
first fills the compiled-program and code caches, the second takes the
program and its blocks from them).  The three runs must print the same
summary (the speed line apart), the same hints and runtime warnings, and
write the same pin trace; a file that does not compile must fail the same
way each time.  Not part of the test run (it needs the Parallax library).
"""
from __future__ import annotations

import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

LIB = "/opt/oracles/propeller/libraries/community/p1/All"


def run(path: str, extra: list, cache: str, cycles: int) -> tuple:
    out = os.path.join(cache, "trace.log")
    env = dict(os.environ, SPINEMU_CACHE_DIR=cache)
    env.pop("SPINEMU_CACHE", None)
    r = subprocess.run([sys.executable, "-m", "spinemu", "run", path, "--cycles", str(cycles), "--trace", out,
                        "--no-progress", *extra], capture_output=True, text=True, errors="replace", env=env,
                       cwd=os.path.dirname(path), timeout=600)
    trace = None
    if os.path.exists(out):
        with open(out, encoding="utf-8") as f:
            trace = f.read()
        os.unlink(out)
    return r.returncode, re.sub(r"speed .*\n", "", r.stdout), r.stderr, trace


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", default=LIB)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--sample", type=int, default=40)
    ap.add_argument("--cycles", type=int, default=3_000_000)
    a = ap.parse_args(argv)
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.library) for f in fs if f.endswith(".spin"))
    chosen = random.Random(a.seed).sample(files, min(a.sample, len(files)))
    same = failed = 0
    for path in chosen:
        cache = tempfile.mkdtemp(prefix="spinemu-cache-campaign-")
        try:
            runs = [run(path, extra, cache, a.cycles) for extra in (["--no-cache"], [], [])]
        except subprocess.TimeoutExpired:
            print(f"timeout: {path}")
            continue
        finally:
            shutil.rmtree(cache, ignore_errors=True)
        failed += runs[0][0] != 0
        if runs[0] == runs[1] == runs[2]:
            same += 1
        else:
            what = [name for k, name in enumerate(("status", "summary", "messages", "trace"), 0)
                    if not runs[0][k] == runs[1][k] == runs[2][k]]
            print(f"DIFFERENT ({', '.join(what)}): {path}", flush=True)
    print(f"seed {a.seed}: {len(chosen)} programs, {same} the same all three times "
          f"({failed} of them do not compile or fail), {len(chosen) - same} different")
    return 0 if same == len(chosen) else 1


if __name__ == "__main__":
    sys.exit(main())
