"""Record what the reference tools say about a seeded sample of generated programs, for the default tests.

    python -m tests.fuzz.record [--compile 0:32] [--reference 0:12] [--openspin PATH] [--spinsim PATH]

writes ``tests/data/fuzz/compile_sample.json`` (per seed: the SHA-256 of the
program's text and of OpenSpin's image) and ``tests/data/fuzz/reference_sample.json``
(per seed: the program and image hashes, the ``results`` longs spinsim ``-p``
left and the SHA-256 of its hub RAM).  tests/fuzz/test_sample.py checks
spinemu against them without OpenSpin or spinsim.  The program hash tells a
changed generator (re-record) from a changed compiler.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os

from . import oracles
from .generator import generate

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "data", "fuzz")


def sha(data) -> str:
    return hashlib.sha256(data if isinstance(data, bytes) else data.encode()).hexdigest()


def _range(text: str) -> range:
    lo, hi = (int(x) for x in text.split(":"))
    return range(lo, hi)


def record_compile(seeds, openspin: str) -> dict:
    out = {}
    for seed in seeds:
        program = generate(seed)
        image, err = oracles.openspin_compile(program, openspin)
        out[str(seed)] = {"program": sha(program.text()), "openspin": sha(image) if image else "rejected"}
    return out


def record_reference(seeds, openspin: str, spinsim: str) -> dict:
    out = {}
    for seed in seeds:
        program = generate(seed)
        image, err = oracles.openspin_compile(program, openspin)
        if image is None:
            raise SystemExit(f"seed {seed}: OpenSpin rejects the program: {err}")
        hub = oracles.spinsim_hub(image, spinsim)
        out[str(seed)] = {
            "program": sha(program.text()), "image": sha(image),
            "results": [f"${v:08X}" for v in program.results.read(image, hub)], "hub": sha(hub),
        }
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(prog="python -m tests.fuzz.record", description=__doc__.split("\n\n")[0])
    ap.add_argument("--compile", default="0:32", help="seeds A:B for compile_sample.json")
    ap.add_argument("--reference", default="0:12", help="seeds A:B for reference_sample.json")
    ap.add_argument("--openspin", default=oracles.OPENSPIN)
    ap.add_argument("--spinsim", default=oracles.SPINSIM)
    a = ap.parse_args(argv)
    os.makedirs(DATA, exist_ok=True)
    for name, data in (("compile_sample.json", record_compile(_range(a.compile), a.openspin)),
                       ("reference_sample.json", record_reference(_range(a.reference), a.openspin, a.spinsim))):
        with open(os.path.join(DATA, name), "w") as fh:
            json.dump({"source": "see tests/data/README.md (fuzz/)", "seeds": data}, fh, indent=1)
            fh.write("\n")
        print(f"{name}: {len(data)} seeds")


if __name__ == "__main__":
    main()
