"""Closures that read and write BS2 RAM views (README 1.1-1.2, 3.1).

A view is ``width`` bits (1, 4, 8 or 16) at ``bitoff``; views are always
aligned to their own width, so one never straddles two RAM words.  Reading
zero-extends; writing keeps only the low ``width`` bits (``nib = 15 + 1``
stores 0, ``byte = 300`` stores 44).  Word 0 is INS: reads come from the
pins, writes are ignored with a warning ([OPEN] README 4.1).  A write to
OUTS or DIRS (words 1, 2) records the pins.

Indexes are not range-checked (``x(3)`` on a byte is the byte 3 positions
further on, whatever lives there); an index past the 32-byte RAM wraps
modulo 256 bits with a warning ([OPEN] README 1.2).

Hot path: every variable access of a running program goes through these.
"""
from __future__ import annotations

from typing import Callable, Optional

from . import messages as M

__all__ = ["reader", "writer", "byte_reader", "byte_writer"]

RAM_BITS = 256


def _wrap(m, off: int, width: int, warn: Callable) -> int:
    if off + width > RAM_BITS:
        off %= RAM_BITS
        warn(m, M.W_INDEX_WRAP.format(off))
    return off


def reader(bitoff: int, width: int, index: Optional[Callable], warn: Callable) -> Callable:
    """``f(m) -> value`` of a fixed or indexed view."""
    mask = (1 << width) - 1
    if index is None:
        wi, sh = bitoff >> 4, bitoff & 15
        if wi == 0:
            pins = mask << sh

            def read_ins(m):
                floating = pins & ~m.w[2] & m.unstimulated
                if floating:
                    m.float_warning(floating)
                return (m.ins() >> sh) & mask
            return read_ins
        return lambda m: (m.w[wi] >> sh) & mask

    def read(m):
        off = _wrap(m, bitoff + index(m) * width, width, warn)
        wi = off >> 4
        if wi == 0:
            floating = (mask << (off & 15)) & ~m.w[2] & m.unstimulated
            if floating:
                m.float_warning(floating)
            word = m.ins()
        else:
            word = m.w[wi]
        return (word >> (off & 15)) & mask
    return read


def _store(m, off: int, width: int, value: int, warn: Callable) -> None:
    wi, sh = off >> 4, off & 15
    if wi == 0:
        warn(m, M.W_INS_WRITE)
        return
    mask = ((1 << width) - 1) << sh
    m.w[wi] = (m.w[wi] & ~mask) | ((value << sh) & mask)
    if wi < 3:
        m.pins_changed()


def writer(bitoff: int, width: int, index: Optional[Callable], warn: Callable) -> Callable:
    """``g(m, value)`` storing the low ``width`` bits of a 16-bit value."""
    if index is not None:
        def write_indexed(m, v):
            off = _wrap(m, bitoff + index(m) * width, width, warn)
            _store(m, off, width, v, warn)
        return write_indexed
    wi, sh = bitoff >> 4, bitoff & 15
    mask = ((1 << width) - 1) << sh
    keep = ~mask & 0xFFFF
    if wi == 0:
        return lambda m, v: warn(m, M.W_INS_WRITE)
    if wi < 3:
        def write_pins(m, v):
            m.w[wi] = (m.w[wi] & keep) | ((v << sh) & mask)
            m.pins_changed()
        return write_pins

    def write(m, v):
        m.w[wi] = (m.w[wi] & keep) | ((v << sh) & mask)
    return write


def byte_reader(bitoff: int, width: int, warn: Callable) -> Callable:
    """``f(m, i) -> element i`` of an array view (STR, WAITSTR)."""
    mask = (1 << width) - 1

    def read(m, i):
        off = _wrap(m, bitoff + i * width, width, warn)
        wi = off >> 4
        word = m.ins() if wi == 0 else m.w[wi]
        return (word >> (off & 15)) & mask
    return read


def byte_writer(bitoff: int, width: int, warn: Callable) -> Callable:
    """``g(m, i, value)`` storing element i of an array view (SERIN STR)."""
    def write(m, i, v):
        _store(m, _wrap(m, bitoff + i * width, width, warn), width, v, warn)
    return write
