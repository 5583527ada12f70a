"""Propeller 1 image layout: the 16-byte header, object tables, checksum, EEPROM form.

An image (what OpenSpin writes with ``-b``) is laid out in hub RAM from 0::

    $0000  long  clkfreq        system clock in Hz
    $0004  byte  clkmode        value for the CLK register
    $0005  byte  checksum       makes the byte sum of image + boot frame 0 (mod 256)
    $0006  word  pbase          address of the top object ($0010)
    $0008  word  vbase          address of the top object's VAR (= image size)
    $000A  word  dbase          frame base of the first method (its result long)
    $000C  word  pcurr          address of the first method's first bytecode
    $000E  word  dcurr          stack pointer at start (dbase + 4 + locals)
    $0010  ...   the top object, then its children

The boot loader puts the frame ``$FFF9FFFF, $FFF9FFFF`` at ``dbase - 8``; a
return from the first method lands on ROM bytecode that stops the cog.  The
checksum counts those 8 bytes.  The ``.eeprom`` form is the whole 32 KB hub
image with that frame in place.

Every object starts with a table::

    word  object size in bytes (table + DAT + code + strings, long-aligned)
    byte  method count + 1      byte  child object count (instances)
    long  per method:  word code offset (from object start), word local bytes
    long  per child:   word object offset (from this object), word VAR offset

Source: Propeller Manual v1.2, "Memory Organization"; checked against the
images OpenSpin 1.00.81 writes (tests/data/article).

This module is a shared leaf: it imports nothing from the project but
:mod:`spinemu.diagnostics`.
"""
from __future__ import annotations

import struct

from .diagnostics import ImageError
from .records import Record

__all__ = [
    "HUB_SIZE", "HEADER_SIZE", "FALLBACK_CLOCK_HZ", "BOOT_FRAME", "ImageHeader", "ObjectTable",
    "image_checksum", "to_eeprom", "from_eeprom", "load_image", "describe_clkmode",
    "CLKMODE_NAMES",
]

HUB_SIZE = 0x8000
HEADER_SIZE = 16
#: Cycles per second for times (trace, ``--seconds``) when an image's header says 0 Hz, as
#: OpenSpin writes for ``_xinfreq = 0`` or ``_clkfreq = 0``: RCFAST's nominal 12 MHz.
FALLBACK_CLOCK_HZ = 12_000_000
BOOT_FRAME = 0xFFF9FFFF  # written twice at dbase-8 by the boot loader
_BOOT_FRAME_SUM = 2 * sum(BOOT_FRAME.to_bytes(4, "little"))

#: Spin clock-mode names and the bit each sets in ``_clkmode`` (Propeller Manual, _CLKMODE).
CLKMODE_NAMES = {
    "RCFAST": 0x001, "RCSLOW": 0x002, "XINPUT": 0x004, "XTAL1": 0x008,
    "XTAL2": 0x010, "XTAL3": 0x020, "PLL1X": 0x040, "PLL2X": 0x080,
    "PLL4X": 0x100, "PLL8X": 0x200, "PLL16X": 0x400,
}


class ImageHeader(Record):
    """The first 16 bytes of an image.

    >>> h = ImageHeader.parse(bytes.fromhex("00b4c4046fdc1000a800bc002800c000"))
    >>> h.clkfreq, hex(h.clkmode), h.pbase, h.vbase, h.dbase, h.pcurr, h.dcurr
    (80000000, '0x6f', 16, 168, 188, 40, 192)
    """

    _fields = ("clkfreq", "clkmode", "checksum", "pbase", "vbase", "dbase", "pcurr", "dcurr")

    def __init__(self, clkfreq: int, clkmode: int, checksum: int, pbase: int, vbase: int, dbase: int,
                 pcurr: int, dcurr: int):
        self.clkfreq, self.clkmode, self.checksum = clkfreq, clkmode, checksum
        self.pbase, self.vbase, self.dbase, self.pcurr, self.dcurr = pbase, vbase, dbase, pcurr, dcurr

    FORMAT = "<IBBHHHHH"

    @classmethod
    def parse(cls, data: bytes) -> "ImageHeader":
        if len(data) < HEADER_SIZE:
            raise ImageError(f"image too short for a header ({len(data)} bytes, need 16)")
        return cls(*struct.unpack_from(cls.FORMAT, data, 0))

    def pack(self) -> bytes:
        return struct.pack(self.FORMAT, self.clkfreq, self.clkmode, self.checksum, self.pbase,
                           self.vbase, self.dbase, self.pcurr, self.dcurr)


