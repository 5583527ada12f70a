#!/usr/bin/env python3
"""Measure when the ROM interpreter reads and writes back the target of update bytecodes.

Usage (from the worktree root; needs OpenSpin and spinsim, which tests never need)::

    python tests/chip/tools/derive_update_moments.py [--openspin PATH] [--spinsim PATH]
        [--json PATH] [--keep DIR] [--only SUBSTRING] [--brief]

An *update* bytecode is a USING access (low two bits ``10``) of a VAR/LOC
long ($40-$7F) or of memory ($80-$DF) followed by an assignment operator
(``x++``, ``x += n``, ``x~``, ``n := x := v``...).  Parallax's ROM interpreter
reads the target in one hub window and writes it back in a later one; this
tool finds both moments on spinsim (cycle-exact cogs running the ROM
interpreter), per variant.

It

1. generates one short probe program per target kind (VAR, LOC, DAT and
   ``long/word/byte[addr]``; byte/word/long; indexed or not; one- and
   two-byte offsets), each applying every assignment operator, in its
   statement form and in its pushing form (``n := x OP= v``), to several
   (old value, operand) pairs,
2. compiles it with OpenSpin and runs it on one cog of spinsim with ``-p -l``,
3. follows the cog's registers through the log (every ``R=`` value), so that
   every hub instruction gets its hub address, and splits the bytecode's hub
   instructions into the opcode/operand fetches (the register the fetch at
   $009 reads through), the stack (the register a constant push ($34-$3B) writes
   through) and the *target*: all others, which must all hit one address
   per probe,
4. reports, per variant, the offsets of the target reads and writes from the
   fetch.

Reference: ``tf`` as in :mod:`spinsim_log`/``derive_timing`` is the cycle of
the interpreter's instruction at $00A, the first one after the opcode fetch
(the fetch's hub instruction has its own non-waiting log line at ``tf - 4``).
A hub instruction's moment is given as the cycle its non-waiting log line
shows, minus ``tf``, **plus 4** -- i.e. the cycle at which the instruction
completes and the next one starts.  That is the convention of
``spinemu.chip.timing.access_offsets`` (a VAR long POP's wrlong logs at
tf+140 and access_offsets says 144).  Subtract 4 for the log line itself
(the figures "rdlong +188 / wrlong +316" of a hand reading are log lines).
Since every hub instruction waits for the cog's window, all such offsets are
``16*k`` relative to the fetch's own hub access.

Nothing from spinsim or the ROM is stored: only cycle counts and the values
the log shows.
"""
from __future__ import annotations

import argparse
import collections
import json
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, ROOT)
sys.path.insert(0, HERE)

import derive_timing  # noqa: E402  (inserts the paths it needs)
import spinsim_log  # noqa: E402
from spinemu.bytecode import decode_assign  # noqa: E402

# ----------------------------------------------------------------------------- probes
#: (old value, operand) pairs applied with every operator
PAIRS = [(12345, 3), (0, 0), (-1, 1000), ("$7FFF_FFFF", -7), (987654321, 123456789),
         (5, 31), (-100000, 77), (1, 1)]

#: binary assignment operators (Spin symbol)
BINARY = ["+=", "-=", "*=", "**=", "/=", "//=", "&=", "|=", "^=", "<<=", ">>=", "~>=",
          "->=", "<-=", "><=", "#>=", "<#=", "AND=", "OR=", "<=", ">=", "<>=", "===", "=<=", "=>="]
#: unary assignment operators (prefix)
UNARY = ["-", "!", "||", "^^", ">|", "|<", "NOT "]
#: operators without an operand: (statement form, pushing form)
SIMPLE = [("{t}++", "n := {t}++"), ("{t}--", "n := {t}--"), ("++{t}", "n := ++{t}"),
          ("--{t}", "n := --{t}"), ("{t}~", "n := {t}~"), ("{t}~~", "n := {t}~~"),
          ("~{t}", "n := ~{t}"), ("~~{t}", "n := ~~{t}"), ("?{t}", "n := ?{t}"), ("{t}?", "n := {t}?")]

