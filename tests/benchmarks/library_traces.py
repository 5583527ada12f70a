#!/usr/bin/env python3
"""Library programs on spinemu and on spinsim 0.99: pin traces compared (run on demand).

Usage (needs OpenSpin, spinsim and the Parallax library under /opt/oracles)::

    python tests/benchmarks/library_traces.py --sample 40 --seed 2811 --jobs 1
    python tests/benchmarks/library_traces.py --cycles 1000000 FILE.spin ...   # these files only
    python tests/benchmarks/library_traces.py --list                           # the candidates, no runs

Top-level programs: the library's ``.spin`` files (once each, as
``library_runs.spin_files`` finds them) that set ``_clkmode`` or ``_xinfreq``
in a CON block and have a PUB method (objects used by others rarely set the
clock).  The standard objects (FullDuplexSerial, ...) come from the folder
``library_runs.build_standard_folder`` builds from the library's copies; it is
on OpenSpin's ``-L`` after the file's own folder, and on spinemu's include path.
OpenSpin on Linux matches object names letter by letter: a name it misses only by
letter case (``"tv"`` for ``TV.spin``) is copied under the spelling asked for into
a folder on its ``-L`` (as the Propeller Tool and spinemu find it).

Each program is compiled with OpenSpin and with spinemu; when the images are
identical it runs for ``--cycles`` cycles on spinsim ``-p`` (pins from its
instruction log, streamed and never stored: ``pasm_drivers.spinsim_trace``, which
this script extends with the pins a cog releases when it stops or is restarted)
and on spinemu (``Chip(image)``, compat "spinsim"), each program in a child
process with a wall-time cap.  The traces are compared up to 100 cycles before
the limit (a write near the end shows on one side only) with
``compare_traces``.  Classes:

* ``identical``: same sequence of pin states and the same cycles (or within
  0.5 % timing error: the largest offset is printed);
* ``differs``: first differing change (cycle on each side, pins that differ)
  or a timing error over 0.5 %;
* ``not comparable``: spinsim has no counter modules and no video: a program
  that set a counter mode (CTRA/CTRB) or a video mode (VCFG), or ran WAITVID,
  on spinemu is left out (its result is still shown); without video, the
  traces are still compared up to the first counter mode, and a difference
  before it counts as ``differs``;
* ``spinsim error``: spinsim printed an error or logged nothing;
* ``compile problem``: OpenSpin or spinemu fails, or the images differ;
* ``timeout``: over the wall cap.

Exits 1 if any program differs.
"""
from __future__ import annotations

import argparse
import collections
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, ROOT)
sys.path.insert(0, HERE)

import library_runs  # noqa: E402
import pasm_drivers  # noqa: E402

LIB = pasm_drivers.LIB
CLKMODE = re.compile(r"^\s*_(clkmode|xinfreq)\s*=", re.I | re.M)
PUB = re.compile(r"^pub\b", re.I | re.M)
MISSING = re.compile(r"^(.*?) : error : Can not find/open file", re.M)
CLASSES = ["identical", "differs", "not comparable", "spinsim error", "compile problem", "timeout", "INTERNAL"]


def top_level(path: str) -> bool:
    try:
        text = open(path, "rb").read()
    except OSError:
        return False
    for enc in ("utf-16",) if text[:2] in (b"\xff\xfe", b"\xfe\xff") else ("latin-1",):
        text = text.decode(enc, errors="replace")
    return bool(CLKMODE.search(text) and PUB.search(text))


def shown(path: str, library: str) -> str:
    """``path`` relative to the library when it lies in it."""
    return os.path.relpath(path, library) if path.startswith(library + os.sep) else path


def pins_of(mask: int) -> str:
    return ",".join(f"P{i}" for i in range(32) if mask >> i & 1) or "-"


