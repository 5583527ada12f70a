#!/usr/bin/env python3
"""Random PASM programs run on spinsim and on spinemu: every instruction's cycle, result and flags.

Usage (from the worktree root; needs OpenSpin and spinsim)::

    python tests/chip/tools/pasm_random.py --count 300 --seed 1          # compare, report differences
    python tests/chip/tools/pasm_random.py --count 40 --seed 7 --record  # write the test sample

Each program (:func:`program`, deterministic for a seed) is one PASM cog
started by ``cognew(@entry, @buf)``: ``--length`` random instructions, then
``cogstop`` of itself.  The instructions are drawn from every family: ALU
instructions with random conditions, effects (``wz wc wr nr``), immediate
or register sources and the special registers as source or destination;
forward jumps (``jmp`` direct and through a register, ``jmpret``, ``djnz``,
``tjz``, ``tjnz``); hub reads and writes of every size in ``buf`` (some
misaligned); ``waitcnt`` 5..60 cycles ahead; ``waitpeq``/``waitpne`` that
hold at once; ``cogid`` and lock operations; ``waitvid``; ``movs``/``movd``
changing a later instruction's operands (the pipeline); ``nop``.  Jumps only
go forward and nothing writes code but ``movs``/``movd``, so every program
ends.  OpenSpin assembles the text, so the encodings are the reference's.

spinsim's instruction log gives each instruction's first cycle, the value
it wrote and the flags (tests/chip/tools/spinsim_log.py); its pins, end
cycle and hub RAM are compared too.  ``--record`` writes
``tests/data/chip/pasm_random/sample.json.gz`` (sources, images, what spinsim
did) for ``tests/chip/test_pasm_random.py``.
"""
from __future__ import annotations

import argparse
import gzip
import hashlib
import json
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, HERE)
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(HERE))
import spinsim_log  # noqa: E402
from chip_helpers import pasm_mismatches  # noqa: E402
from make_conformance import hub_dump  # noqa: E402

from spinemu import pasm  # noqa: E402
from spinemu.chip import Chip  # noqa: E402

SAMPLE = os.path.join(ROOT, "tests", "data", "chip", "pasm_random", "sample.json.gz")
REGS = [f"r{k}" for k in range(10)]
VALUES = [0, 1, 2, 31, 32, 0x1FF, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0xFFFFFFFE, 0x55AA55AA, 0x12345678]
ALU = sorted(m for m, ins in pasm.INSTRUCTIONS.items() if ins.kind == "alu")
CONDS = sorted(pasm.CONDITIONS)
#: special registers a random instruction may read, and write (counters stay off: spinsim has none)
SPECIAL_SRC = ["par", "cnt", "ina", "outa", "dira", "phsa", "vscl"]
SPECIAL_DST = ["outa", "dira", "cnt", "par", "ina", "phsb", "vcfg"]

HEADER = """'' random PASM program {name} (tests/chip/tools/pasm_random.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long buf[20]
PUB main
  cognew(@entry, @buf)
DAT
        org     0
entry   mov     hp, par
"""


def _effects(rng, *, wr_nr=True, default=()):
    effs = [e for e in ("wz", "wc") if rng.random() < 0.5]
    if wr_nr and rng.random() < 0.2:
        effs.append(rng.choice(["wr", "nr"]))
    return (" " + ", ".join(effs)) if effs else ""


def _cond(rng):
    return rng.choice(CONDS) if rng.random() < 0.4 else ""


def _src(rng, *, imm_range=512):
    r = rng.random()
    if r < 0.45:
        return f"#{rng.randrange(imm_range)}"
    if r < 0.9:
        return rng.choice(REGS)
    return rng.choice(SPECIAL_SRC)


def _dst(rng):
    return rng.choice(SPECIAL_DST) if rng.random() < 0.06 else rng.choice(REGS)


