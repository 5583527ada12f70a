"""Write the generated compiler probes and compile every probe with OpenSpin.

Usage::

    python tests/data/compiler/make_probes.py --openspin /path/to/openspin

* ``probes/*.spin`` written by hand (children are named ``child_*``) and the
  generated ones below are compiled with ``openspin -q -b NAME.spin -o NAME.binary``.
* ``errors/*.spin`` are compiled too; OpenSpin's message goes to
  ``errors/openspin.json`` (path-free: ``line``, ``col``, ``message``).
* ``constants.json``: the value OpenSpin gives each of
  :data:`CONSTANT_EXPRESSIONS` as a CON constant (``null``: rejected).

The tests (tests/compiler) then check spinemu's images against these files
without needing OpenSpin.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROBES = os.path.join(HERE, "probes")
ERRORS = os.path.join(HERE, "errors")

CLOCKS = {
    "clock_default": "",
    "clock_rcslow": "_clkmode = rcslow",
    "clock_rcfast": "_clkmode = rcfast",
    "clock_xinput": "_clkmode = xinput\n  _xinfreq = 10_000_000",
    "clock_xtal2_pll8x": "_clkmode = xtal2 + pll8x\n  _xinfreq = 10_000_000",
    "clock_xtal3_pll1x": "_clkmode = xtal3 + pll1x\n  _clkfreq = 20_000_000",
    "clock_xinput_pll4x": "_clkmode = xinput + pll4x\n  _xinfreq = 6_000_000",
}


def generated() -> dict:
    files = {}
    for name, con in CLOCKS.items():
        what = con.replace("\n  ", ", ") or "no settings"
        files[name] = f"' Probe: clock header for {what}\nCON\n  {con or 'X = 0'}\n\nPUB main\n  outa[0]~~\n"
    # case and lookup end addresses around 255/256 (PUSH_IMM1 -> PUSH_IMM2), forward jumps 62/63
    for pad in (236, 237, 238, 239, 240):
        body = "".join("      abort\n" for _ in range(pad))
        files[f"case_end_{pad}"] = (f"' Probe: case end address with {pad} bytes of body\n"
                                    f"PUB main | x\n  case x\n    1:\n{body}  x := 1\n")
    for n in (61, 62, 63, 64):
        body = "".join("    abort\n" for _ in range(n))
        files[f"jump_fwd_{n}"] = f"' Probe: forward jump over {n} bytes\nPUB main | x\n  if x\n{body}  x := 1\n"
        files[f"jump_back_{n}"] = f"' Probe: backward jump over {n} bytes\nPUB main | x\n  repeat\n{body}  x := 1\n"
    return files


#: constant expressions whose values OpenSpin folds (constants.json)
CONSTANT_EXPRESSIONS = [
    "1.0/3.0", "0.1*3.0", "0.1+0.2", "1e38*10.0", "||-2.5", "^^2.0", "1.0 #> 2.0", "3.0 <# 2.0",
    "2.0 == 2.0", "1.0 < 2.0", "1.0 > 2.0", "1.0 =< 2.0", "1.0 <> 1.0", "-0.0", "float(7)/2.0",
    "round(-2.5)", "trunc(-2.7)", "round(1e20)", "trunc(3e9)", "round(2.5)", "round(0.5)", "round(1.5)",
    "round(-0.5)", "trunc(-0.5)", "round(8388609.5)", "7 >< 4", "5 >< 0", "5 >< 32", "-7 / 2", "-7 // 2",
    "7 // -2", "$80000000 ** 2", "-3 ** 5", "^^ -1", "^^ 2", "^^ 1000000", ">| 0", ">| 1", ">| $80000000",
    "|< 33", "1 << 33", "-8 ~> 1", "-8 >> 1", "1 -> 1", "1 <- 33", "NOT 0", "3 AND 0", "2 OR 0", "-1 < 0",
    "$FFFFFFFF > 0", "!0", "\"A\"+1", "2.0 * -0.0", "float(-3)", "||negx", "-negx", "1.0 / 0.0",
    "^^16.0", "1.0 AND 2.0", "NOT 1.0", "-1.0 #> 0.0", "-pi", "pi * 2.0", "float($7FFFFFFF)",
    "float(16777217)", "negx * -1", "5 * -3", "100000 * 100000", "%%3210", "$FFFF_FFFF + 1",
    "10.0 ** 2.0", "1 + 1.0", "1.0 == 1", "1 / 0", "5 // 0",
]


def constant_table(exe: str) -> dict:
    import tempfile
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for e in CONSTANT_EXPRESSIONS:
            src = os.path.join(tmp, "c.spin")
            with open(src, "w") as fh:
                fh.write(f"CON\n  C0 = {e}\nDAT\n  long C0\nPUB m\n")
            rc, _text = openspin(exe, src, os.path.join(tmp, "c.binary"))
            if rc:
                out[e] = None
            else:
                with open(os.path.join(tmp, "c.binary"), "rb") as fh:
                    out[e] = int.from_bytes(fh.read()[0x18:0x1C], "little")
    return out


def openspin(exe: str, path: str, out: str):
    r = subprocess.run([exe, "-q", "-b", path, "-o", out], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--openspin", required=True)
    args = ap.parse_args(argv)
    for name, text in generated().items():
        with open(os.path.join(PROBES, name + ".spin"), "w", newline="\n") as fh:
            fh.write(text)
    failed = 0
    for fname in sorted(os.listdir(PROBES)):
        if not fname.endswith(".spin") or fname.startswith("child_"):
            continue
        src = os.path.join(PROBES, fname)
        rc, text = openspin(args.openspin, src, src[:-5] + ".binary")
        if rc:
            print(f"{fname}: OpenSpin failed:\n{text}")
            failed += 1
    if os.path.isdir(ERRORS):
        results = {}
        for fname in sorted(os.listdir(ERRORS)):
            if not fname.endswith(".spin") or fname.startswith("child_"):
                continue
            src = os.path.join(ERRORS, fname)
            out = os.path.join(ERRORS, "_unused.binary")
            rc, text = openspin(args.openspin, src, out)
            if os.path.exists(out):
                os.remove(out)
            m = re.search(r"^(.*?)\((\d+):(\d+)\) : error : (.*)", text, re.M)
            if rc and m:
                results[fname] = {"file": os.path.basename(m.group(1)), "line": int(m.group(2)),
                                  "col": int(m.group(3)), "message": m.group(4).strip()}
            elif rc:
                results[fname] = {"line": None, "col": None, "message": text.strip().splitlines()[0]
                                  .split(" : ")[-1] if text.strip() else f"exit status {rc}"}
            else:
                results[fname] = {"line": None, "col": None, "message": "accepted"}
        with open(os.path.join(ERRORS, "openspin.json"), "w") as fh:
            json.dump(results, fh, indent=1, sort_keys=True)
            fh.write("\n")
    with open(os.path.join(HERE, "constants.json"), "w") as fh:
        json.dump(constant_table(args.openspin), fh, indent=1)
        fh.write("\n")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
