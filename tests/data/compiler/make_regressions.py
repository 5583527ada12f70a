"""Record what OpenSpin makes of each compiler regression program (bugs the program generator found).

Usage::

    python tests/data/compiler/make_regressions.py --openspin /path/to/openspin

For every ``regressions/NAME.spin`` that is not a child object (``*_child.spin``),
``regressions/openspin.json`` gets the SHA-256 of OpenSpin's image
(``openspin -q -b NAME.spin``) and, when the program has DAT labels ``folded``
and ``folded_end``, the longs between them in that image (the values the
constant expressions there must fold to).  tests/compiler/test_regressions.py
checks spinemu against this file without OpenSpin.
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
REGRESSIONS = os.path.join(HERE, "regressions")
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(HERE))))


def folded_values(image: bytes, path: str):
    """The longs between DAT labels ``folded`` and ``folded_end`` (spinemu's layout locates them)."""
    from spinemu.compiler import compile_file
    lay = compile_file(path).layout
    if "folded" not in lay.dat:
        return None
    start = lay.pbase + lay.dat["folded"][0]
    end = lay.pbase + lay.dat["folded_end"][0]
    return [int.from_bytes(image[a:a + 4], "little") for a in range(start, end, 4)]


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", required=True)
    a = ap.parse_args(argv)
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for path in sorted(glob.glob(os.path.join(REGRESSIONS, "*.spin"))):
            name = os.path.basename(path)
            if name.endswith("_child.spin"):
                continue
            binary = os.path.join(tmp, "out.binary")
            r = subprocess.run([a.openspin, "-q", "-b", path, "-o", binary], capture_output=True, text=True)
            if r.returncode:
                sys.exit(f"{name}: OpenSpin rejects it: {r.stdout}{r.stderr}")
            with open(binary, "rb") as fh:
                image = fh.read()
            entry = {"sha256": hashlib.sha256(image).hexdigest(), "size": len(image)}
            values = folded_values(image, path)
            if values is not None:
                entry["folded"] = [f"${v:08X}" for v in values]
            out[name] = entry
            print(name, entry["sha256"][:16], len(values or []), "values")
    with open(os.path.join(REGRESSIONS, "openspin.json"), "w") as fh:
        json.dump(out, fh, indent=1, sort_keys=True)
        fh.write("\n")


if __name__ == "__main__":
    main()