VAR_BLOCK = """VAR
  long n, vl, vpad[6]
  long vlf
  long va[4]
  word vw, vwa[4]
  byte vb, vba[4]
"""
#: the same names, with every variable at a two-byte offset but n and vl
VAR_FAR_BLOCK = """VAR
  long n, vl, vpad[6]
  long vpad2[30]
  long vlf
  long va[4]
  word vw, vwa[4]
  byte vb, vba[4]
"""
DAT_BLOCK = """DAT
dl      long 0
dla     long 0[4]
dw      word 0
dwa     word 0[4]
db      byte 0
dba     byte 0[4]
dpad    long 0[40]
dlfar   long 0
"""
LOCALS = "i, p, a, b, c, d, e, f, la[4], big[30], z"

#: probe name -> target expression (``i`` holds 1, ``p`` the address of ``va``)
TARGETS = {
    "var_long": "vl",                 # $40-$5F compact
    "var_long_off1": "vlf",           # memory form, one-byte offset
    "var_long_off2": "vlf",           # two-byte offset (VAR_FAR_BLOCK for every *_off2 probe)
    "var_word_off2": "vw",
    "var_byte_off2": "vb",
    "var_long_idx_off2": "va[i]",
    "var_byte_idx_off2": "vba[i]",
    "var_word": "vw",
    "var_byte": "vb",
    "var_long_idx": "va[i]",
    "var_word_idx": "vwa[i]",
    "var_byte_idx": "vba[i]",
    "loc_long": "a",                  # $60-$7F compact
    "loc_long_off1": "f",
    "loc_long_off2": "z",
    "loc_long_idx": "la[i]",
    "loc_word_idx": "a.word[i]",
    "loc_byte_idx": "a.byte[i]",
    "loc_word": "a.word",
    "loc_byte": "a.byte",
    "dat_long": "dl",
    "dat_long_off2": "dlfar",
    "dat_word": "dw",
    "dat_byte": "db",
    "dat_long_idx": "dla[i]",
    "dat_word_idx": "dwa[i]",
    "dat_byte_idx": "dba[i]",
    "mem_long": "long[p]",
    "mem_word": "word[p]",
    "mem_byte": "byte[p]",
    "mem_long_idx": "long[p][i]",
    "mem_word_idx": "word[p][i]",
    "mem_byte_idx": "byte[p][i]",
    "values": None,                   # value sweeps of the value-dependent operators on vl
}

#: value sweeps: divisors and dividends of every bit length, ENCODE of every top bit
SWEEP_DIVISORS = [0, 1, -1] + [s * ((1 << k) | 1) for k in range(1, 32) for s in (1, -1)] + ["$8000_0000"]
SWEEP_DIVIDENDS = [0, 1, 1000, -1000, "$7FFF_FFFF", "$8000_0000", 123456789]


def statements(t: str) -> list:
    """Spin statements applying every operator to target ``t``."""
    out = []
    for old, v in PAIRS:
        def one(s, old=old):
            out.append(f"{t} := {old}")
            out.append(s)
        for st, pu in SIMPLE:
            one(st.format(t=t))
            one(pu.format(t=t))
        for op in BINARY:
            one(f"{t} {op} {v}")
            one(f"n := {t} {op} {v}")
        for op in UNARY:
            one(f"{op}{t}")
            one(f"n := {op}{t}")
        out.append(f"n := {t} := {v}")
    # REPEAT (loop variable): taken and not taken, with and without STEP
    for frm, to, step in ((0, 2, None), (5, 1, None), (0, 6, 3), (7, 1, -2)):
        st = f" step {step}" if step is not None else ""
        out.append(f"repeat {t} from {frm} to {to}{st}\n    n := 1")
    return out


def sweep_statements(t: str = "vl") -> list:
    """``t /= d``, ``t //= d`` over divisors and dividends; ENCODE, SQRT, MUL over values."""
    out = []
    for x in SWEEP_DIVIDENDS:
        for dv in SWEEP_DIVISORS:
            for op in ("/=", "//="):
                out += [f"{t} := {x}", f"{t} {op} {dv}"]
    for k in range(33):
        for x in ([0] if k == 32 else [1 << k, (1 << k) * 2 - 1 if k < 31 else -1]):
            for op in (">|", "^^", "|<", "||", "-"):
                out += [f"{t} := {x}", f"{op}{t}"]
            for op in ("*=", "**=", "->=", "<<=", "~>="):
                out += [f"{t} := {x}", f"{t} {op} {x}"]
    return out


def probe_source(name: str) -> str:
    t = TARGETS[name]
    stmts = sweep_statements() if t is None else statements(t)
    body = ["  i := 1", "  p := @va"] + ["  " + s for s in stmts]
    var = VAR_FAR_BLOCK if name.endswith("_off2") else VAR_BLOCK
    return var + DAT_BLOCK + f"PUB main | {LOCALS}\n" + "\n".join(body) + "\n"


