"""Byte identity at scale: compile a library of .spin files with OpenSpin and with spinemu.

Usage::

    python tests/benchmarks/corpus.py --library /opt/oracles/propeller \\
        --openspin /opt/oracles/OpenSpin/build/openspin [--jobs 2] [--limit N] [--show 30]

Every .spin file is compiled as a top object by both compilers.  The report
gives the share of files whose images are byte-identical (of those OpenSpin
compiles); for the others, the first differing byte and the source line and
method there; and for the files OpenSpin rejects, whether spinemu rejects
them too, and on the same line.  Not part of the test run (it needs OpenSpin
and the library, which tests never use).
"""
from __future__ import annotations

import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", ".."))

_ERR_RE = re.compile(r"^(.*)\((\d+):(\d+)\) : error : (.*)", re.M)


def openspin(exe: str, path: str, out_dir: str):
    out = os.path.join(out_dir, "ref.binary")
    try:
        r = subprocess.run([exe, "-q", "-b", path, "-o", out], capture_output=True, text=True,
                           errors="replace", timeout=60)
    except subprocess.TimeoutExpired:
        return None, (None, "timeout", None)
    if r.returncode == 0 and os.path.exists(out):
        with open(out, "rb") as fh:
            return fh.read(), None
    text = r.stdout + r.stderr
    m = _ERR_RE.search(text)
    if m:
        return None, (int(m.group(2)), m.group(4).strip(), m.group(1))
    first = text.strip().splitlines()[:1]
    return None, (None, first[0] if first else f"exit status {r.returncode}", None)


def where(prog, addr: int) -> str:
    """The object, method and source line that made hub byte ``addr``."""
    for cobj in prog.objects:
        base = prog.addresses[id(cobj.unit)]
        if base <= addr < base + cobj.size:
            off = addr - base
            name = os.path.basename(cobj.unit.path)
            if off < 4 * (1 + cobj.n_methods + len(cobj.instances)):
                return f"{name}: object table +{off}"
            if off < cobj.methods[0].offset if cobj.methods else True:
                line = prog.line_table(addr)
                return f"{name}: DAT" + (f" line {line[1]}" if line else "")
            for m in cobj.methods:
                if m.offset <= off < m.end:
                    line = prog.line_table(addr)
                    text = ""
                    if line:
                        src = cobj.unit.spin.source.line(line[1]) or ""
                        text = f" line {line[1]}: {src.strip()[:60]}"
                    return f"{name}: method {m.name}{text}"
            return f"{name}: +{off}"
    return "header" if addr < 16 else "?"


def one(args):
    path, exe = args
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError
    with tempfile.TemporaryDirectory() as tmp:
        ref, ref_err = openspin(exe, path, tmp)
    t0 = time.perf_counter()
    mine = err = None
    prog = None
    try:
        prog = compile_file(path)
        mine = prog.binary
    except SpinError as exc:
        err = (exc.line, exc.message)
        lines = {(os.path.realpath(d.path), d.line) for d in exc.diagnostics if d.path}
        missing = any("cannot find" in d.message or "is empty" in d.message for d in exc.diagnostics)
    except Exception as exc:  # a crash is a finding too
        err = (None, f"CRASH {type(exc).__name__}: {exc}")
    elapsed = time.perf_counter() - t0
    res = {"path": path, "time": elapsed}
    if ref is not None:
        if mine == ref:
            res["status"] = "identical"
        elif mine is None:
            res["status"] = "rejected-by-spinemu"
            res["detail"] = f"line {err[0]}: {err[1]}"
        else:
            n = min(len(mine), len(ref))
            i = next((k for k in range(n) if mine[k] != ref[k] and k != 5), n)
            res["status"] = "different"
            res["detail"] = (f"sizes {len(mine)}/{len(ref)}, first difference at ${i:04X} "
                             f"(spinemu {mine[i:i+6].hex()} / OpenSpin {ref[i:i+6].hex()}) in {where(prog, i)}")
    else:
        if mine is not None:
            res["status"] = "accepted-by-spinemu"
            res["detail"] = f"OpenSpin: line {ref_err[0]}: {ref_err[1]}"
        elif ref_err[0] is not None and (os.path.realpath(os.path.join(os.path.dirname(path), ref_err[2])),
                                         ref_err[0]) in lines:
            res["status"] = "rejected-same-line"
        elif ref_err[0] is None and "find/open" in ref_err[1] and missing:
            res["status"] = "rejected-same-line"   # a missing or empty file: OpenSpin gives no line
        else:
            res["status"] = "rejected-other-line"
            res["detail"] = f"OpenSpin line {ref_err[0]}: {ref_err[1]} | spinemu line {err[0]}: {err[1]}"
    return res


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--library", required=True)
    ap.add_argument("--openspin", required=True)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--limit", type=int, default=0)
    ap.add_argument("--show", type=int, default=25, help="how many examples of each problem to print")
    ap.add_argument("--filter", default="", help="only files whose path contains this")
    args = ap.parse_args(argv)
    files = []
    for d, _dirs, names in os.walk(args.library):
        for n in names:
            if n.lower().endswith(".spin"):
                files.append(os.path.join(d, n))
    files.sort()
    if args.filter:
        files = [f for f in files if args.filter in f]
    if args.limit:
        files = files[:args.limit]
    t0 = time.time()
    with ProcessPoolExecutor(args.jobs) as ex:
        results = list(ex.map(one, [(f, args.openspin) for f in files], chunksize=4))
    wall = time.time() - t0
    count = collections.Counter(r["status"] for r in results)
    compiled = count["identical"] + count["different"] + count["rejected-by-spinemu"]
    rejected = count["accepted-by-spinemu"] + count["rejected-same-line"] + count["rejected-other-line"]
    print(f"files: {len(results)}   wall time {wall:.1f} s   spinemu compile time "
          f"{sum(r['time'] for r in results):.1f} s")
    if compiled:
        print(f"OpenSpin compiles {compiled}: identical {count['identical']} "
              f"({100.0 * count['identical'] / compiled:.2f} %), different {count['different']}, "
              f"rejected by spinemu {count['rejected-by-spinemu']}")
    print(f"OpenSpin rejects {rejected}: spinemu rejects on the same line {count['rejected-same-line']}, "
          f"on another line {count['rejected-other-line']}, accepts {count['accepted-by-spinemu']}")
    for status in ("different", "rejected-by-spinemu", "accepted-by-spinemu", "rejected-other-line"):
        items = [r for r in results if r["status"] == status]
        if not items:
            continue
        print(f"\n== {status} ({len(items)})")
        for r in items[:args.show]:
            print(f"  {os.path.relpath(r['path'], args.library)}\n      {r.get('detail', '')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
