"""The Propeller 1 hub ROM ($8000-$FFFF) as far as spinemu models it.

Layout (Propeller Manual v1.2, "Main Memory"; P8X32A datasheet, "Main ROM")::

    $8000-$BFFF  character font (16 x 32 pixels, 256 characters)   not modelled: reads 0
    $C000-$CFFF  log table: 2048 words, log2(1 + i/2048) * 65536
    $D000-$DFFF  anti-log table: 2048 words, (2**(i/2048) - 1) * 65536
    $E000-$F001  sine table: 2049 words, sin(i/2048 * pi/2) * 65535 (first quadrant)
    $F004-$FFFF  boot loader and Spin interpreter (PASM)               not modelled: reads 0,
                 except the three bytecodes at $FFF9 described below and $FFFF
    $FFFF        the chip's version, 1 on the P8X32A: Spin's CHIPVER reads it (``byte[$FFFF]``;
                 Propeller Manual, CHIPVER), and drivers such as VGA64 and PS2_HID check it

The tables are computed here from the manual's definitions, rounded to the
nearest integer; checksums of all 6,145 entries agree with the ROM that
spinsim 0.99 carries (``tests/chip/test_rom_and_timing.py``).

``$FFF9`` holds the Spin bytecodes a cog's top method returns into (the boot
frame's return address): ``$3F $89`` (push register $1E9, the cog's own id)
and ``$21`` (COGSTOP), so the cog stops itself.  This was observed by running
programs on the reference interpreter; nothing else of the interpreter's
ROM code is reproduced.
"""
from __future__ import annotations

import math
import sys
from array import array
from functools import lru_cache

__all__ = ["ROM_BASE", "INTERPRETER_ENTRY", "RETURN_TO_STOP", "CHIP_VERSION", "build_rom"]

ROM_BASE = 0x8000
#: the code address COGINIT gets for a Spin cog: the ROM interpreter's image
INTERPRETER_ENTRY = 0xF004
#: where a cog's top-level method returns to (see module docstring)
RETURN_TO_STOP = 0xFFF9
_STOP_BYTECODES = bytes([0x3F, 0x89, 0x21])
#: where CHIPVER reads the chip's version, and the P8X32A's
CHIP_VERSION_ADDR, CHIP_VERSION = 0xFFFF, 1


@lru_cache(maxsize=1)
def build_rom() -> bytes:
    """The 32 KB from $8000 to $FFFF.

    >>> rom = build_rom()
    >>> int.from_bytes(rom[0xE000 - 0x8000 + 2048:][:2], "little")   # sin(45 deg)
    46340
    """
    rom = bytearray(0x8000)
    log2, sin, pi = math.log2, math.sin, math.pi
    # the three tables follow each other: log at $C000, anti-log at $D000, sine at $E000
    tables = array("H", [round(log2(1 + i / 2048) * 65536) for i in range(2048)])
    tables.extend([round((2 ** (i / 2048) - 1) * 65536) for i in range(2048)])
    tables.extend([round(sin(i / 2048 * pi / 2) * 65535) for i in range(2049)])
    if sys.byteorder != "little":
        tables.byteswap()
    for addr, data in ((0xC000, tables.tobytes()), (RETURN_TO_STOP, _STOP_BYTECODES),
                       (CHIP_VERSION_ADDR, bytes([CHIP_VERSION]))):
        rom[addr - ROM_BASE: addr - ROM_BASE + len(data)] = data
    return bytes(rom)