def program(seed: int, length: int) -> str:
    """The source of random program ``seed`` (about ``length`` instructions).

    The program is a list of groups (one instruction, or a few that belong
    together: ``mov``/``add``/``waitcnt``); jumps target the start of a
    later group, so none lands inside one.
    """
    rng = random.Random(seed)
    groups: list = []           # [lines] per group
    subs: list = []             # subroutines placed after the program
    labels: dict = {}           # group index -> label
    count = 0

    def target(ahead: int) -> str:
        k = len(groups) + ahead
        return labels.setdefault(k, f"L{k}")

    def add(*lines):
        nonlocal count
        groups.append(list(lines))
        count += len(lines)

    while count < length:
        kind = rng.choices(["alu", "jump", "hub", "waitcnt", "waitpin", "hubop", "selfmod", "waitvid", "nop",
                            "loop", "call"],
                           [60, 10, 10, 4, 3, 5, 5, 2, 1, 3, 3])[0]
        cond = _cond(rng)
        if kind == "alu":
            add(f"{cond:<12} {rng.choice(ALU):<7} {_dst(rng)}, {_src(rng)}{_effects(rng)}")
        elif kind == "jump":
            to = target(rng.randrange(1, 5))
            mn = rng.choice(["jmp", "jmpret", "djnz", "tjz", "tjnz", "jmpreg"])
            if mn == "jmp":
                add(f"{cond:<12} jmp     #{to}{_effects(rng, wr_nr=False)}")
            elif mn == "jmpreg":
                reg = rng.choice(REGS)
                add(f"{'':<12} mov     {reg}, #{to}", f"{cond:<12} jmp     {reg}{_effects(rng, wr_nr=False)}")
            elif mn == "jmpret":
                add(f"{cond:<12} jmpret  {rng.choice(REGS)}, #{to}{_effects(rng)}")
            else:
                add(f"{cond:<12} {mn:<7} {rng.choice(REGS)}, #{to}{_effects(rng)}")
        elif kind == "hub":
            size = rng.choice(["byte", "word", "long"])
            op = rng.choice(["rd", "wr"])
            effs = [e for e in ("wz", "wc") if rng.random() < 0.4]
            add(f"{'':<12} mov     ha, hp", f"{'':<12} add     ha, #{rng.randrange(64)}",
                f"{cond:<12} {op}{size:<5} {rng.choice(REGS)}, ha" + (" " + ", ".join(effs) if effs else ""))
        elif kind == "waitcnt":
            reg = rng.choice(REGS)
            add(f"{'':<12} mov     {reg}, cnt", f"{'':<12} add     {reg}, #{rng.randrange(5, 61)}",
                f"{cond:<12} waitcnt {reg}, {_src(rng, imm_range=64)}{_effects(rng)}")
        elif kind == "waitpin":                 # both hold at once (mask 0)
            reg = rng.choice(REGS)              # wr writes D - (INA & S): into a copy of zero/one
            if rng.random() < 0.5:
                add(f"{'':<12} mov     {reg}, #0", f"{cond:<12} waitpeq {reg}, #0{_effects(rng)}")
            else:
                add(f"{'':<12} mov     {reg}, #1", f"{cond:<12} waitpne {reg}, #0{_effects(rng)}")
        elif kind == "hubop":
            op = rng.choice(["cogid", "locknew", "lockret", "lockset", "lockclr"])
            add(f"{cond:<12} {op:<7} {rng.choice(REGS)}{_effects(rng)}")
        elif kind == "selfmod":                 # change an ALU instruction one or two ahead
            gap = rng.choice([1, 2])
            to = f"M{len(groups)}"
            lines = [f"{cond:<12} {rng.choice(['movs', 'movd']):<7} {to}, #{rng.choice(REGS)}"]
            if gap == 2:
                lines.append(f"{'':<12} {rng.choice(ALU):<7} {rng.choice(REGS)}, {_src(rng)}")
            lines.append(f"{to:<12} {rng.choice(ALU):<7} {rng.choice(REGS)}, {_src(rng)}{_effects(rng)}")
            add(*lines)
        elif kind == "waitvid":
            add(f"{cond:<12} waitvid {rng.choice(REGS)}, {_src(rng)}{_effects(rng, wr_nr=False)}")
        elif kind == "loop":                    # a backward djnz, 1..4 times round
            counter = rng.choice(REGS)
            others = [r for r in REGS if r != counter]
            head = f"B{len(groups)}"
            body = [f"{'':<12} {rng.choice(ALU):<7} {rng.choice(others)}, {_src(rng)}{_effects(rng)}"
                    for _ in range(rng.randrange(1, 4))]
            body[0] = f"{head:<12}" + body[0][12:]
            add(f"{'':<12} mov     {counter}, #{rng.randrange(1, 5)}", *body,
                f"{cond:<12} djnz    {counter}, #{head}{_effects(rng, wr_nr=False)}")
        elif kind == "call":                    # call/ret to a subroutine after the program
            name = f"S{len(groups)}"
            subs.append([f"{name:<12} {rng.choice(ALU):<7} {rng.choice(REGS)}, {_src(rng)}{_effects(rng)}",
                         f"{name + '_ret':<12} ret"])
            if rng.random() < 0.5:
                add(f"{cond:<12} call    #{name}")
            else:                               # the same through a register
                reg = rng.choice(REGS)
                add(f"{'':<12} mov     {reg}, #{name}", f"{cond:<12} jmpret  {name}_ret, {reg}")
        else:
            add(f"{'':<12} nop")
    out = []
    for k, lines in enumerate(groups):
        if k in labels:
            out.append(labels[k])
        out += lines
    out += [labels[k] for k in sorted(labels) if k >= len(groups)]
    out += [f"{'':<12} cogid   ha", f"{'':<12} cogstop ha"]
    for sub in subs:
        out += sub
    data = [f"{r:<12} long    ${rng.choice(VALUES) if rng.random() < 0.6 else rng.getrandbits(32):08X}"
            for r in REGS]
    data += ["hp           long    0", "ha           long    0", "zero         long    0", "one          long    1"]
    return HEADER.format(name=seed) + "\n".join("        " + x if x.startswith((" ", "if_"))
                                                else x for x in out + data) + "\n"


