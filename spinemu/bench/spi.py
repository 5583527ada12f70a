"""SPI: a decoder of a clocked serial bus, live or on recorded traces, in modes 0-3.

A master clocks SCLK; each clock moves one bit out on MOSI and one in on
MISO, most significant first unless set otherwise; an optional chip select
(CS, active low) frames the words.  The mode is ``CPOL * 2 + CPHA``
(Motorola's SPI Block Guide; the modes every SPI datasheet tabulates):
CPOL is SCLK's idle level; with CPHA = 0 the bits are read on the leading
(first) edge of each clock, with CPHA = 1 on the trailing edge.  The BASIC
Stamp's SHIFTOUT is mode 0 (MSBFIRST) with the clock idling low.

:class:`SpiDecoder` is fed ``(cycle, sclk, mosi, miso, cs)`` in time order and
makes :class:`SpiWord` records; a chip select that ends a word early is a
protocol violation at its cycle.  :func:`decode_spi` does it on a trace.
:func:`spi_levels` generates a bus signal (for tests and examples).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional, Sequence

from .levels import level_changes

__all__ = ["SpiWord", "SpiDecoder", "decode_spi", "spi_levels"]


@dataclass(frozen=True)
class SpiWord:
    """One word on the bus: its first and last sampling edges and the bits each way."""

    start: int
    end: int
    mosi: int
    miso: Optional[int]
    bits: int

    def text(self) -> str:
        digits = (self.bits + 3) // 4
        miso = f" MISO {self.miso:0{digits}X}" if self.miso is not None else ""
        return f"MOSI {self.mosi:0{digits}X}{miso}"


class SpiDecoder:
    """A streaming SPI decoder.

    Args:
        mode: 0-3 (CPOL * 2 + CPHA).
        bits: bits per word.
        lsb_first: least significant bit first.
        has_miso, has_cs: whether MISO and CS are connected (else ignored).
        on_word: called with each :class:`SpiWord`.

    Raises:
        ValueError: for a mode outside 0-3 or a word size outside 1-32.

    >>> d = SpiDecoder(mode=0, has_miso=False, has_cs=False)
    >>> for t, *lv in spi_levels([0xA5], mode=0, half_bit=10):
    ...     d.feed(t, *lv)
    >>> [w.text() for w in d.words]
    ['MOSI A5']
    """

    def __init__(self, mode: int = 0, bits: int = 8, lsb_first: bool = False, *, has_miso: bool = True,
                 has_cs: bool = True, on_word: Optional[Callable[[SpiWord], None]] = None):
        if mode not in (0, 1, 2, 3):
            raise ValueError(f"SPI mode must be 0-3, not {mode!r}")
        if not 1 <= bits <= 32:
            raise ValueError(f"bits per word must be 1-32, not {bits!r}")
        self.mode, self.bits, self.lsb_first = mode, bits, lsb_first
        self.cpol, self.cpha = mode >> 1, mode & 1
        self.has_miso, self.has_cs = has_miso, has_cs
        self.on_word = on_word
        self.words: list[SpiWord] = []
        #: ``(cycle, message)`` of each protocol violation
        self.violations: list = []
        self.sclk = self.cpol
        self.selected = not has_cs
        self._n = 0
        self._mosi = self._miso = 0
        self._first = 0

    def feed(self, cycle: int, sclk: int, mosi: int, miso: int = 0, cs: int = 0) -> None:
        """From ``cycle`` on the lines are at these levels (calls in time order)."""
        if self.has_cs:
            selected = not cs
            if selected != self.selected:
                if not selected and self._n:
                    self.violations.append((cycle, f"SPI chip select ended a word after {self._n} of "
                                                   f"{self.bits} bits"))
                self.selected = selected
                self._n = self._mosi = self._miso = 0
                self.sclk = sclk
                return
        if sclk == self.sclk:
            return
        self.sclk = sclk
        if not self.selected:
            return
        leading = sclk != self.cpol
        if leading != (self.cpha == 0):
            return                              # not a sampling edge
        if self._n == 0:
            self._first = cycle
        if self.lsb_first:
            self._mosi |= mosi << self._n
            self._miso |= miso << self._n
        else:
            self._mosi = (self._mosi << 1) | mosi
            self._miso = (self._miso << 1) | miso
        self._n += 1
        if self._n == self.bits:
            word = SpiWord(self._first, cycle, self._mosi, self._miso if self.has_miso else None, self.bits)
            self.words.append(word)
            self._n = self._mosi = self._miso = 0
            if self.on_word is not None:
                self.on_word(word)


def decode_spi(trace, sclk: int, mosi: int, miso: Optional[int] = None, cs: Optional[int] = None, *,
               mode: int = 0, bits: int = 8, lsb_first: bool = False) -> SpiDecoder:
    """Decode SPI on pins of a recorded trace (undriven lines read 0, an undriven CS 1).

    Returns:
        the decoder: ``.words`` and ``.violations``.

    Raises:
        ValueError: for a pin the trace does not have, a bad mode or word size.
    """
    pins: Sequence[int] = [p for p in (sclk, mosi, miso, cs) if p is not None]
    for p in pins:
        if not 0 <= p < trace.pin_count:
            raise ValueError(f"pin {p} does not exist (pins are 0..{trace.pin_count - 1})")
    d = SpiDecoder(mode, bits, lsb_first, has_miso=miso is not None, has_cs=cs is not None)
    idle = (mode >> 1, 0, 0, 1)
    sel = [(sclk, idle[0]), (mosi, 0)] + ([(miso, 0)] if miso is not None else []) + \
          ([(cs, 1)] if cs is not None else [])
    first = True
    for cycle, levels in level_changes(trace.changes, [p for p, _ in sel], idle=[i for _, i in sel]):
        lv = dict(zip([p for p, _ in sel], levels))
        if first:
            d.sclk = lv[sclk]
            first = False
        d.feed(cycle, lv[sclk], lv[mosi], lv.get(miso, 0), lv.get(cs, 0))
    return d


def spi_levels(words, *, mode: int = 0, bits: int = 8, half_bit: int = 100, start: int = 0,
               miso_words=None, lsb_first: bool = False) -> list:
    """``(cycle, sclk, mosi, miso, cs)`` of a master sending ``words`` (one CS frame each): a test signal.

    As SPI devices do, the data change on the edge that is not the sampling
    edge: with CPHA = 0 the first bit is set up after CS falls and the next
    ones on each trailing edge; with CPHA = 1 each bit on its leading edge.
    """
    cpol, cpha = mode >> 1, mode & 1
    t = start
    out = [(t, cpol, 0, 0, 1)]
    miso_words = list(miso_words) if miso_words is not None else [0] * len(words)
    for w, r in zip(words, miso_words):
        order = list(range(bits) if lsb_first else range(bits - 1, -1, -1))
        bit = [((w >> i) & 1, (r >> i) & 1) for i in order]
        t += half_bit
        out.append((t, cpol, 0, 0, 0))                          # select
        if cpha == 0:
            out.append((t + half_bit // 2, cpol, *bit[0], 0))   # the first bit before the first edge
        lag = max(1, half_bit // 4)                             # data follow the shifting edge a little later
        prev = bit[0] if cpha == 0 else (0, 0)
        for k, (a, b) in enumerate(bit):
            t += half_bit
            if cpha == 0:
                out.append((t, 1 - cpol, a, b, 0))              # leading edge: sampled
                t += half_bit
                out.append((t, cpol, a, b, 0))                  # trailing edge: shifts...
                if k + 1 < len(bit):
                    out.append((t + lag, cpol, *bit[k + 1], 0))     # ... the next bit out
            else:
                out.append((t, 1 - cpol, *prev, 0))             # leading edge: shifts...
                out.append((t + lag, 1 - cpol, a, b, 0))        # ... the bit out
                t += half_bit
                out.append((t, cpol, a, b, 0))                  # trailing edge: sampled
            prev = (a, b)
        t += half_bit
        out.append((t, cpol, 0, 0, 1))                          # deselect
    return out
