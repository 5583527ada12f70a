#!/usr/bin/env python3
"""Derive spinemu's bytecode timing table from spinsim runs of probe programs.

Usage (from the worktree root; needs OpenSpin and spinsim, which tests never need)::

    python tests/chip/tools/derive_timing.py --openspin PATH --spinsim PATH [--check] [probe.spin ...]

For every probe (default: tests/data/chip/programs/*.spin and the conformance
programs) it

1. compiles it with OpenSpin,
2. runs it on spinsim with ``-p -l`` (Parallax's ROM interpreter on
   cycle-exact cogs) and reads, per bytecode, the cycle at which the fetch
   completed and the cycle at which the next bytecode started,
3. runs the same image on spinemu (compat="spinsim") with the recorder on,
   which gives the same bytecodes with spinemu's view of them (operands,
   stack values, whether a jump was taken),
4. turns each bytecode into a timing *name* (the ones :class:`Timing` reads)
   and checks that every name always took the same number of cycles.

Names that combine (a USING access plus an assignment operator) are solved
as sums; loops (string, fill and move bytecodes) as ``base + per * count``.
It then writes spinemu/chip/timing_data.py (``--check`` only compares).
Nothing from spinsim or the ROM is stored: only cycle counts.
"""
from __future__ import annotations

import argparse
import collections
import glob
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, ROOT)
sys.path.insert(0, HERE)

from spinemu.bytecode import instruction_length  # noqa: E402
from spinemu.chip import Chip  # noqa: E402
from spinemu.chip.rom import build_rom  # noqa: E402
import spinsim_log  # noqa: E402

ROM = build_rom()