# ----------------------------------------------------------------------------- log analysis
HUB = re.compile(r"\b(rd|wr)(byte|word|long)\s+([0-9a-f]{3}),\s*(#?)([0-9a-f]{3})")
SIZE_NAMES = ("byte", "word", "long")
BASE_NAMES = ("MEM", "DAT", "VAR", "LOC")


def hub_ops(events) -> dict:
    """``{id(line): (kind, size, addr_reg or None, address, value or None)}`` for every executed hub op.

    Registers are followed through the ``R=`` values of the log; a register
    no logged instruction has written yet has no known value (``None``).
    """
    regs: dict = {}
    out = {}
    for ev in events:
        cyc, addr, ins, flag, text = ev
        if flag != " ":
            continue
        m = HUB.search(text)
        r = spinsim_log.RVAL.search(text)
        if m:
            kind, size, _dst, imm, src = m.groups()
            src = int(src, 16)
            hub = src if imm else regs.get(src)
            out[id(ev)] = (kind, size, None if imm else src, hub, int(r.group(1), 16) if r else None)
        if r and int(ins, 16) & (1 << 23):
            regs[(int(ins, 16) >> 9) & 0x1FF] = int(r.group(1), 16)
    return out


def variant_of(image: bytes, pc: int, op: int):
    """``(key dict, assign byte)`` of the update bytecode at ``pc``, or None."""
    if op & 3 != 2 or not 0x40 <= op <= 0xDF:
        return None
    if op < 0x80:
        key = dict(family="compact", base="LOC" if op & 0x20 else "VAR", size="long", indexed=False, off_bytes=0)
        k = 1
    else:
        base = (op >> 2) & 3
        offb = 0 if base == 0 else (2 if image[pc + 1] & 0x80 else 1)
        key = dict(family="mem", base=BASE_NAMES[base], size=SIZE_NAMES[(op >> 5) & 3],
                   indexed=bool(op & 0x10), off_bytes=offb)
        k = 1 + offb
    a = image[pc + k]
    dec = decode_assign(a)
    name = dec.text[:-5] if dec.text.endswith("_PUSH") else dec.text
    key.update(operator=name, push=dec.push, opcode=f"{op:02X}")
    return key, a, dec


def analyse(name: str, image: bytes, ref: dict) -> list:
    """Samples of one probe: dict(key, read, write, ...) per update bytecode."""
    events = ref["events"]
    recs = ref["records"]
    ops = hub_ops(events)
    fetch_reg = stack_reg = None
    for r in recs:
        for ln in r["lines"]:
            h = ops.get(id(ln))
            if h and ln[1] == 0x009 and fetch_reg is None:
                fetch_reg = h[2]
            if h and 0x34 <= r["op"] <= 0x3B and h[0] == "wr" and stack_reg is None:   # constant push
                stack_reg = h[2]
        if fetch_reg is not None and stack_reg is not None:
            break
    if fetch_reg is None or stack_reg is None:
        raise RuntimeError(f"{name}: no opcode fetch or no constant push in the log")
    out = []
    for idx, r in enumerate(recs):
        v = variant_of(image, r["pc"], r["op"])
        if v is None:
            continue
        key, abyte, dec = v
        tf = r["tf"]
        target, stack = [], []
        for ln in r["lines"]:
            h = ops.get(id(ln))
            if not h or ln[1] == 0x009 and h[2] == fetch_reg and ln[0] < tf:
                continue
            kind, size, reg, hub, val = h
            rec = (kind, size, ln[0] - tf + 4, hub, val)
            if reg == fetch_reg:
                continue
            (stack if reg == stack_reg else target).append(rec)
        nxt = recs[idx + 1] if idx + 1 < len(recs) else None
        length = 1 + (0 if key["family"] == "compact" else key["off_bytes"]) + 1 + (
            (2 if image[r["pc"] + 2 + key["off_bytes"]] & 0x80 else 1) if dec.has_jump else 0)
        jumped = None
        if dec.has_jump and nxt is not None:
            jumped = nxt["pc"] != (r["pc"] + length) & 0xFFFF
        out.append(dict(probe=name, pc=r["pc"], key=key, tf=tf, jumped=jumped,
                        end=(r["next_start"] - tf) if "next_start" in r else None,
                        target=target, stack=stack))
    return out


