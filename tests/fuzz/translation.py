"""Translation differential: generated Spin programs on the bytecode engine and on the Python engine.

Each program runs on both engines (compat mode ``spinsim``); they agree when
the pin traces are identical (every change at the same cycle), the end cycle
is the same, and hub RAM is identical outside the cogs' stacks (VAR, DAT,
code, free RAM: tests/translate/crosscheck.py).  A program that faults must
fault on both engines with the same message.  A construct the translator does
not handle (``TranslateError``) counts as a disagreement.

Two generators: ``full`` (tests/fuzz/generator.py: the whole language, child
objects, DAT ...) and ``order`` (tests/fuzz/order_programs.py: expressions with
side effects in every operand position).  ``python -m tests.fuzz --check
translate`` runs this check on ``full`` programs too.

Reproduce a seed (prints the program and the first difference; ``--shrink``
also prints the program cut down to what still disagrees)::

    python -m tests.fuzz.translation --seed 17 [--generator order] [--shrink]

Run a campaign (seeds ``start .. start + count - 1``)::

    python -m tests.fuzz.translation --start 0 --count 10000 --jobs 2
"""
from __future__ import annotations

import argparse
import os
import re
import sys
import tempfile
from dataclasses import replace

from spinemu import translate
from spinemu.diagnostics import EmulationError, SpinError
from spinemu.translate import TranslateError
from tests.translate.crosscheck import crosscheck, run_bytecode

#: chip cycles a generated program may run (they end long before)
MAX_CYCLES = 20_000_000


def _generators() -> dict:
    from tests.fuzz.generator import generate
    from tests.fuzz.order_programs import generate as order
    return {"full": generate, "order": order}


#: the verdict for a program whose image does not do what its source says (not compared)
NOT_COMPARED = "not compared"


def _stale_jumps(path: str) -> bool:
    """Does OpenSpin's sizing (which the compiler copies) write a jump of ``path`` with a stale address?

    The image then does not do what the source says (spinemu.compiler.code, "stale"; the compiler's
    hint names the line), while the Python engine runs the source: the engines cannot agree.
    """
    from spinemu.compiler import compile_file
    from spinemu import messages
    marker = messages.HINT_STALE_JUMP.split("{")[0]
    return any(w.message.startswith(marker) for w in compile_file(path).warnings)


def compare(path: str, max_cycles: int = MAX_CYCLES) -> str:
    """Run the Spin program at ``path`` on both engines; "" when they agree, else the first difference
    (:data:`NOT_COMPARED` when its image does not follow its source: :func:`_stale_jumps`).

    Raises:
        TranslateError: the translator does not handle the program.
        SpinError: the program does not compile.
    """
    if _stale_jumps(path):
        return NOT_COMPARED
    try:
        bytecode_run = run_bytecode(path, max_cycles)
    except EmulationError as fault:
        try:
            translate.run_translated(path, max_cycles=max_cycles)
        except EmulationError as other:
            if fault.message.split(":")[0] == other.message.split(":")[0]:
                return ""
            return f"both fault, differently: {fault.message} / {other.message}"
        return f"the bytecode engine faults ({fault.message}), the Python engine does not"
    result = crosscheck(path, max_cycles, bytecode_run=bytecode_run)
    b, p = result.bytecode, result.python
    if b.trace.changes != p.trace.changes:
        for k, (x, y) in enumerate(zip(b.trace.changes, p.trace.changes)):
            if x != y:
                return f"pin change {k}: bytecode {x}, Python {y}"
        return f"pin changes: bytecode {len(b.trace.changes)}, Python {len(p.trace.changes)}"
    if b.end_cycle != p.end_cycle:
        return f"end cycle: bytecode {b.end_cycle}, Python {p.end_cycle}"
    if result.hub_differences:
        vbase = b.hub[8] | b.hub[9] << 8
        shown = []
        for a, x, y in result.hub_differences[:6]:
            where = f"VAR+{a - vbase}" if a >= vbase else f"${a:04X}"
            shown.append(f"{where}: {x} vs {y}")
        return f"hub RAM differs at {len(result.hub_differences)} bytes (bytecode vs Python): {', '.join(shown)}"
    return ""


def check_translate(program, ctx: dict = None) -> str | None:
    """The check ``translate``: both engines agree on a generated program (``None``), else the first difference.

    A program that does not compile gives ``None`` (the compile check reports it).
    """
    with tempfile.TemporaryDirectory(prefix="spinemu-fuzz-") as tmp:
        top = program.write(tmp)
        try:
            verdict = compare(top)
            return None if verdict == NOT_COMPARED and not (ctx or {}).get("count_skipped") else verdict or None
        except TranslateError as exc:
            return "not translated: " + str(exc).replace(tmp + os.sep, "").splitlines()[0]
        except SpinError:
            return None
        except Exception as exc:  # noqa: BLE001 - an engine's crash is a disagreement too
            return f"{type(exc).__name__}: {exc}"


# ---------------------------------------------------------------------------- shrinking
def _kind(verdict) -> str | None:
    return verdict.split(":")[0].split(" ")[0] if verdict else None


