"""Record what spinsim 0.99 does with its emulated EEPROM (``-e``) on the bench's EEPROM program.

Development tool (not run by the tests; they read what it wrote): runs
``spinsim -p -e -l LOG eeprom_rw.binary`` in a temporary folder holding an
erased 64 KB ``eeprom.dat``, and again with ``-d`` (``run``, ``dumph``) for hub
RAM, and writes ``tests/data/bench/parts/eeprom_rw.spinsim.json``: the pin
trace (``[cycle, dir, out]`` from the instruction log's DIRA/OUTA writes), the
cycle the program's cog stopped, the VAR longs and readback bytes at the end,
and the EEPROM bytes $7F00-$7F07 afterwards.  Only what spinsim prints and
writes is kept; nothing of spinsim is stored.

    python tests/bench/tools/record_eeprom_spinsim.py [--spinsim PATH]
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(ROOT, "tests", "chip", "tools"))
import spinsim_log  # noqa: E402

PARTS = os.path.join(ROOT, "tests", "data", "bench", "parts")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--spinsim", default="/opt/oracles/spinsim/build/spinsim")
    args = ap.parse_args(argv)
    image = os.path.join(PARTS, "eeprom_rw.binary")
    binary = open(image, "rb").read()
    vbase = struct.unpack_from("<H", binary, 8)[0]
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(image, tmp)
        local = os.path.join(tmp, "eeprom_rw.binary")

        def erased():
            with open(os.path.join(tmp, "eeprom.dat"), "wb") as f:
                f.write(b"\xff" * 65536)

        erased()
        log = os.path.join(tmp, "run.log")
        subprocess.run([args.spinsim, "-p", "-e", "-l", log, "-40000000", local], cwd=tmp,
                       capture_output=True, timeout=1200, check=False)
        cogs = spinsim_log.parse_log(log)
        dira = outa = 0
        trace, end = [[0, 0, 0]], 0
        for t, cog, reg, value in spinsim_log.pin_writes(cogs[0], 0):
            if reg == 0x1F4:
                outa = value
            else:
                dira = value
            if trace[-1][1:] != [dira, dira & outa]:
                trace.append([t, dira, dira & outa])
        for cyc, addr, ins, flag, text in cogs[0]:
            if flag == " " and " cogstop " in f" {text} ":
                end = max(end, cyc + 4)
        erased()
        r = subprocess.run([args.spinsim, "-p", "-e", "-d", local], input="run\ndumph 0\nexit\n", cwd=tmp,
                           capture_output=True, text=True, timeout=1200)
        mem = bytearray(0x8000)
        for a, v in re.findall(r"([0-9a-f]{8}) ([0-9a-f]{8})", r.stdout):
            a = int(a, 16)
            if a < 0x8000:
                mem[a:a + 4] = int(v, 16).to_bytes(4, "little")
        eeprom = open(os.path.join(tmp, "eeprom.dat"), "rb").read()
    record = {"source": "spinsim 0.99 -p -e on tests/data/bench/parts/eeprom_rw.binary, erased 64 KB eeprom.dat",
              "end_cycle": end, "trace": trace,
              "acks_polls": list(struct.unpack_from("<2i", mem, vbase)),
              "readback": list(mem[vbase + 8:vbase + 13]),
              "eeprom_7f00": eeprom[0x7F00:0x7F08].hex()}
    with open(os.path.join(PARTS, "eeprom_rw.spinsim.json"), "w") as f:
        json.dump(record, f)
        f.write("\n")
    print(f"{len(trace)} pin states, end at cycle {end}; acks/polls {record['acks_polls']}, "
          f"readback {record['readback']}, EEPROM {record['eeprom_7f00']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
