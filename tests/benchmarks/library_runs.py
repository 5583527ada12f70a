#!/usr/bin/env python3
"""The Parallax library run as a new user runs it: ``spinemu run FILE``, the standard objects on SPINEMU_PATH.

Usage (needs the Parallax library; OpenSpin to tell which compile errors are genuine)::

    python tests/benchmarks/library_runs.py --sample 80 --seed 1       # a seeded random sample, 0.5 s each
    python tests/benchmarks/library_runs.py --all                      # every .spin file of the library
    python tests/benchmarks/library_runs.py --all --cycles 20000000    # every program for 20 M cycles
    python tests/benchmarks/library_runs.py --acceptance               # the serial console checks

The Propeller Tool's standard objects (FullDuplexSerial, Parallax Serial
Terminal, TV_Text, Graphics, Float32, ...: ``STANDARD_OBJECTS`` of
``spinemu.frontend.search``) are not in one folder of the library, but copies
lie beside many programs.  The script builds a "standard library" folder in a
temporary directory from the most common version of each (the one most copies
share), puts it on ``SPINEMU_PATH`` and runs library files as top objects,
each in its own process with a wall-time cap: ``python -m spinemu run FILE
--seconds 0.5`` (or ``--cycles N``) through ``spinemu.cli.main``.  Each file
ends up in one class:

* ``ran``: the run ended normally (cycle limit, all cogs stopped, deadlock);
  its warnings are counted by kind;
* ``compile: missing object`` / ``compile: missing data file``: a name found
  nowhere (objects the library does not have);
* ``compile: OpenSpin too``: an error OpenSpin also gives (with the same
  folders on its ``-L``), i.e. the file is not a program that compiles;
* ``compile: spinemu only``: OpenSpin compiles it and spinemu does not (a bug);
* ``fault``: the emulated program faulted (spinemu's runtime error, exit 1);
* ``INTERNAL``: a Python traceback, exit status 70, or a Python warning
  reaching the user (a bug);
* ``timeout``: the run took longer than the cap (wall time).

Warnings that say a feature is not emulated (``not emulated``, ``not
modelled``, ``not supported``) are counted apart as gaps.  The summary table
is followed by the worst cases.  ``--acceptance`` runs two programs of its
own through the console against the library's unchanged FullDuplexSerial and
Parallax Serial Terminal (found through SPINEMU_PATH): a hello world must print
exactly its text, and a number sent to the program must come back as the
program computes it.  Nothing of the library is copied into the repository.
Not part of the test run (it needs the library, which tests never use).
"""
from __future__ import annotations

import argparse
import collections
import hashlib
import io
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
import traceback
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

LIBRARY = "/opt/oracles/propeller/libraries"
OPENSPIN = "/opt/oracles/OpenSpin/build/openspin"

#: warning texts -> short kind names (the rest are shown by their first words)
WARNING_KINDS = [
    (re.compile(r"is spelled '.*' on disk"), "name in another letter case"),
    (re.compile(r"waitcnt for a count that passed"), "waitcnt-passed"),
    (re.compile(r"stack .*past|grows past|beyond the .*stack", re.I), "stack-overflow"),
    (re.compile(r"no free cog|all eight cogs", re.I), "no-free-cog"),
    (re.compile(r"drives? .* low while|pin conflict", re.I), "pin-conflict"),
    (re.compile(r"past the end of hub RAM"), "write-outside-hub"),
    (re.compile(r"changes the program's own code"), "write-into-code"),
    (re.compile(r"before it is assigned|leftover stack|read before", re.I), "uninitialized"),
    (re.compile(r"CLKSET"), "clock change"),
    (re.compile(r"PLL"), "PLL"),
    (re.compile(r"counter output edges exceed"), "counter edges capped"),
    (re.compile(r"APIN = BPIN"), "counter feedback loop"),
    (re.compile(r"hides|shadow", re.I), "object shadowed"),
]
GAP = re.compile(r"not (yet )?(emulated|modell?ed|supported|implemented)", re.I)


# ----------------------------------------------------------------------------- the standard folder
def spin_files(library: str) -> list:
    """Every .spin file of ``library`` once (symbolic links to files elsewhere in it are skipped)."""
    seen, out = set(), []
    for root, _dirs, names in os.walk(library):
        for n in sorted(names):
            if not n.lower().endswith(".spin"):
                continue
            path = os.path.join(root, n)
            real = os.path.realpath(path)
            if real not in seen and os.path.isfile(real):
                seen.add(real)
                out.append(real)
    return sorted(out)