class ObjectTable(Record):
    """An object's table: size, method entries and child entries.

    Attributes:
        base: hub address of the object.
        size: object size in bytes.
        methods: ``(code_offset, local_bytes)`` per method, method 1 first.
        children: ``(object_offset, var_offset)`` per child instance.
    """

    _fields = ("base", "size", "methods", "children")

    def __init__(self, base: int, size: int, methods: list, children: list):
        self.base, self.size, self.methods, self.children = base, size, methods, children

    @classmethod
    def parse(cls, hub: bytes, base: int) -> "ObjectTable":
        if base + 4 > len(hub):
            raise ImageError(f"object table at ${base:04X} lies outside the image")
        size, nmeth, nobj = struct.unpack_from("<HBB", hub, base)
        need = base + 4 * (nmeth + nobj)
        if nmeth < 1 or need > len(hub):
            raise ImageError(f"object table at ${base:04X} is malformed")
        methods = [struct.unpack_from("<HH", hub, base + 4 * i) for i in range(1, nmeth)]
        children = [struct.unpack_from("<HH", hub, base + 4 * (nmeth + i)) for i in range(nobj)]
        return cls(base, size, methods, children)


def image_checksum(image: bytes) -> int:
    """The header checksum byte for ``image`` (its own checksum byte is ignored).

    >>> data = bytearray(bytes.fromhex("00b4c4046f001000a800bc002800c000"))
    >>> hex(image_checksum(bytes(data)))
    '0xcd'
    """
    total = sum(image) - image[5] + _BOOT_FRAME_SUM
    return (-total) & 0xFF


def to_eeprom(image: bytes, size: int = HUB_SIZE) -> bytes:
    """The EEPROM form of a binary image: padded to 32 KB with the boot frame.

    Raises:
        ImageError: if the image does not fit.
    """
    hdr = ImageHeader.parse(image)
    if hdr.dcurr > size or len(image) > size:
        raise ImageError(f"image needs {max(hdr.dcurr, len(image))} bytes, more than the {size}-byte EEPROM")
    ee = bytearray(size)
    ee[: len(image)] = image
    frame = BOOT_FRAME.to_bytes(4, "little")
    ee[hdr.dbase - 8: hdr.dbase - 4] = frame
    ee[hdr.dbase - 4: hdr.dbase] = frame
    return bytes(ee)


def from_eeprom(eeprom: bytes) -> bytes:
    """The binary image inside an EEPROM image (its first ``vbase`` bytes)."""
    hdr = ImageHeader.parse(eeprom)
    return bytes(eeprom[: hdr.vbase])


def load_image(data: bytes, name: str = "<image>") -> bytes:
    """Validate a ``.binary`` or ``.eeprom`` image and return its binary form.

    Raises:
        ImageError: naming ``name`` and what is wrong with it.
    """
    if len(data) < HEADER_SIZE:
        raise ImageError(f"not a Propeller image: {len(data)} bytes is too short for a header", path=name)
    hdr = ImageHeader.parse(data)
    problems = []
    if hdr.pbase != 0x0010:
        problems.append(f"pbase is ${hdr.pbase:04X}, expected $0010")
    if not (HEADER_SIZE < hdr.vbase <= len(data) and hdr.vbase <= HUB_SIZE):
        problems.append(f"vbase ${hdr.vbase:04X} is outside the {len(data)}-byte file")
    if not (hdr.vbase <= hdr.dbase <= hdr.dcurr <= HUB_SIZE):
        problems.append(f"stack pointers out of order (vbase ${hdr.vbase:04X}, dbase ${hdr.dbase:04X}, dcurr ${hdr.dcurr:04X})")
    if not (hdr.pbase < hdr.pcurr < hdr.vbase):
        problems.append(f"first bytecode address ${hdr.pcurr:04X} is outside the program")
    if problems:
        raise ImageError(f"not a valid Propeller image: {problems[0]}", path=name)
    binary = bytes(data[: hdr.vbase])
    if image_checksum(binary) != hdr.checksum:
        raise ImageError(
            f"checksum mismatch: header says ${hdr.checksum:02X}, contents give ${image_checksum(binary):02X}",
            path=name)
    return binary


def describe_clkmode(clkmode: int) -> str:
    """Spin names for a CLK register value.

    >>> describe_clkmode(0x6F)
    'XTAL1 + PLL16X'
    >>> describe_clkmode(0x00)
    'RCFAST'
    """
    clksel = clkmode & 7
    if clksel == 0:
        return "RCFAST"
    if clksel == 1:
        return "RCSLOW"
    osc = {0: "XINPUT", 1: "XTAL1", 2: "XTAL2", 3: "XTAL3"}[(clkmode >> 3) & 3]
    if clksel == 2:
        return osc
    return f"{osc} + PLL{1 << (clksel - 3)}X"
