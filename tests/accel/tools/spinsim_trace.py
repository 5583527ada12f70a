"""Pin trace of a Propeller image on spinsim 0.99 (cycle-exact PASM cogs), for the reference data.

Development tool (tests never run it): it runs a spinsim binary the user points
at with ``-p -l /dev/stdout -N`` (Parallax's ROM interpreter on cycle-exact
cogs, every executed instruction logged) and turns the logged writes to DIRA
and OUTA of every cog into a ``<cycle> <dir> <out>`` trace: ``dir`` the OR of
DIRA, ``out`` the OR of DIRA & OUTA.  A write logged at cycle c takes effect at
c + 4 (as in tests/chip/tools/spinsim_log.py).  Cogs that stop are not
noticed (their pins would float): use it for programs whose cogs keep running.

    python tests/accel/tools/spinsim_trace.py IMAGE.binary INSTRUCTIONS > out.trace
        [--spinsim /opt/oracles/spinsim/build/spinsim] [--until CYCLE]

Nothing of spinsim is stored; only what it printed ends up in the trace.
"""
from __future__ import annotations

import argparse
import re
import subprocess
import sys

LINE = re.compile(r"^Cog (\d):\s+(\d+) [0-9a-f]{3} ([0-9a-f]{8}) ([WXI ]) .*R=([0-9a-f]{8})")
OUTA, DIRA = 0x1F4, 0x1F6


def trace_lines(spinsim: str, image: str, instructions: int, until: int | None):
    proc = subprocess.Popen([spinsim, "-p", "-l", "/dev/stdout", f"-{instructions}", image],
                            stdout=subprocess.PIPE, text=True, bufsize=1 << 20)
    dira, outa = [0] * 8, [0] * 8
    last = None
    yield "0 00000000 00000000"
    for line in proc.stdout:
        if until is not None and line.startswith("Cog"):
            fields = line.split(None, 3)
            if fields[2].isdigit() and int(fields[2]) > until:
                break
        if "1f4" not in line and "1f6" not in line:
            continue
        m = LINE.match(line)
        if not m or m.group(4) != " ":
            continue
        cog, cycle, word, value = int(m.group(1)), int(m.group(2)), int(m.group(3), 16), int(m.group(5), 16)
        dest = (word >> 9) & 0x1FF
        if dest not in (OUTA, DIRA) or not (word >> 23) & 1:      # r bit: the result is written
            continue
        (outa if dest == OUTA else dira)[cog] = value
        d = o = 0
        for c in range(8):
            d |= dira[c]
            o |= dira[c] & outa[c]
        if (d, o) != last:
            last = (d, o)
            yield f"{cycle + 4} {d:08x} {o:08x}"
    proc.kill()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("image")
    ap.add_argument("instructions", type=int)
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    ap.add_argument("--until", type=int, metavar="CYCLE")
    a = ap.parse_args(argv)
    for text in trace_lines(a.spinsim, a.image, a.instructions, a.until):
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