def standard_versions(files: list) -> dict:
    """Standard object name -> list of ``(copies, sha256 prefix, a path)``, most common version first."""
    from spinemu.frontend.search import STANDARD_OBJECTS
    found: dict = collections.defaultdict(dict)
    for path in files:
        stem = os.path.basename(path)[:-5].lower()
        if stem in STANDARD_OBJECTS:
            with open(path, "rb") as fh:
                digest = hashlib.sha256(fh.read()).hexdigest()[:12]
            entry = found[STANDARD_OBJECTS[stem]].setdefault(digest, [0, path])
            entry[0] += 1
    # most copies first; a tie goes to the larger file (a later version mostly adds), then the digest
    return {name: sorted(((n, d, p) for d, (n, p) in versions.items()),
                         key=lambda v: (-v[0], -os.path.getsize(v[2]), v[1]))
            for name, versions in sorted(found.items())}


def build_standard_folder(files: list, dest: str) -> dict:
    """Copy the most common version of every standard object into ``dest`` under its usual spelling."""
    versions = standard_versions(files)
    os.makedirs(dest, exist_ok=True)
    for name, vs in versions.items():
        shutil.copyfile(vs[0][2], os.path.join(dest, name + ".spin"))
    return versions


# ----------------------------------------------------------------------------- one run (child process)
def classify_warning(text: str) -> str:
    if GAP.search(text):
        return "GAP: " + text[:90]
    for pattern, kind in WARNING_KINDS:
        if pattern.search(text):
            return kind
    return " ".join(text.split()[:6])


def _warning_texts(stderr: str) -> list:
    """The warnings a run printed: diagnostics (``file:line:col: warning: ...``) and chip warnings."""
    out = []
    for line in stderr.splitlines():
        m = re.match(r"^(?:.*?:\d+:\d+: )?warning: (.*)", line)
        if m:
            out.append(m.group(1))
    return out


def child(path: str, limit_args: list) -> dict:
    """Run ``path`` through the CLI as a user does (compiling it); everything that happened, as a dict.

    A run that fails is compiled once more on its own, to tell a compile error from a fault.
    """
    import warnings

    from spinemu import cli
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError

    res: dict = {"path": path}
    out, err = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(record=True) as pywarn:
        warnings.simplefilter("always")
        t1 = time.perf_counter()
        try:
            rc = cli.main(["run", path, "--no-progress", *limit_args], stdout=out, stderr=err)
        except BaseException:  # noqa: BLE001 -- what we look for
            res["class"] = "INTERNAL"
            res["detail"] = "run: " + traceback.format_exc(limit=-8)
            res["stderr"] = err.getvalue()[-2000:]
            return res
        res["run_s"] = time.perf_counter() - t1
        if rc == 1:
            try:
                compile_file(path)
            except SpinError as exc:
                res["class"] = "compile"
                res["detail"] = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
                return res
            except BaseException:  # noqa: BLE001
                pass
    stderr, stdout = err.getvalue(), out.getvalue()
    res["rc"] = rc
    res["pywarnings"] = [f"{w.category.__name__}: {w.message} ({os.path.basename(w.filename)}:{w.lineno})"
                         for w in pywarn]
    if rc == 70 or "Traceback (most recent call last)" in stderr + stdout:
        res["class"] = "INTERNAL"
        res["detail"] = stderr[-2000:]
    elif rc != 0:
        res["class"] = "fault"
        res["detail"] = stderr.strip().splitlines()[0] if stderr.strip() else f"exit status {rc}"
    elif res["pywarnings"]:
        res["class"] = "INTERNAL"
        res["detail"] = "Python warning: " + res["pywarnings"][0]
    else:
        res["class"] = "ran"
    res["warnings"] = [classify_warning(t) for t in _warning_texts(stderr)]
    m = re.search(r"^ended\s+(.+?)\s*$", stdout, re.M)
    res["ended"] = m.group(1) if m else ""
    m = re.search(r"^simulated\s+([\d.,]+) ms", stdout, re.M)
    res["sim_ms"] = float(m.group(1).replace(",", "")) if m else 0.0
    res["pasm"] = "PASM at" in stdout
    return res