def compile_spin(openspin: str, path: str, out: str) -> bytes:
    r = subprocess.run([openspin, "-q", "-L", os.path.dirname(os.path.abspath(path)), "-b", path, "-o", out],
                       capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError(f"{path}: {r.stdout}{r.stderr}")
    with open(out, "rb") as f:
        return f.read()


def spinsim_records(spinsim: str, image_path: str, log_path: str, instructions: int) -> dict:
    """Per cog: bytecode records, RUN merged with the ROM routine it runs."""
    spinsim_log.run_spinsim_log(spinsim, image_path, log_path, instructions)
    cogs = spinsim_log.parse_log(log_path)
    out = {}
    for cog, events in cogs.items():
        recs = spinsim_log.bytecodes(events)
        merged = []
        for r in recs:
            if merged and merged[-1]["op"] == 0x15 and (0xFF00 <= r["pc"] < 0xFFF9 or r["pc"] >= 0xFFFC):
                continue                      # inside cognew's ROM routine
            merged.append(r)
        for a, b in zip(merged, merged[1:]):
            a["rest"] = b["start"] - a["tf"]
            a["next_start"] = b["start"]
        out[cog] = {"records": merged, "events": events}
    return out


def spinemu_records(image: bytes, max_cycles: int) -> dict:
    chip = Chip(image, compat="spinsim", fast_forward=False)
    chip.recorder = []
    try:
        chip.run(max_cycles=max_cycles)
    except Exception as e:  # keep what was recorded
        print("  spinemu stopped:", e)
    out = collections.defaultdict(list)
    for rec in chip.recorder:
        out[rec[0]].append(rec)
    return out, chip


def code_bytes(chip, pc: int, n: int = 6) -> bytes:
    return bytes(chip.mem[pc: pc + n])


# ----------------------------------------------------------------------------- naming
def assign_jump_long(code, k) -> bool:
    """Whether the REPEAT assignment operator at code[k] has a two-byte jump."""
    return k + 1 < len(code) and bool(code[k + 1] & 0x80)


def name_of(chip, rec) -> tuple:
    """``(names, context)``: the timing names whose sum is this bytecode's rest."""
    cog, pc, op, t, tf, t_next, before, after, target = rec
    code = code_bytes(chip, pc)
    length = instruction_length(code, 0) if pc < 0xFFF0 else 2 if op == 0x3F else 1
    pc_after_seq = (pc + length) & 0xFFFF
    nxt = NEXT_PC.get(id(rec))
    jumped = nxt is not None and nxt != pc_after_seq
    long_ = bool(code[1] & 0x80) if len(code) > 1 else False
    lg = "long" if long_ else "short"
    if op <= 0x03:
        return ["frame"], None
    if op == 0x04:
        return [f"jmp/{lg}"], None
    if op in (0x05, 0x06, 0x07):
        return [("call", "call_obj", "call_obj_x")[op - 5]], None
    if op in (0x08, 0x09, 0x0A, 0x0B, 0x0D, 0x0E):
        n = {8: "tjz", 9: "djnz", 10: "jz", 11: "jnz", 13: "case_value", 14: "case_range"}[op]
        return [f"{n}/{lg}/{'taken' if jumped else 'not'}"], None
    if op == 0x0C:
        return ["case_done"], None
    if op == 0x0F:
        return ["look_done"], None
    if 0x10 <= op <= 0x13:
        n = ("lookup_value", "lookdown_value", "lookup_range", "lookdown_range")[op - 0x10]
        return [f"{n}/{'found' if jumped else 'not'}"], None
    if op == 0x14:
        return ["pop"], None
    if op == 0x15:
        return [("run", (before[1] >> 8) & 0xFF)], None
    if op == 0x16:
        return [("strsize", after[0])], None
    if op == 0x17:                  # characters compared (recorded before it ran)
        return [("strcomp_eq" if after[0] else "strcomp_ne", before[4])], None
    if 0x18 <= op <= 0x1A:
        return [(("bytefill", "wordfill", "longfill")[op - 0x18], before[0])], None
    if 0x1C <= op <= 0x1E:
        return [(("bytemove", "wordmove", "longmove")[op - 0x1C], before[0])], None
    if op == 0x20:
        return ["clkset"], None
    if op == 0x21:
        return ["cogstop"], None
    if op == 0x22:
        return ["lockret"], None
    if op in (0x1B, 0x1F, 0x23, 0x27):
        return [("wait", op)], None
    if op == 0x24:
        return ["spr/push"], None
    if op == 0x25:
        return ["spr/pop"], None
    if op == 0x26:
        return ["spr/using", ("assign", code[1], before, jumped, "reg", assign_jump_long(code, 1))], None
    if op in (0x28, 0x2C):
        return ["coginit/result" if op == 0x28 else "coginit"], None
    if op in (0x29, 0x2D):
        return ["locknew/result" if op == 0x29 else "locknew"], None
    if op in (0x2A, 0x2B, 0x2E, 0x2F):
        return [("lockset" if op in (0x2A, 0x2E) else "lockclr") + ("/result" if op < 0x2C else "")], None
    if 0x30 <= op <= 0x33:
        frames = before[4] if op < 0x32 else 1
        return [("return", op, frames, nxt)], None
    if 0x34 <= op <= 0x36:
        return ["push_const"], None
    if op == 0x37:
        return ["push_mask"], None
    if 0x38 <= op <= 0x3B:
        return [f"push_imm/{op - 0x37}"], None
    if op in (0x3D, 0x3E, 0x3F):
        reg = code[1]
        access = (reg >> 5) & 3
        r = 0x1E0 + (reg & 0x1F)
        pins = r in (0x1F4, 0x1F6)
        base = f"reg/{op:02x}/{access}"
        if access == 2:
            extra = 1 if op == 0x3D else 2 if op == 0x3E else 0
            return [base, ("assign", code[2], before[extra:], jumped, "reg", assign_jump_long(code, 2))], ("reg", r)
        return [base], ("reg", r)
    if 0x40 <= op <= 0x7F:
        if op & 3 == 2:
            return [f"var_using/{'loc' if op & 0x20 else 'var'}", ("assign", code[1], before, jumped, "mem", assign_jump_long(code, 1))], None
        return [f"var/{op:02x}"], None
    if 0x80 <= op <= 0xDF:
        base = (op >> 2) & 3
        name = f"mem/{op:02x}" + ("/long" if base and long_ else "")
        if op & 3 == 2:
            k = 1 + (2 if base and long_ else 1 if base else 0)
            pops = (1 if op & 0x10 else 0) + (1 if base == 0 else 0)
            return [name, ("assign", code[k], before[pops:], jumped, "mem", assign_jump_long(code, k))], None
        return [name], None
    return [("math", op, before[1], before[0])], None


NEXT_PC = {}


def collect(probes, openspin, spinsim, instructions, max_cycles, verbose=False):
    obs = []
    with tempfile.TemporaryDirectory() as tmp:
        for src in probes:
            name = os.path.splitext(os.path.basename(src))[0]
            img_path = os.path.join(tmp, name + ".binary")
            image = compile_spin(openspin, src, img_path)
            ref = spinsim_records(spinsim, img_path, os.path.join(tmp, name + ".log"), instructions)
            mine, chip = spinemu_records(image, max_cycles)
            n_ok = 0
            for cog, data in ref.items():
                recs = data["records"]
                my = mine.get(cog, [])
                for i, (r, m) in enumerate(zip(recs, my)):
                    if r["pc"] != m[1] or r["op"] != m[2]:
                        print(f"  {name}: cog {cog} diverges at bytecode {i}: spinsim ${r['pc']:04X} op ${r['op']:02X}"
                              f" / spinemu ${m[1]:04X} op ${m[2]:02X}")
                        break
                    if i + 1 < len(my):
                        NEXT_PC[id(m)] = my[i + 1][1]
                        if my[i + 1][3] != m[5]:
                            continue                  # the cog was stopped and started again
                    if "rest" not in r:
                        continue
                    names, ctx = name_of(chip, m)
                    obs.append((names, r["rest"], name, cog, r, m, ctx))
                    n_ok += 1
            if verbose:
                print(f"  {name}: {n_ok} bytecodes matched")
    return obs


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("--instructions", type=int, default=3_000_000)
    ap.add_argument("--max-cycles", type=int, default=40_000_000)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("probes", nargs="*")
    a = ap.parse_args(argv)
    probes = a.probes or sorted(glob.glob(os.path.join(ROOT, "tests/data/chip/programs/*.spin")))
    obs = collect(probes, a.openspin, a.spinsim, a.instructions, a.max_cycles, verbose=True)
    from solve_timing import solve
    data, problems = solve(obs)
    for p in problems:
        print("PROBLEM:", p)
    if not a.check:
        write_table(data)
    return 1 if problems else 0


def write_table(data: dict) -> None:
    path = os.path.join(ROOT, "spinemu/chip/timing_data.py")
    lines = ["# Generated by tests/chip/tools/derive_timing.py -- do not edit.",
             "# Cycle counts of Parallax's ROM Spin interpreter, measured on spinsim 0.99 (-p);",
             "# see spinemu/chip/timing.py for what the names mean.",
             "DATA = {"]
    for k in sorted(data, key=str):
        lines.append(f"    {k!r}: {data[k]!r},")
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