# ----------------------------------------------------------------------------- child: one program
def compile_pair(path: str, std: str, tmp: str):
    """The image if OpenSpin and spinemu agree, else ``(None, why)``."""
    from spinemu.compiler import compile_file
    out = os.path.join(tmp, "main.binary")
    folder = os.path.dirname(path)
    alias = os.path.join(tmp, "alias")     # names OpenSpin misses only by letter case (it matches
    os.makedirs(alias, exist_ok=True)      # them exactly on Linux; the Propeller Tool and spinemu don't)
    for _ in range(12):
        try:
            r = subprocess.run([pasm_drivers.OPENSPIN, "-q", "-L", folder, "-L", std, "-L", alias, "-b", path,
                                "-o", out], capture_output=True, text=True, errors="replace", timeout=120)
        except subprocess.TimeoutExpired:
            return None, "OpenSpin timed out"
        if not r.returncode and os.path.exists(out):
            break
        m = MISSING.search(r.stdout + r.stderr)
        name = os.path.basename(m.group(1).strip()) if m else ""
        hit = next((os.path.join(d, n) for d in (folder, std) for n in sorted(os.listdir(d))
                    if n.lower() == name.lower() and os.path.isfile(os.path.join(d, n))), None)
        if not name or hit is None or os.path.exists(os.path.join(alias, name)):
            return None, "OpenSpin: " + ((r.stdout + r.stderr).strip().splitlines() or ["failed"])[-1][:160]
        shutil.copyfile(hit, os.path.join(alias, name))
    image = open(out, "rb").read()
    try:
        ours = compile_file(path, include_dirs=[folder, std]).binary
    except Exception as exc:  # noqa: BLE001 -- a class of its own
        return None, f"spinemu only: {type(exc).__name__}: {str(exc).splitlines()[0][:160] if str(exc) else ''}"
    if ours != image:
        n = next((i for i in range(min(len(ours), len(image))) if ours[i] != image[i]), min(len(ours), len(image)))
        return None, f"images differ ({len(image)} / {len(ours)} bytes, first at ${n:04X})"
    return image, out


def spinsim_trace(image_path: str, cycles: int, err):
    """``pasm_drivers.spinsim_trace`` plus cog stops and restarts: a cog that stops (COGSTOP) or is
    restarted (COGINIT of a running cog) releases its DIRA/OUTA, as on the chip and on spinemu.

    The stopped cog's id is the value of COGSTOP's D register, known from the last logged write to
    that register in the same cog (``R=``); an id not known so is skipped.
    """
    from spinemu.trace import PinTrace
    proc = subprocess.Popen([pasm_drivers.SPINSIM, "-p", "-l", "/dev/stdout", f"-{cycles}", image_path],
                            stdout=subprocess.PIPE, stderr=err, text=True, errors="replace")
    drive: dict = {}
    regs: dict = collections.defaultdict(dict)
    trace = PinTrace(pasm_drivers.CLOCK)
    trace.record(0, 0, 0)
    logged = 0

    def put(cyc):
        dirs = outs = 0
        for dd, oo in drive.values():
            dirs |= dd
            outs |= dd & oo
        trace.record(cyc + 4, dirs, outs)
    for line in proc.stdout:
        m = pasm_drivers.LINE.match(line)
        if not m:
            continue
        logged += 1
        cog, cyc, ins, flag, r = m.groups()
        cyc, cog = int(cyc), int(cog)
        if cyc > cycles:
            break
        if flag != " ":
            continue
        word = int(ins, 16)
        dest = (word >> 9) & 0x1FF
        if word >> 26 == 3 and word & (1 << 22) and word & 0x1FF in (2, 3):     # COGINIT, COGSTOP
            target = regs[cog].get(dest)
            if (word & 0x1FF) == 2 and target is not None and target & 8:
                target = None                   # COGNEW: a free cog, nothing driven
            if target is not None and (target & 7) in drive:
                del drive[target & 7]
                put(cyc)
        if r is None:
            continue
        regs[cog][dest] = int(r, 16)
        if dest in (0x1F4, 0x1F6) and word & (1 << 23):
            d = drive.setdefault(cog, [0, 0])
            d[0 if dest == 0x1F6 else 1] = int(r, 16)
            put(cyc)
    proc.kill()
    proc.wait()
    return trace, logged


def spinsim_run(image_path: str, cycles: int, tmp: str):
    """spinsim's pin trace with its stderr caught in a file: (trace, lines logged, stderr text)."""
    err_path = os.path.join(tmp, "spinsim.err")
    with open(err_path, "w") as fh:
        trace, logged = spinsim_trace(image_path, cycles, fh)
    return trace, logged, open(err_path, errors="replace").read()


