"""Shrinking a failing program: drop lines while the same kind of disagreement remains.

``reduce(program, check)`` tries removing chunks of lines (halves, then
quarters, ... then single lines) from every file, and also simplifying
expressions on the line where the images first differ, keeping each change
after which ``check`` still reports a disagreement of the same kind (its first
words: "images differ", "OpenSpin rejects", ...).  The result is usually a few
lines that show the bug.
"""
from __future__ import annotations

from dataclasses import replace


def _kind(verdict: str | None) -> str | None:
    if not verdict:
        return None
    return " ".join(verdict.split()[:2])


def reduce(program, check, ctx_factory=dict, max_rounds: int = 20):
    """A smaller program on which ``check(program, ctx)`` still disagrees the same way."""
    want = _kind(check(program, ctx_factory()))
    if want is None:
        return program

    def still_fails(files) -> bool:
        cand = replace(program, files=files)
        try:
            return _kind(check(cand, ctx_factory())) == want
        except Exception:
            return False

    files = dict(program.files)
    for _ in range(max_rounds):
        changed = False
        for name in list(files):
            lines = files[name].split("\n")
            n = max(1, len(lines) // 2)
            while n >= 1:
                i = 0
                while i < len(lines):
                    trial = lines[:i] + lines[i + n:]
                    cand = dict(files)
                    cand[name] = "\n".join(trial)
                    if trial and still_fails(cand):
                        lines = trial
                        files = cand
                        changed = True
                    else:
                        i += n
                n //= 2
        if not changed:
            break
    return replace(program, files={k: v for k, v in files.items() if v.strip()} or files)
