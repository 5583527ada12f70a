"""Projects written on Windows: OBJ and FILE names in another letter case than the file on disk.

Usage::

    python tests/benchmarks/windows_case.py --library /opt/oracles/propeller \\
        --openspin /opt/oracles/OpenSpin/build/openspin [--jobs 2] [--show 20] [--standard]

Finds every library .spin file that names an OBJ or DAT ``file`` which has
no exact match in its folder but one in another letter case (what the
Propeller Tool on Windows finds and OpenSpin on Linux rejects), or uses an
object that does.  Each such
file is compiled as a top object by spinemu (which finds the names in any
case, with a warning) and, in a copy of its folder where every such name also
exists exactly as written ("fixed by hand"), by OpenSpin; the report gives how
many images are byte-identical.  ``--standard`` also gives both compilers the
Propeller Tool's standard objects (``FullDuplexSerial``, ``TV`` ...), in a
folder built from the library's copies as ``library_runs.py`` builds it:
spinemu finds it on ``SPINEMU_PATH``; OpenSpin gets the ones a project lacks copied
into its folder (with ``-L`` it would take them before the project's own copies).  Not part of the test run (it needs OpenSpin
and the library).
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", ".."))

def referenced_names(path: str) -> list:
    """``(kind, file name)`` for every OBJ and DAT ``file`` name in the file (read by spinemu's parser)."""
    from spinemu.frontend.ast import DatFile
    from spinemu.frontend.parser import parse_text
    from spinemu.frontend.source import read_source
    try:
        spin, _errors = parse_text(read_source(path))
    except Exception:   # unreadable: nothing to report
        return []
    out = [("OBJ", d.filename if d.filename.lower().endswith(".spin") else d.filename + ".spin") for d in spin.objs]
    out += [("FILE", line.body.filename) for line in spin.dat if isinstance(line.body, DatFile)]
    return out


def case_mismatches(path: str) -> list:
    """The names of ``path`` with no exact file in its folder but one in another case."""
    folder = os.path.dirname(path)
    entries = os.listdir(folder)
    lower = {}
    for e in entries:
        lower.setdefault(e.lower(), []).append(e)
    out = []
    for kind, name in referenced_names(path):
        if name in entries or "/" in name or "\\" in name:
            continue
        if name.lower() in lower:
            out.append((kind, name, lower[name.lower()]))
    return out


def uses_other_case(path: str) -> bool:
    """Whether compiling ``path`` meets a name in another letter case (itself or any object it uses)."""
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError
    from spinemu.frontend.search import SearchPath
    search = SearchPath(environ={}, standard=False)
    try:
        compile_file(path, search=search)
    except SpinError:
        pass
    except Exception:   # a crash is for tests/benchmarks/corpus.py to report
        return False
    return bool(search.warnings)


def _select(path: str):
    return path, bool(case_mismatches(path)) or uses_other_case(path)


def _fixed_copy(folder: str, tmp: str, std: str = "") -> str:
    """A copy of ``folder`` in which every name used in another case also exists as written.

    ``std``: a folder of standard objects; each one the project has in no letter case is
    copied in too (OpenSpin's ``-L`` folders come before the source's own folder, where
    the Propeller Tool looks in the project first).
    """
    dst = os.path.join(tmp, "proj")
    shutil.copytree(folder, dst)
    if std:
        have = {e.lower() for e in os.listdir(dst)}
        for name in os.listdir(std):
            if name.lower() not in have:
                shutil.copyfile(os.path.join(std, name), os.path.join(dst, name))
    for fname in os.listdir(dst):
        if fname.lower().endswith(".spin"):
            for _kind, name, actual in case_mismatches(os.path.join(dst, fname)):
                target = os.path.join(dst, name)
                if not os.path.exists(target):
                    shutil.copyfile(os.path.join(dst, actual[0]), target)
    return dst


def check(args):
    path, openspin, std = args
    from spinemu.compiler import compile_file
    from spinemu.diagnostics import SpinError
    from spinemu.frontend.search import SearchPath
    with tempfile.TemporaryDirectory() as tmp:
        proj = _fixed_copy(os.path.dirname(path), tmp, std)
        out = os.path.join(tmp, "ref.binary")
        r = subprocess.run([openspin, "-q", "-b", os.path.join(proj, os.path.basename(path)), "-o", out],
                           capture_output=True, text=True, errors="replace")
        ref = open(out, "rb").read() if r.returncode == 0 and os.path.exists(out) else None
    try:
        environ = {"SPINEMU_PATH": std} if std else {}
        prog = compile_file(path, search=SearchPath(environ=environ, standard=False))
        mine, warnings, err = prog.binary, len(prog.warnings), None
    except SpinError as exc:
        mine, warnings, err = None, 0, str(exc).splitlines()[0]
    if ref is None:
        verdict = "openspin rejects" if mine is None else "openspin rejects, spinemu compiles"
    elif mine is None:
        verdict = "spinemu rejects"
    else:
        verdict = "identical" if mine == ref else "differ"
    return path, verdict, warnings, err or (r.stdout.strip().splitlines() or [""])[0]


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", default="/opt/oracles/propeller")
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--show", type=int, default=20)
    ap.add_argument("--standard", action="store_true",
                    help="give both compilers the standard objects built from the library's copies")
    a = ap.parse_args(argv)
    std = ""
    if a.standard:
        from library_runs import build_standard_folder, spin_files
        std = tempfile.mkdtemp(prefix="spinemu-standard-")
        build_standard_folder(spin_files(a.library), std)
    every = sorted(os.path.join(root, n) for root, _dirs, names in os.walk(a.library)
                   for n in names if n.lower().endswith(".spin"))
    direct = sum(1 for p in every if case_mismatches(p))
    counts: dict = {}
    shown = 0
    with ProcessPoolExecutor(a.jobs) as pool:
        files = [p for p, hit in pool.map(_select, every, chunksize=8) if hit]
        for path, verdict, warnings, detail in pool.map(check, [(p, a.openspin, std) for p in files], chunksize=4):
            counts[verdict] = counts.get(verdict, 0) + 1
            if verdict != "identical" and shown < a.show:
                shown += 1
                print(f"{verdict}: {os.path.relpath(path, a.library)}: {detail}")
    total = len(files)
    ok = counts.get("identical", 0)
    compiled = total - counts.get("openspin rejects", 0) - counts.get("openspin rejects, spinemu compiles", 0)
    print(f"{direct} library files name an OBJ or FILE in another letter case than the file on disk; "
          f"{total} meet such a name when compiled (themselves or in an object they use)")
    for k in sorted(counts):
        print(f"  {k}: {counts[k]}")
    print(f"identical images: {ok} of {total} ({100 * ok / max(total, 1):.1f} %); "
          f"of the {compiled} OpenSpin compiles once the names are fixed: {100 * ok / max(compiled, 1):.1f} %")


if __name__ == "__main__":
    main()
