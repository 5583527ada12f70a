"""Protocol decoders as parts: I2C, SPI and pulses (servo/PWM) decoded live as the run goes.

Each monitor watches some pins and feeds the wire levels to a decoder of
:mod:`spinemu.bench.i2c`, :mod:`spinemu.bench.spi` or
:mod:`spinemu.bench.pwm` as the run goes; what it decoded is in its
attributes and its summary, and protocol violations (a START in the middle
of a byte, a chip select that cuts a word short) are its warnings, at the
cycle they happened.  On the wire, the levels a part drives count (an
EEPROM's ACKs); an undriven I2C line reads 1, an undriven SPI line 0 (CS 1).
(The serial console, :class:`spinemu.bench.SerialConsole`, is the UART's.)
"""
from __future__ import annotations

from typing import Optional

from .i2c import I2cDecoder
from .levels import LevelTracker
from .part import Part, check_pin
from .pwm import PulseDecoder, pulse_stats
from .spi import SpiDecoder

__all__ = ["I2cMonitor", "SpiMonitor", "PulseMonitor"]


class _Monitor(Part):
    def _levels(self, changes):
        return self._tracker.feed(changes)

    def _violation(self, cycle: int, message: str) -> None:
        self.warn(cycle, message)


class I2cMonitor(_Monitor):
    """Decodes the I2C bus on ``scl``/``sda``: ``transfers`` (:class:`~spinemu.bench.i2c.I2cTransfer`)."""

    kind = "i2c"
    pin_parameters = ("scl", "sda")

    def __init__(self, *, scl: int = 28, sda: int = 29, name: Optional[str] = None):
        super().__init__(name=name)
        self.scl, self.sda = check_pin(scl, "scl"), check_pin(sda, "sda")
        self.decoder = I2cDecoder()
        self._tracker = LevelTracker((self.scl, self.sda), idle=1)
        self._seen = 0

    @property
    def name(self) -> str:
        return self._name or f"I2C P{self.scl}/P{self.sda}"

    def watched_pins(self) -> tuple:
        return (self.scl, self.sda)

    @property
    def transfers(self) -> list:
        return self.decoder.transfers

    def on_pins(self, changes, upto, present) -> None:
        d = self.decoder
        for c, (scl, sda) in self._levels(changes):
            d.feed(c, scl, sda)
        for cycle, message in d.violations[self._seen:]:
            self._violation(cycle, message)
        self._seen = len(d.violations)

    def finish(self, end_cycle: int) -> None:
        self.decoder.finish(end_cycle)

    def summary(self) -> str:
        t = self.transfers
        if not t:
            return f"{self.name}: no transfers"
        devices = sorted({x.address for x in t if x.complete_address})
        naks = sum(1 for x in t if x.complete_address and not x.acked)
        nbytes = sum(len(x.data) for x in t)
        return (f"{self.name}: {len(t)} transfers, {nbytes} data bytes, devices "
                + ", ".join(f"0x{a:02X}" for a in devices) + (f"; {naks} not acknowledged" if naks else ""))

    def view(self) -> str:
        return self.transfers[-1].text() if self.transfers else "idle"


class SpiMonitor(_Monitor):
    """Decodes SPI (mode 0-3) on ``sclk``, ``mosi`` and optional ``miso`` and ``cs``: ``words``."""

    kind = "spi"
    pin_parameters = ("sclk", "mosi", "miso", "cs")

    def __init__(self, *, sclk: int, mosi: int, miso: Optional[int] = None, cs: Optional[int] = None,
                 mode: int = 0, bits: int = 8, lsb_first: bool = False, name: Optional[str] = None):
        super().__init__(name=name)
        self.sclk, self.mosi = check_pin(sclk, "sclk"), check_pin(mosi, "mosi")
        self.miso = None if miso is None else check_pin(miso, "miso")
        self.cs = None if cs is None else check_pin(cs, "cs")
        self.decoder = SpiDecoder(mode, bits, lsb_first, has_miso=miso is not None, has_cs=cs is not None)
        self.decoder.sclk = mode >> 1
        pins = [self.sclk, self.mosi] + [p for p in (self.miso, self.cs) if p is not None]
        idle = [mode >> 1, 0] + ([0] if self.miso is not None else []) + ([1] if self.cs is not None else [])
        self._tracker = LevelTracker(pins, idle=idle)
        self._seen = 0

    @property
    def name(self) -> str:
        return self._name or f"SPI P{self.sclk}/P{self.mosi}"

    def watched_pins(self) -> tuple:
        return tuple(p for p in (self.sclk, self.mosi, self.miso, self.cs) if p is not None)

    @property
    def words(self) -> list:
        return self.decoder.words

    def on_pins(self, changes, upto, present) -> None:
        d = self.decoder
        has_miso, has_cs = self.miso is not None, self.cs is not None
        for c, lv in self._levels(changes):
            miso = lv[2] if has_miso else 0
            cs = lv[-1] if has_cs else 0
            d.feed(c, lv[0], lv[1], miso, cs)
        for cycle, message in d.violations[self._seen:]:
            self._violation(cycle, message)
        self._seen = len(d.violations)

    def summary(self) -> str:
        w = self.words
        if not w:
            return f"{self.name}: no words"
        shown = " ".join(f"{x.mosi:02X}" for x in w[:16]) + (" ..." if len(w) > 16 else "")
        return f"{self.name} (mode {self.decoder.mode}): {len(w)} words out: {shown}"

    def view(self) -> str:
        return self.words[-1].text() if self.words else "idle"


class PulseMonitor(_Monitor):
    """Pulse widths, periods and duty on one pin (``pulses``: :class:`~spinemu.bench.pwm.Pulse`)."""

    kind = "pwm"

    def __init__(self, *, pin: int, active: str = "high", name: Optional[str] = None):
        super().__init__(name=name)
        self.pin = check_pin(pin)
        if active not in ("high", "low"):
            raise ValueError(f"active must be 'high' or 'low', not {active!r}")
        self.decoder = PulseDecoder(1 if active == "high" else 0)
        self._tracker = LevelTracker((self.pin,), idle=1 - self.decoder.active)

    @property
    def name(self) -> str:
        return self._name or f"pulses P{self.pin}"

    def watched_pins(self) -> tuple:
        return (self.pin,)

    @property
    def pulses(self) -> list:
        return self.decoder.pulses

    def on_pins(self, changes, upto, present) -> None:
        for c, (lv,) in self._levels(changes):
            self.decoder.feed(c, lv)

    def summary(self) -> str:
        st = pulse_stats(self.pulses, self.clock_hz)
        if not st["count"]:
            return f"{self.name}: no pulses"
        duty = f", duty {100 * st['duty']:.1f} %" if st["duty"] is not None else ""
        return (f"{self.name}: {st['count']} pulses {st['min_width'] * 1e3:.3f}-{st['max_width'] * 1e3:.3f} ms"
                + duty)

    def view(self) -> str:
        p = self.pulses
        return f"{p[-1].width / self.clock_hz * 1e3:.3f} ms" if p else "no pulses"
