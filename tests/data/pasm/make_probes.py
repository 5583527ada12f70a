"""Write the PASM probe files of tests/data/pasm (and optionally compile them).

Each probe set is a DAT-only Spin file: after a two-long header (the labels
``lab`` at $123 and ``lab_ret`` at $1EE, for ``call #lab``) every line is one
case and assembles to one long (``org 0`` lines restart the cog address every
256 cases).  Error probes are one file each; errors.json records the line,
the spinemu.pasm.encode arguments it stands for, spinemu's message and what
OpenSpin said.

Usage (from the repository root)::

    python tests/data/pasm/make_probes.py [--openspin PATH]

With ``--openspin`` the probes are compiled with ``openspin -q -c`` (DAT
only) into ``<name>.dat``, and error messages are recorded.  The probes are
hand-designed (sets ``instructions``, ``conditions``, ``operands``) or drawn
from a fixed seed (``words``: every opcode x zcri value, plus random longs,
written as spinemu's disassembly so that OpenSpin checks the text).
"""
from __future__ import annotations

import argparse
import itertools
import json
import random
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2]))

from spinemu import pasm  # noqa: E402

LAB, LAB_RET = 0x123, 0x1EE          # cog addresses of the call probe's labels
HEAD = ["DAT", "        org $123", "lab     long 0", "        org $1EE", "lab_ret long 0"]
TAIL = ["", "PUB main", ""]
ORG_EVERY = 256


def case(line, **kw):
    """One probe: its PASM line and the spinemu.pasm.encode arguments it stands for."""
    return line, kw


def operand_cases(ins):
    """(text, kwargs) per operand form of one instruction."""
    m = ins.mnemonic
    if ins.operands == "ds":
        return [(f"{m} $0A5, $15A", dict(dest=0xA5, src=0x15A)),
                (f"{m} $15A, #$0A5", dict(dest=0x15A, src=0xA5, immediate=True))]
    if ins.operands == "d":
        return [(f"{m} $0A5", dict(dest=0xA5))]
    if ins.operands == "s":
        return [(f"{m} $0A5", dict(src=0xA5)), (f"{m} #$15A", dict(src=0x15A, immediate=True))]
    if ins.operands == "call":
        return [(f"{m} #lab", dict(dest=LAB_RET, src=LAB, immediate=True))]
    return [(m, {})]


def effect_lists(ins):
    if ins.kind == "nop":
        return [[]]
    names = ["wz", "wc", "wr", "nr"] if ins.allows_wr_nr else ["wz", "wc"]
    out = []
    for n in range(len(names) + 1):
        out += [list(c) for c in itertools.combinations(names, n)]
    if ins.allows_wr_nr:
        out += [["nr", "wr"], ["wc", "nr", "wz"], ["wr", "wz", "nr"]]
    return out


def instructions_set():
    cases = []
    for ins in pasm.INSTRUCTIONS.values():
        for text, kw in operand_cases(ins):
            for effs in effect_lists(ins):
                line = text + (" " + ", ".join(effs) if effs else "")
                cases.append(case(line, mnemonic=ins.mnemonic, effects=effs, **kw))
    # upper and mixed case spellings
    cases.append(case("MOV $005, #$003 WZ", mnemonic="MOV", effects=["WZ"], dest=5, src=3, immediate=True))
    cases.append(case("If_Nz Djnz $005, #$002 Wc", mnemonic="Djnz", condition="If_Nz", effects=["Wc"],
                      dest=5, src=2, immediate=True))
    return cases


def conditions_set():
    cases = []
    samples = [("mov", "mov $005, #$003", dict(dest=5, src=3, immediate=True)),
               ("djnz", "djnz $1FF, #$100 wz", dict(dest=0x1FF, src=0x100, immediate=True, effects=["wz"])),
               ("jmp", "jmp #$007", dict(src=7, immediate=True)),
               ("ret", "ret", {}),
               ("call", "call #lab", dict(dest=LAB_RET, src=LAB, immediate=True)),
               ("cogid", "cogid $004 wc", dict(dest=4, effects=["wc"])),
               ("test", "test $001, $002 wc, wz", dict(dest=1, src=2, effects=["wc", "wz"]))]
    for cond in pasm.CONDITIONS:
        for mnem, text, kw in samples:
            cases.append(case(f"{cond} {text}", mnemonic=mnem, condition=cond, **kw))
    return cases


def operands_set():
    cases = []
    values = [0, 1, 2, 0x55, 0xAA, 0x100, 0x155, 0x1AA, 0x1EF, 0x1FF]
    for v in values:
        cases.append(case(f"mov ${v:03X}, ${0x1FF - v:03X}", mnemonic="mov", dest=v, src=0x1FF - v))
        cases.append(case(f"add ${v:03X}, #${v:03X}", mnemonic="add", dest=v, src=v, immediate=True))
        cases.append(case(f"jmp #${v:03X}", mnemonic="jmp", src=v, immediate=True))
    for name, addr in pasm.REGISTERS.items():
        cases.append(case(f"mov {name}, {name.lower()}", mnemonic="mov", dest=addr, src=addr))
        cases.append(case(f"or {name}, #{addr}", mnemonic="or", dest=addr, src=addr, immediate=True))
        cases.append(case(f"cogid {name}", mnemonic="cogid", dest=addr))
    for text in ["-1", "-2", "-$1FF", "-$200", "-$12345"]:
        v = -int(text[2:], 16) if "$" in text else int(text)
        cases.append(case(f"mov $005, #{text}", mnemonic="mov", dest=5, src=v, immediate=True))
        cases.append(case(f"mov {text}, $005", mnemonic="mov", dest=v, src=5))
        cases.append(case(f"jmp #{text}", mnemonic="jmp", src=v, immediate=True))
        cases.append(case(f"djnz $005, #{text}", mnemonic="djnz", dest=5, src=v, immediate=True))
        cases.append(case(f"cogid {text}", mnemonic="cogid", dest=v))
    cases.append(case("if_never mov $005, #$003", mnemonic="mov", condition="if_never", dest=5, src=3,
                      immediate=True))
    return cases