def collect(openspin, spinsim, names, keep=None, instructions=2_000_000, verbose=True):
    samples = []
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        d = keep or tmp
        os.makedirs(d, exist_ok=True)
        for name in names:
            src = os.path.join(d, name + ".spin")
            with open(src, "w") as f:
                f.write(probe_source(name))
            img_path = os.path.join(d, name + ".binary")
            image = derive_timing.compile_spin(openspin, src, img_path)
            log = os.path.join(d, name + ".log")
            ref = derive_timing.spinsim_records(spinsim, img_path, log, instructions)
            if not keep:
                os.remove(log)
            got = analyse(name, image, ref[0])
            addrs = collections.Counter(t[3] & ~3 if t[1] == "long" else t[3] & ~1 if t[1] == "word" else t[3]
                                        for s in got for t in s["target"])
            if len(addrs) != 1:
                problems.append(f"{name}: target accesses hit {len(addrs)} addresses: "
                                + ", ".join(f"${a:04X}x{n}" if a is not None else f"?x{n}" for a, n in addrs.items()))
            for s in got:
                kinds = [t[0] for t in s["target"]]
                if "rd" not in kinds and s["key"]["operator"] != "WRITE" or "wr" not in kinds and s["jumped"] is None:
                    problems.append(f"{name} ${s['pc']:04X} {s['key']['operator']}: target ops {kinds}")
            if verbose:
                print(f"  {name}: {len(ref[0]['records'])} bytecodes, {len(got)} updates, target "
                      + ", ".join(f"${a:04X}" for a in addrs if a is not None), file=sys.stderr)
            samples += got
    return samples, problems


# ----------------------------------------------------------------------------- grouping
def vkey(k: dict) -> tuple:
    return (k["family"], k["base"], k["size"], k["indexed"], k["off_bytes"], k["operator"], k["push"])


def fmt_set(xs) -> str:
    xs = sorted(set(xs))
    if not xs:
        return "-"
    if len(xs) == 1:
        return str(xs[0])
    if len(xs) <= 3:
        return "/".join(map(str, xs))
    return f"{xs[0]}..{xs[-1]}({len(xs)})"


def summarise(samples) -> list:
    groups = collections.OrderedDict()
    for s in samples:
        k = vkey(s["key"]) + (("jump" if s["jumped"] else "nojump") if s["jumped"] is not None else "",)
        groups.setdefault(k, []).append(s)
    rows = []
    for k, ss in groups.items():
        reads = [tuple(t[2] for t in s["target"] if t[0] == "rd") for s in ss]
        writes = [tuple(t[2] for t in s["target"] if t[0] == "wr") for s in ss]
        r0 = [x[0] for x in reads if x]
        w_last = [x[-1] for x in writes if x]
        row = dict(family=k[0], base=k[1], size=k[2], indexed=k[3], off_bytes=k[4], operator=k[5],
                   push=k[6], repeat=k[7], opcodes=sorted({s["key"]["opcode"] for s in ss}),
                   samples=len(ss), reads=sorted(set(reads)), writes=sorted(set(writes)),
                   read=sorted(set(r0)), write=sorted(set(w_last)),
                   end=sorted({s["end"] for s in ss if s["end"] is not None}),
                   constant=len(set(reads)) == 1 and len(set(writes)) == 1)
        if not row["constant"]:
            row["by_sample"] = [dict(pc=s["pc"], probe=s["probe"], old=next((t[4] for t in s["target"] if t[0] == "rd"), None),
                                     stack_reads=[t[4] for t in s["stack"] if t[0] == "rd"],
                                     read=[t[2] for t in s["target"] if t[0] == "rd"],
                                     write=[t[2] for t in s["target"] if t[0] == "wr"]) for s in ss]
        rows.append(row)
    order = {"VAR": 0, "LOC": 1, "DAT": 2, "MEM": 3}
    rows.sort(key=lambda r: (r["family"] != "compact", order[r["base"]], r["size"], r["indexed"], r["off_bytes"],
                             r["operator"], r["push"], r["repeat"]))
    return rows