def uses_counters_or_video(chip) -> list:
    why = []
    if chip.counters_on:
        why.append("counter output mode")
    try:
        modes = {seg.mode for pair in chip.counters.units for unit in pair for seg in unit.segs if seg.mode}
        if modes and not chip.counters_on:
            why.append("counter mode %s" % ",".join(f"%{m:05b}" for m in sorted(modes)))
    except AttributeError:
        pass
    if any((c.vcfg >> 29) & 3 for c in chip.cogs):
        why.append("video mode (VCFG)")
    if any(getattr(chip, "_video_ready", [0])):
        why.append("WAITVID")
    return why


def first_difference(r_states: list, c_states: list):
    """The first state change that differs in state or cycle (index, both sides, pins), or None."""
    n = min(len(r_states), len(c_states))
    k = next((i for i in range(n) if r_states[i] != c_states[i]), None)
    if k is None and len(r_states) != len(c_states):
        k = n
    if k is None:
        return None
    r = r_states[k] if k < len(r_states) else None
    c = c_states[k] if k < len(c_states) else None
    prev = r_states[k - 1] if k else (0, 0, 0)
    if r and c:
        diff = (r[1] ^ c[1]) | (r[2] ^ c[2])
        if not diff:                    # same state at another cycle: the pins that change there
            diff = (r[1] ^ prev[1]) | (r[2] ^ prev[2])
    else:
        diff = ((r or c)[1] ^ prev[1]) | ((r or c)[2] ^ prev[2])
    return {"index": k, "spinsim": r, "spinemu": c, "pins": pins_of(diff)}


def describe(f: dict) -> str:
    def fmt(s):
        return "none" if s is None else f"cycle {s[0]} dir {s[1]:08x} out {s[2]:08x}"
    return f"change #{f['index']} ({f['pins']}): spinsim {fmt(f['spinsim'])}; spinemu {fmt(f['spinemu'])}"


