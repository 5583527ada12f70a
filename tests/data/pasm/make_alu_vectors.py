"""Measure PASM ALU results (result, C, Z) on spinsim; write tests/data/pasm/alu_vectors.txt.

Probe images (our own PASM, compiled by OpenSpin) run one loop on cog 0: it
reads a vector from hub (instruction long, D, S, a long whose bit 31 is the
C input, a long that is 0 for a Z input of 1), sets C with ``mov tmp, c wc``
and Z with ``mov tmp, z wz``, then executes the instruction long on the D and
S registers (always with ``wz, wc``).  spinsim's instruction log (``-l``)
prints result and flags of every executed instruction; they are read back
from the lines at the slot's cog address.

Usage (from the repository root)::

    python tests/data/pasm/make_alu_vectors.py --openspin PATH --spinsim PATH

Output: ``mnemonic D S C Z -> result C Z`` per line, hex longs and 0/1 flags;
``result`` is the long written to D, ``--------`` for instructions that do not
write (``test``, ``cmp``...: their ``wr`` forms ``and``, ``sub``... show it).
"""
from __future__ import annotations

import argparse
import itertools
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2]))

from spinemu import pasm  # noqa: E402

D_VALUES = [0x00000000, 0x00000001, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0x89ABCDEF]
S_VALUES = [0x00000000, 0x00000001, 0x00000004, 0x0000001F, 0x00000121,
            0x80000000, 0xFFFFFFFF, 0x12345678]
#: instructions whose result depends on the C or Z input
FLAG_READERS = {"rcr", "rcl", "muxc", "muxnc", "muxz", "muxnz", "sumc", "sumnc", "sumz", "sumnz",
                "negc", "negnc", "negz", "negnz", "addx", "subx", "cmpx", "addsx", "subsx", "cmpsx"}
VECTORS_PER_IMAGE = 1200
SLOT, DREG, SREG = 15, 18, 19          # cog addresses in PROBE (checked against the log)

PROBE = """PUB main
  coginit(0, @entry, @vectors)

DAT
              org     0
entry         mov     ptr, par
              rdlong  count, ptr
              add     ptr, #4
loop          rdlong  slot, ptr
              add     ptr, #4
              rdlong  dreg, ptr
              add     ptr, #4
              rdlong  sreg, ptr
              add     ptr, #4
              rdlong  cin, ptr
              add     ptr, #4
              rdlong  zin, ptr
              add     ptr, #4
              mov     tmp, cin        wc
              mov     tmp, zin        wz
slot          nop
              djnz    count, #loop
halt          jmp     #halt
dreg          long    0
sreg          long    0
ptr           long    0
count         long    0
cin           long    0
zin           long    0
tmp           long    0

vectors       long    {count}
{table}
"""
LOG_LINE = re.compile(r"Cog 0:\s+\d+ ([0-9a-f]{3}) ([0-9a-f]{8}) .* Z=(\d) C=(\d)(?: R=([0-9a-f]{8}))?$")


def vectors():
    for ins in pasm.INSTRUCTIONS.values():
        if ins.kind != "alu":
            continue
        flags = [(c, z) for c in (0, 1) for z in (0, 1)] if ins.mnemonic in FLAG_READERS else [(0, 0), (1, 1)]
        for d, s, (c, z) in itertools.product(D_VALUES, S_VALUES, flags):
            yield ins.mnemonic, d, s, c, z


def run_image(batch, openspin: str, spinsim: str, work: Path):
    rows = []
    for mnem, d, s, c, z in batch:
        word = pasm.encode(mnem, dest=DREG, src=SREG, effects=["wz", "wc"])
        rows.append(f"              long    ${word:08X}, ${d:08X}, ${s:08X}, ${c << 31:08X}, {0 if z else 1}")
    (work / "alu.spin").write_text(PROBE.format(count=len(batch), table="\n".join(rows)))
    subprocess.run([openspin, "-q", "-b", "alu.spin", "-o", "alu.binary"], cwd=work, check=True)
    steps = 80 * len(batch) + 2000            # hub waits are logged as steps too
    subprocess.run([spinsim, "-l", "alu.log", f"-{steps}", "alu.binary"], cwd=work, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    results = []
    for line in (work / "alu.log").read_text().splitlines():
        m = LOG_LINE.match(line)
        if m and int(m.group(1), 16) == SLOT:
            result = None if m.group(5) is None else int(m.group(5), 16)
            results.append((int(m.group(2), 16), result, int(m.group(4)), int(m.group(3))))
    if len(results) < len(batch):
        raise SystemExit(f"spinsim logged {len(results)} of {len(batch)} vectors; raise the step count")
    out = []
    for (mnem, d, s, c, z), (word, r, c_out, z_out) in zip(batch, results):
        assert word == pasm.encode(mnem, dest=DREG, src=SREG, effects=["wz", "wc"]), (mnem, hex(word))
        shown = "--------" if r is None else f"{r:08X}"
        out.append(f"{mnem} {d:08X} {s:08X} {c} {z} -> {shown} {c_out} {z_out}")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--openspin", required=True)
    ap.add_argument("--spinsim", required=True)
    args = ap.parse_args()
    todo = list(vectors())
    lines = ["# PASM ALU vectors measured on spinsim 0.99 (instruction log); see make_alu_vectors.py",
             "# mnemonic D S C Z -> result C Z"]
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(0, len(todo), VECTORS_PER_IMAGE):
            lines += run_image(todo[k:k + VECTORS_PER_IMAGE], args.openspin, args.spinsim, Path(tmp))
    (HERE / "alu_vectors.txt").write_text("\n".join(lines) + "\n")
    print(f"{len(lines) - 2} vectors")


if __name__ == "__main__":
    main()
