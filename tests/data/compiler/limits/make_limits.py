"""Write the nesting and size probes and record OpenSpin's verdict on each.

    python tests/data/compiler/limits/make_limits.py --openspin /path/to/openspin

Writes ``NAME.spin`` (spinemu's own probes, generated below) and
``openspin.json``: for each probe either ``{"sha256": ...}`` of the image
OpenSpin 1.00.81 made (``openspin -q -b NAME.spin``) or ``{"line", "col",
"message"}`` of its first error.  ``tests/compiler/test_limits.py`` compares
spinemu with that record; the tests never run OpenSpin.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def _nest(openers, body="x := 1", head="PUB main | x, i"):
    """A method with one block opener per level (a case opener gets a value line)."""
    lines, indent = [head], 1
    for opener in openers:
        lines.append("  " * indent + opener)
        indent += 1
        if opener.startswith("case"):
            lines.append("  " * indent + "1..3:")
            indent += 1
    lines.append("  " * indent + body)
    return "\n".join(lines) + "\n"


def _lookups(n, word="lookup"):
    return "PUB main | x\n  x := " + f"{word}(x: " * n + "1" + ")" * n + "\n"


def probes() -> dict:
    """``{file name: source}``."""
    p = {
        "blocks_if_9.spin": _nest(["if x"] * 9),
        "blocks_if_10.spin": _nest(["if x"] * 10),
        "blocks_repeat_10.spin": _nest(["repeat"] * 10),
        "blocks_repeat_from_10.spin": _nest(["repeat i from 1 to 2"] * 10),
        "blocks_case_9.spin": _nest(["case x"] * 9),
        "blocks_case_10.spin": _nest(["case x"] * 10),
        "blocks_mixed_9.spin": _nest(["case x", "repeat i from 0 to 2", "if x", "repeat 2", "case x",
                                      "repeat while i < 3", "ifnot x", "repeat", "if x"]),
        "blocks_elseif_chain.spin": "PUB main | x\n  if x\n    x := 1\n"
                                    + "  elseif x\n    x := 1\n" * 15 + "  else\n    x := 2\n",
        "blocks_9_inside_elseif.spin": "PUB main | x\n  if x\n    x := 1\n  elseif x\n"
                                       + "".join("  " * (i + 1) + "if x\n" for i in range(1, 9))
                                       + "  " * 10 + "x := 1\n",
        "blocks_9_inside_else.spin": "PUB main | x\n  if x\n    x := 1\n  else\n"
                                     + "".join("  " * (i + 1) + "if x\n" for i in range(1, 10))
                                     + "  " * 11 + "x := 1\n",
        "blocks_lookup_in_condition.spin": _nest(["repeat"] * 8 + ["if lookup(x: 1, 2)"]),
        "blocks_lookup_in_selector.spin": _nest(["repeat"] * 8 + ["case lookup(x: 1, 2)"]),
        "blocks_lookup_in_count.spin": _nest(["repeat"] * 8 + ["repeat lookup(x: 1, 2)"]),
        "blocks_lookup_in_range.spin": _nest(["repeat"] * 8 + ["repeat i from lookup(x: 1, 2) to 3"]),
        "blocks_lookup_nested_at_8.spin": _nest(["repeat"] * 8, "x := lookup(x: 1, lookup(x: 1, 2))"),
        "blocks_lookup_nested_at_7.spin": _nest(["repeat"] * 7, "x := lookup(x: 1, lookup(x: 1, 2))"),
        "blocks_lookup_in_case_label.spin": _nest(["repeat"] * 8 + ["case x"], "lookup(x: 1): x := 1")
                                            .replace("  " * 10 + "1..3:\n", ""),
        "blocks_lookups_9.spin": _lookups(9),
        "blocks_lookups_10.spin": _lookups(10),
        "blocks_lookdownz_10.spin": _lookups(10, "lookdownz"),
        "expression_parens_98.spin": "PUB main | x\n  x := " + "(" * 98 + "x" + ")" * 98 + "\n",
        "expression_sum_98.spin": "PUB main | x\n  x := " + " + ".join(["x"] * 98) + "\n",
        "locals_8190.spin": "PUB main | q[8190], z\n  z := 1\n",
        "locals_8191.spin": "PUB main | q[8191], z\n  z := 1\n",
        "locals_9000.spin": "PUB main | q[9000], z\n  z := 1\n",
        "locals_two_arrays.spin": "PUB main | q[4000], r[5000], z\n  z := 1\n",
        "var_8192_longs.spin": "VAR\n  long v[8192]\n  word w\nPUB main\n  w := 1\n  v[1] := 2\n",
    }
    return p


def verdict(exe: str, path: str) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "x.binary")
        r = subprocess.run([exe, "-q", "-b", path, "-o", out], capture_output=True, text=True)
        if r.returncode == 0 and os.path.exists(out):
            with open(out, "rb") as fh:
                return {"sha256": hashlib.sha256(fh.read()).hexdigest()}
    m = re.search(r"\((\d+):(\d+)\) : error : (.*)", r.stdout + r.stderr)
    if m:
        return {"line": int(m.group(1)), "col": int(m.group(2)), "message": m.group(3).strip()}
    m = re.search(r": error : (.*)", r.stdout + r.stderr)
    return {"line": None, "col": None, "message": m.group(1).strip() if m else "rejected"}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--openspin", required=True)
    args = ap.parse_args(argv)
    record = {}
    for name, text in sorted(probes().items()):
        path = os.path.join(HERE, name)
        with open(path, "w", newline="\n") as fh:
            fh.write(text)
        record[name] = verdict(args.openspin, path)
    with open(os.path.join(HERE, "openspin.json"), "w") as fh:
        json.dump(record, fh, indent=1, sort_keys=True)
        fh.write("\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