def child(path: str, std: str, cycles: int) -> dict:
    from spinemu.chip import Chip
    from spinemu.analysis.compare import compare_traces, state_changes
    from spinemu.trace import PinTrace
    res: dict = {"path": path}
    with tempfile.TemporaryDirectory(prefix="spinemu-libtrace-") as tmp:
        image, why = compile_pair(path, std, tmp)
        if image is None:
            res.update({"class": "compile problem", "detail": why})
            return res
        t0 = time.perf_counter()
        ref, logged, err = spinsim_run(why, cycles, tmp)
        res["spinsim_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    chip = Chip(image)
    result = chip.run(max_cycles=cycles)
    res["spinemu_s"] = time.perf_counter() - t0
    res["ended"] = result.reason
    until = cycles - 100
    cand = PinTrace(pasm_drivers.CLOCK, [c for c in result.trace.changes if c[0] <= until])
    ref = PinTrace(pasm_drivers.CLOCK, [c for c in ref.changes if c[0] <= until])
    cmp = compare_traces(ref, cand)
    r_states, c_states = state_changes(ref), state_changes(cand)
    res["changes"] = [len(r_states), len(c_states)]
    res["largest_offset"] = cmp.largest_offset
    res["worst_error"] = cmp.worst_error
    res["first"] = first_difference(r_states, c_states)
    why_not = uses_counters_or_video(chip)
    state_same = cmp.identical
    k = None if res["first"] is None else res["first"]["index"]
    counter_t0 = early = None
    compared_early = False
    if why_not:             # the traces can still be compared up to the first counter mode
        try:
            counter_t0 = min((seg.t0 for pair in chip.counters.units for unit in pair for seg in unit.segs
                              if seg.mode), default=None)
        except AttributeError:
            pass
        compared_early = counter_t0 is not None and not any("vid" in w.lower() for w in why_not)
        if compared_early:
            # (up to the cycle before: a pin may follow the counter from the cycle its mode is set)
            early = first_difference(state_changes(ref, counter_t0 - 1), state_changes(cand, counter_t0 - 1))
    if "error" in err.lower() or not logged:
        res["class"] = "spinsim error"
        res["detail"] = err.strip().splitlines()[-1][:200] if err.strip() else "?"
    elif why_not and not (counter_t0 is not None and early is not None):
        res["class"] = "not comparable"
        res["detail"] = "; ".join(why_not) + (" (traces %s" % ("agree" if res["first"] is None else "differ")
                                              + (f"; same up to the first counter mode at cycle {counter_t0})"
                                                 if compared_early else ")"))
    elif why_not:
        res["class"] = "differs"
        res["first"] = early
        res["detail"] = describe(early) + f" (before the first counter mode, at cycle {counter_t0})"
    elif state_same and cmp.worst_error <= 0.005:
        res["class"] = "identical"
        res["detail"] = (f"{len(r_states)} changes, " +
                         ("same cycles" if k is None else
                          f"same states; timing off from change #{k} (largest offset {cmp.largest_offset})"))
    else:
        res["class"] = "differs"
        f = res.get("first")
        res["detail"] = f"timing error {cmp.worst_error:.3%}" if f is None else describe(f)
    return res


# ----------------------------------------------------------------------------- parent
def run_one(path: str, std: str, cycles: int, cap: float) -> dict:
    cmd = [sys.executable, os.path.abspath(__file__), "--child", path, std, str(cycles)]
    t0 = time.perf_counter()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=cap,
                           cwd=tempfile.gettempdir())
    except subprocess.TimeoutExpired:
        return {"path": path, "class": "timeout", "detail": f"over {cap:g} s wall", "wall": cap}
    try:
        res = json.loads(r.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        res = {"path": path, "class": "INTERNAL",
               "detail": f"child exited {r.returncode}: {(r.stderr or r.stdout)[-600:]}"}
    res["wall"] = time.perf_counter() - t0
    return res


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--child"]:
        sys.stdout.write("\n" + json.dumps(child(argv[1], argv[2], int(argv[3]))) + "\n")
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", default=LIB)
    ap.add_argument("--sample", type=int, default=40, help="programs picked at random (default 40)")
    ap.add_argument("--seed", type=int, default=2811)
    ap.add_argument("--cycles", type=int, default=4_000_000)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--cap", type=float, default=600, help="wall seconds per program")
    ap.add_argument("--json", help="write every result to this file")
    ap.add_argument("--list", action="store_true", help="print the sampled files and stop")
    ap.add_argument("files", nargs="*", help="compare these files instead of a sample")
    a = ap.parse_args(argv)
    library = os.path.realpath(a.library)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))     # so the temporary folder goes too
    files = library_runs.spin_files(library)
    tmp = tempfile.mkdtemp(prefix="spinemu-libtrace-std-")
    try:
        std = os.path.join(tmp, "Library")
        library_runs.build_standard_folder(files, std)
        if a.files:
            chosen = [os.path.realpath(f) for f in a.files]
            heading = f"{len(chosen)} files"
        else:
            tops = [f for f in files if top_level(f)]
            chosen = random.Random(a.seed).sample(tops, min(a.sample, len(tops)))
            heading = f"sample of {len(chosen)} of {len(tops)} top-level programs (seed {a.seed})"
        if a.list:
            print("\n".join(shown(p, library) for p in chosen))
            return 0
        print(f"{heading}, {a.cycles:,} cycles each", flush=True)
        results = []
        t0 = time.perf_counter()
        with ThreadPoolExecutor(a.jobs) as pool:
            for i, r in enumerate(pool.map(lambda p: run_one(p, std, a.cycles, a.cap), chosen)):
                results.append(r)
                print(f"[{i + 1}/{len(chosen)}] {r['class']:16s} {r.get('wall', 0):6.1f} s "
                      f"{shown(r['path'], library)}: {r.get('detail', '')}", flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(results, fh, indent=1)
    print(f"\n{heading}, {a.cycles:,} cycles each, {time.perf_counter() - t0:.0f} s wall ({a.jobs} jobs)")
    print(f"{'class':16s} {'files':>5s}")
    for c, k in library_runs.class_counts(results, CLASSES):
        print(f"{c:16s} {k:5d}")
    for c in ("differs", "not comparable", "spinsim error", "compile problem", "timeout", "INTERNAL"):
        rows = [r for r in results if r["class"] == c]
        if rows:
            print(f"\n-- {c} ({len(rows)}):")
            for r in rows:
                print(f"  {shown(r['path'], library)}: {r.get('detail', '')}")
    return 1 if any(r["class"] == "differs" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