def words_set():
    """Every opcode x zcri value with random fields, and 1000 random longs."""
    rng = random.Random(20240601)
    words = [0]
    for opcode, zcri in itertools.product(range(64), range(16)):
        words.append((opcode << 26) | (zcri << 22) | rng.getrandbits(22))
    # the fields the alias choice depends on, with the rest random
    for zcri in range(16):
        for src in list(range(9)) + [0x1FF]:
            for dest in (0, 1, 0x1FF):
                cond = rng.getrandbits(4)
                words.append((0b000011 << 26) | (zcri << 22) | (cond << 18) | (dest << 9) | src)
                words.append((0b010111 << 26) | (zcri << 22) | (cond << 18) | (dest << 9) | src)
    for cond in range(16):
        words.append(cond << 18)
        words.append((cond << 18) | 1)
    words += [rng.getrandbits(32) for _ in range(1000)]
    return [(" ".join(pasm.disassemble(w).split()), None) for w in words]


ERRORS = [
    # line, encode kwargs, spinemu's message
    ("mov $200, #3", dict(mnemonic="mov", dest=0x200, src=3, immediate=True),
     "destination operand $200 exceeds $1FF"),
    ("mov 5, #$200", dict(mnemonic="mov", dest=5, src=0x200, immediate=True),
     "source operand $200 exceeds $1FF"),
    ("mov 5, $3FF", dict(mnemonic="mov", dest=5, src=0x3FF), "source operand $3FF exceeds $1FF"),
    ("jmp 5, #3", dict(mnemonic="jmp", dest=5, src=3, immediate=True),
     "instruction 'jmp' takes no destination operand"),
    ("ret 5", dict(mnemonic="ret", dest=5), "instruction 'ret' takes no destination operand"),
    ("ret #3", dict(mnemonic="ret", src=3, immediate=True), "instruction 'ret' takes no source operand"),
    ("call 5", dict(mnemonic="call", dest=LAB_RET, src=5), "'call' needs '#' before its label"),
    ("if_z nop", dict(mnemonic="nop", condition="if_z"), "'nop' cannot have a condition"),
    ("nop wz", dict(mnemonic="nop", effects=["wz"]), "'nop' cannot have effects"),
    ("wrlong 3, 4 wr", dict(mnemonic="wrlong", dest=3, src=4, effects=["wr"]),
     "'wrlong' cannot use wr or nr (hub memory instruction)"),
    ("rdbyte 3, #4 wz, nr", dict(mnemonic="rdbyte", dest=3, src=4, immediate=True, effects=["wz", "nr"]),
     "'rdbyte' cannot use wr or nr (hub memory instruction)"),
    ("cogid 3, 4", dict(mnemonic="cogid", dest=3, src=4), "instruction 'cogid' takes no source operand"),
    ("cogid #3", dict(mnemonic="cogid", dest=3, immediate=True),
     "instruction 'cogid' has no source operand to make immediate"),
    ("mov 3", dict(mnemonic="mov", dest=3), "instruction 'mov' needs a source operand"),
    ("tjz 3", dict(mnemonic="tjz", dest=3), "instruction 'tjz' needs a source operand"),
    ("mov 3, 4 wx", dict(mnemonic="mov", dest=3, src=4, effects=["wx"]),
     "unknown effect 'wx' (expected wz, wc, wr or nr)"),
    ("foo 3, 4", dict(mnemonic="foo", dest=3, src=4), "unknown instruction 'foo'"),
]

SETS = {"instructions": instructions_set, "conditions": conditions_set,
        "operands": operands_set, "words": words_set}


def write_set(name, cases):
    lines = list(HEAD)
    for k, (line, _) in enumerate(cases):
        if k % ORG_EVERY == 0:
            lines.append("        org 0")
        lines.append("        " + line)
    (HERE / f"{name}.spin").write_text("\n".join(lines + TAIL))


def compile_sets(openspin):
    for name in SETS:
        subprocess.run([openspin, "-q", "-c", f"{name}.spin", "-o", f"{name}.dat"], cwd=HERE, check=True)
    errors = []
    for k, (line, kw, message) in enumerate(ERRORS):
        spin = HERE / "errors" / f"error{k:02d}.spin"
        spin.parent.mkdir(exist_ok=True)
        spin.write_text("\n".join(["DAT", "        org 0", "        " + line, "lab_ret long 0",
                                   "lab     long 0"] + TAIL))
        run = subprocess.run([openspin, "-q", "-c", spin.name, "-o", "/dev/null"], cwd=spin.parent,
                             capture_output=True, text=True)
        said = re.search(r"error : (.*)", run.stdout + run.stderr)
        errors.append({"line": line, "encode": kw, "message": message, "openspin_exit": run.returncode,
                       "openspin": said.group(1).strip() if said else None, "file": f"errors/{spin.name}"})
    (HERE / "errors.json").write_text("[\n" + ",\n".join(json.dumps(e) for e in errors) + "\n]\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--openspin", help="path of the openspin executable; compile the probes")
    args = ap.parse_args()
    for name, make in SETS.items():
        write_set(name, make())
    if args.openspin:
        compile_sets(args.openspin)


if __name__ == "__main__":
    main()