def spinsim_record(src: str, openspin: str, spinsim: str, tmp: str) -> tuple:
    """``(image, expected)``: OpenSpin's image of ``src`` and what spinsim did with it."""
    path = os.path.join(tmp, "r.spin")
    with open(path, "w") as f:
        f.write(src)
    r = subprocess.run([openspin, "-q", "-b", path, "-o", os.path.join(tmp, "r.binary")],
                       capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError(f"OpenSpin rejects the program: {r.stdout}{r.stderr}\n{src}")
    image_path = os.path.join(tmp, "r.binary")
    image = open(image_path, "rb").read()
    log = os.path.join(tmp, "r.log")
    subprocess.run([spinsim, "-p", "-l", log, "-400000", image_path], capture_output=True, timeout=600)
    cogs = spinsim_log.parse_log(log)
    if len(cogs.get(1, [])) > 300_000:
        raise RuntimeError(f"the program does not end on spinsim:\n{src}")
    end = max(line[0] for lines in cogs.values() for line in lines) + 4
    expected = {"end_cycle": end, "steps": spinsim_log.pasm_steps(cogs.get(1, [])),
                "pins": [list(p) for p in spinsim_log.pin_trace(cogs) if p[0] <= end],
                "hub_sha256": hashlib.sha256(hub_dump(spinsim, image_path)).hexdigest()}
    return image, expected


def compare(image: bytes, expected: dict) -> list:
    """Differences between spinemu's run of ``image`` and ``expected`` (empty: identical)."""
    chip = Chip(image)
    steps: list = []
    chip.trace_cog(1, steps.append)
    result = chip.run(max_cycles=10 * expected["end_cycle"] + 100_000)
    bad = pasm_mismatches(expected["steps"], steps)
    if len(steps) != len(expected["steps"]):
        bad.append(f"{len(steps)} instructions, spinsim {len(expected['steps'])}")
    if [list(c) for c in result.trace.changes] != expected["pins"]:
        bad.append(f"pins differ: {result.trace.changes[:6]} vs {expected['pins'][:6]}")
    if result.end_cycle != expected["end_cycle"]:
        bad.append(f"end cycle {result.end_cycle}, spinsim {expected['end_cycle']}")
    if hashlib.sha256(result.hub).hexdigest() != expected["hub_sha256"]:
        bad.append("hub RAM differs")
    return bad


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1, help="first program's seed (then seed+1, ...)")
    ap.add_argument("--length", type=int, default=60, help="random instructions per program")
    ap.add_argument("--record", action="store_true", help=f"write the programs and spinsim's results to {SAMPLE}")
    a = ap.parse_args(argv)
    failed = 0
    sample = []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(a.seed, a.seed + a.count):
            src = program(seed, a.length)
            image, expected = spinsim_record(src, a.openspin, a.spinsim, tmp)
            bad = compare(image, expected)
            if bad:
                failed += 1
                print(f"seed {seed}: {len(bad)} differences: " + " | ".join(bad[:3]))
            sample.append({"seed": seed, "source": src, "binary": image.hex(), "expected": expected})
    n_steps = sum(len(p["expected"]["steps"]) for p in sample)
    print(f"{a.count} programs, {n_steps} instructions compared: {a.count - failed} identical, {failed} differ")
    if a.record:
        os.makedirs(os.path.dirname(SAMPLE), exist_ok=True)
        with gzip.open(SAMPLE, "wt") as f:
            json.dump({"source": "tests/chip/tools/pasm_random.py; spinsim 0.99 -p; see tests/data/README.md",
                       "length": a.length, "programs": sample}, f, separators=(",", ":"))
            f.write("\n")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