def _groups(line: str) -> list:
    """``(start, end)`` of every balanced parenthesised group of ``line``, from the left."""
    out, stack = [], []
    for i, ch in enumerate(line):
        if ch == "(":
            stack.append(i)
        elif ch == ")" and stack:
            out.append((stack.pop(), i + 1))
    return sorted(out)


def _operands(inner: str) -> list:
    """The two sides of ``A op B`` (a binary expression as the generators write it), or []."""
    depth = 0
    for i, ch in enumerate(inner):
        depth += ch in "(["
        depth -= ch in ")]"
        if depth == 0 and ch == " " and i > 0:
            op, _, right = inner[i + 1:].partition(" ")
            if right and (not op[:1].isalnum() or op.upper() in ("AND", "OR")):
                return [inner[:i], right]
            return []
    return []


_SETS_LOCAL = re.compile(r"(?i)\s*(longfill\(@l\d+,|l\d+(\[\d+\])?\s*:=)")


def shrink(program, check=check_translate):
    """A smaller program on which ``check`` still disagrees the same way.

    fuzzc's line reducer (tests/fuzz/reduce.py) first, then each parenthesised
    sub-expression is replaced by ``0``, ``1`` or one of its operands where the
    disagreement stays.
    """
    from tests.fuzz.reduce import reduce
    want = _kind(check(program, {}))
    if want is None:
        return program
    # a local must stay assigned before it is read (Spin does not clear locals, and the engines'
    # stacks hold different scratch): the lines that set locals first are kept
    keep = {(name, line.strip()) for name, text in program.files.items() for line in text.split("\n")
            if _SETS_LOCAL.match(line)}

    checked = check

    def guarded(cand, ctx):
        present = {(name, line.strip()) for name, text in cand.files.items() for line in text.split("\n")}
        return checked(cand, ctx) if keep <= present else None

    program = reduce(program, guarded)
    check = guarded
    changed = True
    while changed:
        changed = False
        for name in list(program.files):
            lines = program.files[name].split("\n")
            for n in range(len(lines)):
                if re.match(r"(?i)\s*(pub|pri|con|var|obj|dat)\b", lines[n]):
                    continue
                k = 0
                while k < len(_groups(lines[n])):
                    a, b = _groups(lines[n])[k]
                    inner = lines[n][a + 1:b - 1]
                    for repl in ["0", "1"] + [f"({o})" for o in _operands(inner)]:
                        trial = lines[:n] + [lines[n][:a] + repl + lines[n][b:]] + lines[n + 1:]
                        cand = replace(program, files=dict(program.files, **{name: "\n".join(trial)}))
                        if repl != lines[n][a:b] and _kind(check(cand, {})) == want:
                            lines, program, changed = trial, cand, True
                            break
                    else:
                        k += 1
    return program


# ---------------------------------------------------------------------------- campaigns
def _run(args):
    seed, generator = args
    program = _generators()[generator](seed)
    return seed, check_translate(program, {"count_skipped": True})


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tests.fuzz.translation", description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, help="show program SEED and what the engines did")
    ap.add_argument("--shrink", action="store_true", help="with --seed: also the program cut down")
    ap.add_argument("--start", type=int, default=0, help="first seed of a campaign")
    ap.add_argument("--count", type=int, default=100, help="programs in a campaign")
    ap.add_argument("--jobs", type=int, default=1, help="processes")
    ap.add_argument("--generator", choices=("full", "order"), default="full")
    args = ap.parse_args(argv)
    generate = _generators()[args.generator]
    if args.seed is not None:
        program = generate(args.seed)
        print(program.text())
        verdict = check_translate(program, {"count_skipped": True})
        print(f"seed {args.seed}: {verdict or 'agree'}")
        if verdict == NOT_COMPARED:
            return 0
        if verdict and args.shrink:
            small = shrink(program)
            print("--- shrunk:")
            print(small.text())
            print(check_translate(small))
        return 1 if verdict else 0
    seeds = [(s, args.generator) for s in range(args.start, args.start + args.count)]
    failed, skipped = [], []
    if args.jobs > 1:
        import multiprocessing
        with multiprocessing.Pool(args.jobs) as pool:
            results = list(_report(pool.imap(_run, seeds, chunksize=4), failed, skipped))
    else:
        results = list(_report(map(_run, seeds), failed, skipped))
    print(f"{args.generator} seeds {args.start}..{args.start + args.count - 1}: "
          f"{len(results) - len(failed) - len(skipped)} agree, {len(failed)} disagree"
          + (f" (seeds {' '.join(map(str, failed[:100]))})" if failed else "")
          + (f"; {len(skipped)} not compared, their images do not follow their sources (OpenSpin's stale jumps: "
             f"seeds {' '.join(map(str, skipped[:100]))})" if skipped else ""))
    return 1 if failed else 0


def _report(results, failed, skipped):
    for n, (seed, verdict) in enumerate(results, 1):
        if verdict == NOT_COMPARED:
            skipped.append(seed)
        elif verdict:
            failed.append(seed)
            print(f"seed {seed}: {verdict}", flush=True)
        if n % 500 == 0:
            print(f"... {n} programs, {len(failed)} disagree", flush=True)
        yield seed


if __name__ == "__main__":
    sys.exit(main())