def table(rows) -> str:
    lines = [f"{'access':28} {'operator':22} {'p':1} {'n':>4} {'read':>14} {'write':>16} {'w-r':>9} {'end':>12}"]
    for r in rows:
        acc = f"{r['family'][:4]} {r['base']} {r['size']}{' idx' if r['indexed'] else ''}" \
              f"{' off' + str(r['off_bytes']) if r['off_bytes'] else ''} [{','.join(r['opcodes'])}]"
        op = r["operator"] + (f"/{r['repeat']}" if r["repeat"] else "")
        diff = sorted({w - rd for w in r["write"] for rd in r["read"]}) if len(r["read"]) == 1 else []
        extra = "" if r["constant"] else " *"
        if any(len(x) > 1 for x in r["reads"] + r["writes"]):
            extra += " multi:" + ";".join("R" + ",".join(map(str, x)) for x in r["reads"] if len(x) > 1) \
                     + ";".join("W" + ",".join(map(str, x)) for x in r["writes"] if len(x) > 1)
        lines.append(f"{acc:28} {op:22} {'P' if r['push'] else '-'} {r['samples']:>4} {fmt_set(r['read']):>14}"
                     f" {fmt_set(r['write']):>16} {fmt_set(diff):>9} {fmt_set(r['end']):>12}{extra}")
    return "\n".join(lines)


def rules(rows) -> str:
    """Two compact tables: the read moment per access kind, the write-back delay per operator."""
    acc = collections.OrderedDict()
    ops = collections.OrderedDict()
    for r in rows:
        a = f"{r['family'][:4]} {r['base']} {r['size']}{' idx' if r['indexed'] else ''}" \
            f"{' off' + str(r['off_bytes']) if r['off_bytes'] else ''} [{','.join(r['opcodes'])}]"
        e = acc.setdefault(a, dict(read=set(), write_only=set(), end_minus_write=set()))
        e["read"].update(r["read"])
        if r["operator"] == "WRITE":
            e["write_only"].update(r["write"])
        e["end_minus_write"].update(x - w for x in r["end"] for w in r["write"] if len(r["write"]) == 1)
        if r["read"]:
            o = r["operator"] + (f"/{r['repeat']}" if r["repeat"] else "")
            d = ops.setdefault(o, dict(delay=set(), push=set(), sizes=set(), n=0))
            d["delay"].update(w - rd for rd in r["read"] for w in r["write"])
            d["push"].add(r["push"])
            d["sizes"].add(r["size"])
            d["n"] += r["samples"]
    out = ["", "Read moment per access kind (all operators but WRITE read there; WRITE, which reads",
           "nothing, writes 16 cycles later; end - write = cycles from the write-back to the next bytecode):",
           f"{'access':30} {'read':>8} {'WRITE w':>8} {'end-w':>6}"]
    for a, e in acc.items():
        out.append(f"{a:30} {fmt_set(e['read']):>8} {fmt_set(e['write_only']):>8} {fmt_set(e['end_minus_write']):>6}")
    out += ["", "Write-back delay (write - read) per operator, over every access kind, size and push form:",
            f"{'operator':24} {'write-read':>14} {'samples':>8}"]
    for o, d in sorted(ops.items(), key=lambda kv: (min(kv[1]["delay"]), kv[0])):
        out.append(f"{o:24} {fmt_set(d['delay']):>14} {d['n']:>8}")
    return "\n".join(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--openspin", default="/opt/oracles/OpenSpin/build/openspin")
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("--instructions", type=int, default=2_000_000,
                    help="PASM instructions spinsim logs per probe")
    ap.add_argument("--json", help="write the per-variant results (and value-dependent samples) here")
    ap.add_argument("--keep", help="keep probe sources, images and logs in this directory")
    ap.add_argument("--brief", action="store_true", help="print only the two summary tables")
    ap.add_argument("--only", help="run only the probes whose name contains this")
    a = ap.parse_args(argv)
    names = [n for n in TARGETS if not a.only or a.only in n]
    samples, problems = collect(a.openspin, a.spinsim, names, a.keep, a.instructions)
    rows = summarise(samples)
    print("Offsets: cycles from tf (first instruction after the opcode fetch) to the completion of the")
    print("hub instruction (log line + 4, as spinemu.chip.timing.access_offsets counts). read = first")
    print("target read, write = last target write, end = start of the next bytecode; * = not constant.")
    if not a.brief:
        print(table(rows))
    print(rules(rows))
    for p in problems:
        print("PROBLEM:", p)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(dict(reference="tf = cycle of the interpreter's instruction at $00A; offset = "
                                     "non-waiting log line of the hub instruction - tf + 4",
                           variants=rows, problems=problems), f, indent=1)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
