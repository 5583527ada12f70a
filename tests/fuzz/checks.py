"""Differential checks of one generated program; each returns ``None`` (agreement) or a message.

A check is a function ``check(program, context) -> str | None``; ``CHECKS``
maps its name to it, so ``python -m tests.fuzz --check NAME`` runs it and
other checks (the Spin->Python translation, ...) can be added by name.
``context`` is a dict shared by the checks of one program (one compile
serves every check that needs the image).

* ``compile``: OpenSpin and spinemu make the same image, or both reject the
  program.
* ``reference``: the image runs on spinsim ``-p`` (Parallax's ROM
  interpreter on cycle-exact cogs) and on spinemu's bytecode engine to the
  end, and leaves the same results (and the same hub RAM).
"""
from __future__ import annotations

from . import oracles


def _images(program, ctx: dict):
    if "spinemu" not in ctx:
        ctx["spinemu"] = oracles.spinemu_compile(program)
    return ctx["spinemu"]


def _first_difference(a: bytes, b: bytes) -> int:
    """The first differing byte after the 16-byte header (which follows from the rest), else in it."""
    for start in (16, 0):
        for i in range(start, min(len(a), len(b))):
            if a[i] != b[i]:
                return i
    return min(len(a), len(b))


def check_compile(program, ctx: dict) -> str | None:
    """OpenSpin's image and spinemu's are byte-identical (or both compilers reject the program)."""
    ref, ref_err = oracles.openspin_compile(program, ctx.get("openspin_exe", oracles.OPENSPIN))
    ctx["openspin"] = (ref, ref_err)
    if ref is None and ref_err.startswith("crashed"):
        return f"OpenSpin {ref_err} (a program the generator should not make)"
    mine, my_err = _images(program, ctx)
    if ref is None and mine is None:
        return None
    if ref is None:
        return f"OpenSpin rejects the program, spinemu compiles it:\n{ref_err}"
    if mine is None:
        return f"spinemu rejects the program, OpenSpin compiles it:\n{my_err}"
    if ref != mine:
        at = _first_difference(ref, mine)
        where = _where(program, mine, at)
        return (f"images differ ({len(ref)} bytes from OpenSpin, {len(mine)} from spinemu), first at "
                f"${at:04X}{where}:\n  OpenSpin {ref[at:at + 12].hex(' ')}\n  spinemu  {mine[at:at + 12].hex(' ')}")
    return None


def _where(program, image: bytes, addr: int) -> str:
    from spinemu.compiler import compile_file
    import tempfile
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        prog = compile_file(program.write(tmp))
        found = prog.line_table(addr)
    if found:
        path, line = found
        import os
        name = os.path.basename(path)
        return f" ({name} line {line}: {program.files[name].splitlines()[line - 1].strip()})"
    return ""


def check_reference(program, ctx: dict) -> str | None:
    """spinsim ``-p`` and spinemu's bytecode engine leave the same results and hub RAM."""
    mine, err = _images(program, ctx)
    if mine is None:
        return None if ctx.get("openspin", (None,))[0] is None else f"spinemu rejects the program:\n{err}"
    ref_hub = oracles.spinsim_hub(mine, ctx.get("spinsim_exe", oracles.SPINSIM))
    result = oracles.spinemu_run(mine)
    if result.reason != "all cogs stopped":
        return f"spinemu's run did not end: {result.reason} at cycle {result.end_cycle}"
    want = program.results.read(mine, ref_hub)
    got = program.results.read(mine, result.hub)
    ctx["reference_results"] = want
    if want != got:
        diffs = [f"results[{i}]: spinsim ${w:08X}, spinemu ${g:08X}"
                 for i, (w, g) in enumerate(zip(want, got)) if w != g]
        return "results differ:\n  " + "\n  ".join(diffs)
    if ref_hub != result.hub:
        at = _first_difference(ref_hub, result.hub)
        return (f"results agree but hub RAM differs, first at ${at:04X}: "
                f"spinsim {ref_hub[at:at + 8].hex(' ')}, spinemu {result.hub[at:at + 8].hex(' ')}")
    return None


from .translation import check_translate  # noqa: E402 - the Spin->Python translation (tests/fuzz/translation.py)

CHECKS = {"compile": check_compile, "reference": check_reference, "translate": check_translate}
