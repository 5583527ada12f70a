"""Cog registers $1E0-$1FF as the Spin REG and SPR bytecodes reach them.

``$1F0-$1FF`` are the special registers (Propeller Manual v1.2, "Cog RAM"):
PAR, CNT, INA and INB read; writes to them land in shadow RAM nobody reads
back, so they are ignored.  OUTA/DIRA writes change the pins at the cycle the
interpreter's PASM instruction writes them.  CTRA/B, FRQA/B and PHSA/B drive
the counter modules (:mod:`spinemu.chip.counters`).  OUTB/DIRB, VCFG and VSCL
are plain storage (there is no port B on the P8X32A; video output is not
modelled).

``$1E0-$1EF`` are the interpreter's own working registers; Spin code only
reaches them through ROM bytecode (``COGID`` reads ``$1E9``).  The ones the
interpreter keeps in named fields map to them (``$1EA`` dcall, ``$1EB`` pbase,
``$1EC`` vbase, ``$1ED`` dbase, ``$1EE`` pcurr, ``$1EF`` dcurr); the others are
kept as plain values (``Cog.scratch``).
"""
from __future__ import annotations

__all__ = ["Registers"]

_M = 0xFFFFFFFF


class Registers:
    """Reads and writes of cog registers for one chip."""

    def __init__(self, chip):
        self.chip = chip

    def read(self, c, r: int, t: int) -> int:
        """Register ``r`` of cog ``c`` as read by an instruction at cycle ``t``."""
        if r >= 0x1F0:
            k = r - 0x1F0
            if k == 1:
                return t & _M
            if k == 2:
                return self.chip.ina(t)
            if k == 0:
                return c.par
            if k == 4:
                return c.outa
            if k == 6:
                return c.dira
            if k in (0xC, 0xD):
                return self.chip.counters.phs(c, k - 0xC, t)
            return (0, 0, 0, 0, 0, c.outb, 0, c.dirb, c.ctra, c.ctrb, c.frqa, c.frqb, 0, 0,
                    c.vcfg, c.vscl)[k]
        k = r - 0x1E0
        if k == 0xE:
            return (c.pc_hi << 16) | c.pc
        if 0xA <= k <= 0xF:
            return (c.dcall, c.pbase | (c.pbase_hi << 16), c.vbase, c.dbase, 0, c.sp)[k - 0xA] & _M
        return c.scratch[k]

    def write(self, c, r: int, v: int, t: int, seen=None, spin: bool = False) -> None:
        """Cog ``c`` writes ``v`` to register ``r`` with an instruction at cycle ``t`` (pins change at ``t``).

        ``seen``: the writing bytecode's access, which the scheduler orders
        the cogs by (a parked PASM loop waiting on the pins wakes by it);
        default ``t - 4`` (a PASM instruction's).  ``spin``: the Spin
        interpreter writes (a bytecode, or the Python engine's statement):
        other cogs' INA reads see a pin change from ``t``, a PASM
        instruction's from ``t - 4`` (both measured on spinsim 0.99,
        tests/data/chip/programs/pins_*.spin).
        """
        v &= _M
        if r >= 0x1F0:
            k = r - 0x1F0
            if k == 4:
                if v != c.outa:
                    c.outa = v
                    self.chip.note_pins(c, t, seen, spin)
            elif k == 6:
                if v != c.dira:
                    c.dira = v
                    self.chip.note_pins(c, t, seen, spin)
            elif k == 5:
                c.outb = v
            elif k == 7:
                c.dirb = v
            elif 8 <= k <= 0xD:
                self.chip.counters.write(c, k - 8, v, t)
            elif k == 0xE:
                c.vcfg = v
            elif k == 0xF:
                c.vscl = v
            return
        k = r - 0x1E0
        if k == 0xA:
            c.dcall = v & 0xFFFF
        elif k == 0xB:
            c.pbase, c.pbase_hi = v & 0xFFFF, v >> 16
        elif k == 0xC:
            c.vbase = v & 0xFFFF
        elif k == 0xD:
            c.dbase = v & 0xFFFF
        elif k == 0xE:
            c.pc, c.pc_hi = v & 0xFFFF, v >> 16
        elif k == 0xF:
            c.sp = v & 0xFFFF
        else:
            c.scratch[k] = v
