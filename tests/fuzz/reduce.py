"""Shrink a Spin program on which the two engines disagree to a small one that still disagrees the same way.

Greedy reduction to a fixed point: drop a statement with its indented block,
then replace a parenthesised sub-expression by ``0``, ``1`` or one of its
operands; a candidate is kept when the engines still disagree in the same
way (the first word of the difference: ``hub``, ``pin``, ``end`` ... or the
same exception).  Usage::

    python -m tests.fuzz.reduce PROGRAM.spin        # writes PROGRAM.min.spin
"""
from __future__ import annotations

import os
import re
import sys
import tempfile

from spinemu.diagnostics import SpinError
from tests.fuzz.translation import compare

__all__ = ["reduce_source"]


def _kind(src: str, folder: str):
    path = os.path.join(folder, "candidate.spin")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(src)
    try:
        detail = compare(path)
    except SpinError:
        return None
    except Exception as exc:  # noqa: BLE001 - an engine's crash is a disagreement of its own kind
        return type(exc).__name__
    return detail.split(" ")[0] if detail else None


def _blocks(lines):
    """(first, end) of each statement with its indented block, inside methods."""
    out = []
    in_method = False
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        if re.match(r"(?i)(pub|pri|var|con|obj|dat)\b", line):
            in_method = line[:3].lower() in ("pub", "pri")
            continue
        if not in_method or not stripped or stripped.startswith("'"):
            continue
        indent = len(line) - len(stripped)
        end = i + 1
        while end < len(lines) and (len(lines[end]) - len(lines[end].lstrip()) > indent or not lines[end].strip()):
            end += 1
        out.append((i, end))
    return out


def _groups(line: str):
    """(start, end) of every balanced parenthesised group in ``line``, innermost last."""
    out, stack = [], []
    for i, ch in enumerate(line):
        if ch == "(":
            stack.append(i)
        elif ch == ")" and stack:
            out.append((stack.pop(), i + 1))
    return sorted(out, key=lambda g: g[0])


def _operands(inner: str):
    """The two top-level operands of ``A op B`` (as the generators write binary expressions), or []."""
    depth = 0
    for i, ch in enumerate(inner):
        depth += ch in "([" 
        depth -= ch in ")]"
        if depth == 0 and ch == " " and i > 0:
            rest = inner[i + 1:]
            op, _, right = rest.partition(" ")
            if right and not op[:1].isalnum() or op.upper() in ("AND", "OR"):
                return [inner[:i], right]
    return []


def reduce_source(src: str, log=None) -> str:
    """The smallest program found that disagrees like ``src`` does (``src`` itself if it agrees)."""
    folder = tempfile.mkdtemp(prefix="spinemu-reduce-")
    want = _kind(src, folder)
    if want is None:
        return src
    lines = src.splitlines()
    changed = True
    while changed:
        changed = False
        for first, end in reversed(_blocks(lines)):
            cand = lines[:first] + lines[end:]
            if _kind("\n".join(cand) + "\n", folder) == want:
                lines, changed = cand, True
                if log:
                    print(f"  dropped line {first + 1} ({end - first} lines)", file=log)
        for n in range(len(lines)):
            k = 0
            while True:
                groups = _groups(lines[n])
                if k >= len(groups):
                    break
                a, b = groups[k]
                inner = lines[n][a + 1:b - 1]
                tried = False
                for repl in ["0", "1"] + [f"({o})" for o in _operands(inner)]:
                    if repl == lines[n][a:b]:
                        continue
                    cand = lines[:n] + [lines[n][:a] + repl + lines[n][b:]] + lines[n + 1:]
                    if _kind("\n".join(cand) + "\n", folder) == want:
                        lines, changed, tried = cand, True, True
                        break
                if not tried:
                    k += 1
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print(__doc__)
        return 2
    src = open(argv[0], encoding="utf-8").read()
    small = reduce_source(src, log=sys.stderr)
    out = os.path.splitext(argv[0])[0] + ".min.spin"
    with open(out, "w", encoding="utf-8") as fh:
        fh.write(small)
    print(small)
    print(f"written to {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
