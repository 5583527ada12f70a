"""Read spinsim 0.99 instruction logs (``spinsim -p -l LOG -N image``) into bytecode records.

Development tool for :mod:`derive_timing`; it only runs a spinsim binary the
user points it at and parses what that binary prints.  Nothing of spinsim or
of the ROM is stored.

A log line looks like ``Cog 0:     196 009 00bc0bee    rdbyte 005, 1ee R=00000032``:
cog, cycle, cog address, instruction word, a flag (``W`` waiting for the hub or
a wait, ``X`` condition false, ``I`` pipeline slot) and the disassembly.  The
ROM interpreter starts every bytecode at cog address $008 and fetches the
opcode with the hub read at $009; the instruction at $00A runs right after the
fetch completes.
"""
from __future__ import annotations

import os
import re
import subprocess

__all__ = ["run_spinsim_log", "parse_log", "bytecodes", "pin_writes", "cog_starts"]

LINE = re.compile(r"^Cog (\d):\s+(\d+) ([0-9a-f]{3}) ([0-9a-f]{8}) ([WXI ]) (.*)$")
RVAL = re.compile(r"R=([0-9a-f]{8})")


def run_spinsim_log(spinsim: str, image_path: str, log_path: str, instructions: int) -> None:
    """Run ``spinsim -p -l log_path -<instructions> image_path``."""
    subprocess.run([spinsim, "-p", "-l", log_path, f"-{instructions}", image_path],
                   capture_output=True, timeout=1200, check=False)


def parse_log(path: str) -> dict:
    """``{cog: [(cycle, cog_addr, instr_hex, flag, text), ...]}``."""
    cogs: dict = {}
    with open(path) as f:
        for line in f:
            m = LINE.match(line)
            if m:
                cog, cyc, addr, ins, flag, text = m.groups()
                cogs.setdefault(int(cog), []).append((int(cyc), int(addr, 16), ins, flag, text.strip()))
    return cogs


def bytecodes(events) -> list:
    """One record per bytecode: ``dict(start, pc, op, tf, lines)``.

    ``start`` is the cycle of the instruction at $008, ``tf`` the cycle of the
    instruction at $00A (the fetch has completed), ``pc`` the opcode's address
    (low 16 bits of pcurr).
    """
    out = []
    cur = None
    for ev in events:
        cyc, addr, ins, flag, text = ev
        if addr == 0x008 and ins == "a0fc0000" and flag == " ":
            cur = {"start": cyc, "lines": []}
            out.append(cur)
        if cur is None:
            continue
        cur["lines"].append(ev)
        if flag != " ":
            continue
        if addr == 0x009 and "op" not in cur:
            cur["op"] = int(RVAL.search(text).group(1), 16)
        elif addr == 0x00A and "pc" not in cur:
            cur["pc"] = (int(RVAL.search(text).group(1), 16) - 1) & 0xFFFF
            cur["tf"] = cyc
    return [b for b in out if "tf" in b]


def pin_writes(events, cog: int) -> list:
    """``(cycle + 4, cog, register, value)`` for every executed write to OUTA ($1F4) or DIRA ($1F6)."""
    out = []
    for cyc, addr, ins, flag, text in events:
        if flag != " ":
            continue
        word = int(ins, 16)
        dest = (word >> 9) & 0x1FF
        if dest in (0x1F4, 0x1F6):
            m = RVAL.search(text)
            if m:
                out.append((cyc + 4, cog, dest, int(m.group(1), 16)))
    return out


def cog_starts(events) -> int:
    """Cycle of a cog's first logged line."""
    return events[0][0]


def spinsim_available(path: str) -> bool:
    return os.path.exists(path)


# ----------------------------------------------------------------------------- PASM cogs
ZVAL = re.compile(r"Z=(\d)")
CVAL = re.compile(r"C=(\d)")
_WAITPIN = (0x3C, 0x3D)


def pasm_steps(events) -> list:
    """One record per executed PASM instruction of one cog's log lines.

    ``(start cycle, cog address, long, executed, result or None, Z or None,
    C or None)``.  spinsim logs an instruction when it completes, after one
    ``W`` line per 4 cycles it waited (hub window, WAITCNT) and, for
    WAITPEQ/WAITPNE, one plain line per poll; ``X`` marks a false condition,
    ``I`` the pipeline's empty slot (a not-taken jump, a cog start).
    """
    out = []
    start = None
    for cyc, addr, ins, flag, text in events:
        if flag == "I":
            start = None
            continue
        if start is None:
            start = cyc
        if flag == "W":
            continue
        word = int(ins, 16)
        r, z, c = RVAL.search(text), ZVAL.search(text), CVAL.search(text)
        rec = [start, addr, word, flag != "X", int(r.group(1), 16) if r else None,
               int(z.group(1)) if z else None, int(c.group(1)) if c else None]
        start = None
        last = out[-1] if out else None
        # a WAITPEQ/WAITPNE logs every poll (plain lines; the last one shows the flags):
        # one instruction from its first poll
        if (last is not None and word >> 26 in _WAITPIN and last[1] == addr and last[2] == word
                and last[4] is None and last[5] is None and last[6] is None and cyc - last[-1] == 4):
            last[4:8] = rec[4:7] + [cyc]
            continue
        out.append(rec + [cyc])
    return [rec[:7] for rec in out]


def pin_trace(cogs: dict) -> list:
    """``[(cycle, dir, out), ...]`` of all cogs from their logs, as the reference traces count.

    An OUTA/DIRA write shows at its instruction's cycle + 4; a cog stopped by
    a COGSTOP (its target read from the value last written to the COGSTOP's
    destination register) floats its pins at the COGSTOP's cycle + 4; a
    stopped cog started again drives its old DIRA/OUTA again from its first
    slot (spinsim does not clear them).
    """
    events = []
    for k, lines in cogs.items():
        regs: dict = {}
        for cyc, addr, ins, flag, text in lines:
            if flag == "I" and addr == 0 and ins == "00000000":
                events.append((cyc, 2, k, "start", 0))
            if flag != " ":
                continue
            word = int(ins, 16)
            dest = (word >> 9) & 0x1FF
            r = RVAL.search(text)
            if r and word & (1 << 23):
                regs[dest] = int(r.group(1), 16)
                if dest in (0x1F4, 0x1F6):
                    events.append((cyc + 4, 1, k, dest, regs[dest]))
            if word >> 26 == 3 and word & (1 << 22) and word & 7 == 3 and dest in regs:
                events.append((cyc + 4, 0, regs[dest] & 7, None, 0))
    events.sort()
    drive: dict = {}
    stopped: dict = {}
    out = [(0, 0, 0)]
    for t, _, k, dest, value in events:
        if dest is None:
            if k in drive:
                stopped[k] = drive.pop(k)
        elif dest == "start":
            if k in stopped:
                drive[k] = stopped.pop(k)
        else:
            d = drive.setdefault(k, [0, 0])
            d[0 if dest == 0x1F6 else 1] = value
        dirs = outs = 0
        for dd, oo in drive.values():
            dirs |= dd
            outs |= dd & oo
        if (dirs, outs) != out[-1][1:]:
            out.append((t, dirs, outs))
    return out