# ----------------------------------------------------------------------------- the parent
def openspin_compiles(path: str, std: str, openspin: str) -> bool:
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "x.binary")
        try:
            r = subprocess.run([openspin, "-q", "-L", os.path.dirname(path), "-L", std, "-b", path, "-o", out],
                               capture_output=True, timeout=120)
        except subprocess.TimeoutExpired:
            return False
        return r.returncode == 0 and os.path.exists(out)


def run_one(path: str, limit_args: list, cap: float, env: dict, std: str, openspin: str) -> dict:
    t0 = time.perf_counter()
    cmd = [sys.executable, os.path.abspath(__file__), "--child", path, "--", *limit_args]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=cap, env=env,
                           cwd=tempfile.gettempdir())
    except subprocess.TimeoutExpired:
        return {"path": path, "class": "timeout", "detail": f"over {cap:g} s wall", "wall": cap}
    wall = time.perf_counter() - t0
    try:
        res = json.loads(r.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        res = {"path": path, "class": "INTERNAL",
               "detail": f"child exited {r.returncode}: {(r.stderr or r.stdout)[-1500:]}"}
    res["wall"] = wall
    if res["class"] == "compile":
        text = res["detail"]
        if "cannot find object file" in text:
            res["class"] = "compile: missing object"
            m = re.search(r"cannot find object file '([^']*)'", text)
            res["missing"] = m.group(1) if m else "?"
        elif "cannot find data file" in text:
            res["class"] = "compile: missing data file"
            m = re.search(r"cannot find data file '([^']*)'", text)
            res["missing"] = m.group(1) if m else "?"
        elif openspin and os.path.exists(openspin):
            res["class"] = "compile: spinemu only" if openspin_compiles(path, std, openspin) \
                else "compile: OpenSpin too"
        else:
            res["class"] = "compile: error"
    return res


ORDER = ["ran", "compile: missing object", "compile: missing data file", "compile: OpenSpin too",
         "compile: error", "compile: spinemu only", "fault", "timeout", "INTERNAL"]


def class_counts(results: list, order: list) -> list:
    """``(class, files)`` for each class that occurs: those of ``order`` first, in that order."""
    counts = collections.Counter(r["class"] for r in results)
    return [(c, counts[c]) for c in order + sorted(set(counts) - set(order)) if counts.get(c)]


def report(results: list, library: str, show: int, heading: str) -> int:
    """Print the summary table and the worst cases; the number of bad results (internal, gaps, spinemu-only)."""
    def rel(p):
        return os.path.relpath(p, library)
    n = len(results)
    print(f"\n{heading}: {n} files")
    print(f"{'class':30s} {'files':>6s} {'share':>7s}")
    for c, k in class_counts(results, ORDER):
        print(f"{c:30s} {k:6d} {100 * k / n:6.1f} %")
    ran = [r for r in results if r["class"] == "ran"]
    if ran:
        pasm = sum(1 for r in ran if r.get("pasm"))
        ended = collections.Counter(r.get("ended", "").split(":")[0] for r in ran)
        print(f"of the {len(ran)} that ran: {pasm} started a PASM cog; ended: "
              + ", ".join(f"{k} {v}" for k, v in ended.most_common()))
    kinds = collections.Counter(k for r in results for k in set(r.get("warnings", ())))
    if kinds:
        print("warnings (files that got each kind):")
        for k, v in kinds.most_common():
            print(f"  {v:5d}  {k}")
    missing = collections.Counter(r["missing"] for r in results if r.get("missing"))
    if missing:
        print("most missed names: " + ", ".join(f"{k} ({v})" for k, v in missing.most_common(10)))
    bad = [r for r in results if r["class"] in ("INTERNAL", "compile: spinemu only")]
    gaps = [r for r in results if any(w.startswith("GAP") for w in r.get("warnings", ()))]
    for title, rows in (("INTERNAL", [r for r in bad if r["class"] == "INTERNAL"]),
                        ("compile: spinemu only", [r for r in bad if r["class"] != "INTERNAL"]),
                        ("emulation gaps", gaps),
                        ("timeouts", [r for r in results if r["class"] == "timeout"]),
                        ("faults", [r for r in results if r["class"] == "fault"])):
        if rows:
            print(f"\n-- {title} ({len(rows)}):")
            for r in rows[:show]:
                detail = r.get("detail", "") if title != "emulation gaps" else \
                    "; ".join(w for w in r["warnings"] if w.startswith("GAP"))
                print(f"{rel(r['path'])}: {detail.strip()[-1200:]}")
    timed = sorted((r for r in results if "wall" in r and r["class"] != "timeout"), key=lambda r: -r["wall"])
    if timed:
        print(f"\n-- slowest ({min(show, len(timed))} of {len(timed)}):")
        for r in timed[:min(show, 10)]:
            print(f"  {r['wall']:7.1f} s  {r['class']:10s} {rel(r['path'])}")
    return len(bad) + len(gaps)


def sweep(a) -> int:
    files = spin_files(a.library)
    tmp = tempfile.mkdtemp(prefix="spinemu-stdlib-")
    try:
        std = os.path.join(tmp, "Library")
        versions = build_standard_folder(files, std)
        print(f"standard library folder: {len(versions)} objects from the library's copies "
              f"({sum(sum(v[0] for v in vs) for vs in versions.values())} copies, "
              f"{sum(len(vs) for vs in versions.values())} versions); on SPINEMU_PATH")
        if a.list_standard:
            for name, vs in versions.items():
                print(f"  {name}: {vs[0][0]} of {sum(v[0] for v in vs)} copies ({len(vs)} versions) "
                      f"from {os.path.relpath(vs[0][2], a.library)}")
        if a.files:
            chosen = [os.path.abspath(f) for f in a.files]
        elif a.all:
            chosen = files
        else:
            chosen = random.Random(a.seed).sample(files, min(a.sample, len(files)))
        env = dict(os.environ, SPINEMU_PATH=std, COLUMNS="200", PYTHONPATH=ROOT)
        limit = ["--cycles", str(a.cycles)] if a.cycles else ["--seconds", str(a.seconds)]
        heading = (f"{'every file' if a.all else f'sample of {len(chosen)} (seed {a.seed})'}, "
                   f"{'%d cycles' % a.cycles if a.cycles else '%g s' % a.seconds} each, cap {a.cap:g} s wall")
        results = []
        t0 = time.perf_counter()
        with ThreadPoolExecutor(a.jobs) as pool:
            for i, r in enumerate(pool.map(lambda p: run_one(p, limit, a.cap, env, std, a.openspin), chosen)):
                results.append(r)
                if a.verbose:
                    print(f"[{i + 1}/{len(chosen)}] {r['class']:26s} {r.get('wall', 0):6.1f} s "
                          f"{os.path.relpath(r['path'], a.library)}", flush=True)
        if a.json:
            with open(a.json, "w") as fh:
                json.dump(results, fh, indent=1)
        bad = report(results, a.library, a.show, heading)
        print(f"\n{len(chosen)} files in {time.perf_counter() - t0:.0f} s wall ({a.jobs} jobs); "
              f"{bad} bad (internal errors, emulation gaps, compile errors OpenSpin does not give)")
        return 1 if bad else 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


# ----------------------------------------------------------------------------- acceptance: the console
HEAD = "CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"

#: name -> (program, console input or None, --console-in-at, seconds, expected console text)
ACCEPTANCE = {
    "FullDuplexSerial hello": (HEAD + textwrap.dedent("""\
        OBJ
          ser : "FullDuplexSerial"
        PUB main
          ser.start(31, 30, 0, 115200)
          ser.str(string("Hello from FullDuplexSerial!", 13, 10))
          ser.dec(-2024)
          ser.tx(32)
          ser.hex($BEEF, 4)
          ser.tx(13)
          waitcnt(cnt + clkfreq / 100)
        """), None, None, 0.1, "Hello from FullDuplexSerial!\r\n-2024 BEEF\r"),
    "Parallax Serial Terminal hello": (HEAD + textwrap.dedent("""\
        OBJ
          pst : "Parallax Serial Terminal"
        PUB main
          pst.Start(115200)
          pst.Str(string("Hello from PST", pst#NL))
          pst.Dec(12345)
          pst.Char(pst#NL)
          waitcnt(cnt + clkfreq / 100)
        """), None, None, 1.2, "\x10Hello from PST\r12345\r"),     # Start clears the screen (CS, 16)
    # FullDuplexSerial has no number input: the program reads digits itself
    "FullDuplexSerial number in": (HEAD + textwrap.dedent("""\
        OBJ
          ser : "FullDuplexSerial"
        PUB main | n, c
          ser.start(31, 30, 0, 115200)
          ser.str(string("n? "))
          n := 0
          repeat while (c := ser.rx) <> 13
            n := n * 10 + c - "0"
          ser.str(string("n*n+7 = "))
          ser.dec(n * n + 7)
          ser.tx(13)
          waitcnt(cnt + clkfreq / 100)
        """), b"1234\r", 0.05, 0.3, "n? n*n+7 = %d\r" % (1234 * 1234 + 7)),
    # Parallax Serial Terminal's DecIn; Start waits a second before it returns
    "Parallax Serial Terminal number in": (HEAD + textwrap.dedent("""\
        OBJ
          pst : "Parallax Serial Terminal"
        PUB main | n
          pst.Start(115200)
          pst.Str(string("Number? "))
          n := pst.DecIn
          pst.Str(string("3n-1 = "))
          pst.Dec(3 * n - 1)
          pst.Char(pst#NL)
          waitcnt(cnt + clkfreq / 100)
        """), b"-417\r", 1.1, 1.3, "\x10Number? 3n-1 = %d\r" % (3 * -417 - 1)),
}


def acceptance(a) -> int:
    from spinemu import cli
    files = spin_files(a.library)
    failures = 0
    with tempfile.TemporaryDirectory(prefix="spinemu-accept-") as tmp:
        std = os.path.join(tmp, "Library")
        build_standard_folder(files, std)
        old = os.environ.get("SPINEMU_PATH")
        os.environ["SPINEMU_PATH"] = std
        try:
            for i, (name, (program, data, at, seconds, expect)) in enumerate(ACCEPTANCE.items()):
                src = os.path.join(tmp, f"accept{i}.spin")
                with open(src, "w") as fh:
                    fh.write(program)
                got_path = os.path.join(tmp, f"accept{i}.out")
                argv = ["run", src, "--seconds", str(seconds), "--console-out", got_path, "--quiet"]
                if data is not None:
                    in_path = os.path.join(tmp, f"accept{i}.in")
                    with open(in_path, "wb") as fh:
                        fh.write(data)
                    argv += ["--console-in", in_path, "--console-in-at", str(at)]
                out, err = io.StringIO(), io.StringIO()
                t0 = time.perf_counter()
                rc = cli.main(argv, stdout=out, stderr=err)
                wall = time.perf_counter() - t0
                got = open(got_path, "rb").read().decode("latin-1") if os.path.exists(got_path) else ""
                ok = rc == 0 and got == expect
                failures += not ok
                print(f"{'PASS' if ok else 'FAIL'}  {name}: console {got!r}"
                      + ("" if ok else f", expected {expect!r} (exit {rc}) {err.getvalue()[-400:]}")
                      + f"  [{seconds:g} s simulated, {wall:.1f} s wall]")
        finally:
            if old is None:
                os.environ.pop("SPINEMU_PATH", None)
            else:
                os.environ["SPINEMU_PATH"] = old
    return 1 if failures else 0


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--child"]:
        res = child(argv[1], argv[3:])
        sys.stdout.write("\n" + json.dumps(res) + "\n")
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", default=LIBRARY)
    ap.add_argument("--openspin", default=OPENSPIN, help="to tell genuine compile errors ('' to skip)")
    ap.add_argument("--sample", type=int, default=80, help="files picked at random (default 80)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--all", action="store_true", help="every .spin file of the library")
    ap.add_argument("--seconds", type=float, default=0.5, help="simulated seconds per run (default 0.5)")
    ap.add_argument("--cycles", type=int, help="cycles per run instead of --seconds (e.g. 20000000)")
    ap.add_argument("--cap", type=float, default=300, help="wall seconds per file before it counts as a timeout")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--show", type=int, default=20, help="worst cases shown per class")
    ap.add_argument("--json", help="write every result to this file")
    ap.add_argument("--verbose", "-v", action="store_true", help="a line per file as it finishes")
    ap.add_argument("--list-standard", action="store_true", help="say which copy of each standard object is used")
    ap.add_argument("--acceptance", action="store_true", help="the serial console checks instead of a sweep")
    ap.add_argument("files", nargs="*", help="run these files instead of a sample")
    a = ap.parse_args(argv)
    a.library = os.path.realpath(a.library)         # paths of files are real paths too
    return acceptance(a) if a.acceptance else sweep(a)


if __name__ == "__main__":
    sys.exit(main())
