"""The bench: what the world outside the chip does on the pins, written once for every engine.

The bench sits below the engines in the import graph: it never imports
``spinemu.chip``, ``spinemu.translate`` or ``spinemu.pbasic``; the engines
and the command line use it.  Every engine -- the Propeller chip (Spin and
PASM cogs), the Python engine's chip and the BASIC Stamp machine -- offers
the same small interface (:mod:`spinemu.bench.board`): ``clock_hz``,
``pin_count``, a settable input model ``inputs``, the ``drive_history``
(:mod:`spinemu.bench.history`) and ``add_pin_listener``.  A part written
once (:mod:`spinemu.bench.part`) works on all of them:

>>> from spinemu.bench import Bench, Button, Led, Servo
>>> bench = Bench()
>>> led = bench.add(Led(pin=16))
>>> _ = bench.add(Button(pin=3, presses=[(0.1, 0.2)], bounce=0.002))
>>> [p.name for p in bench.parts]
['LED P16', 'button P3']

``bench.attach(chip)`` (or ``run_spin(..., parts=bench)``,
``run_bs2(..., parts=bench)``) connects it before a run; afterwards each part
reports (``bench.summary()``, ``led.duty``, ``bench.warnings``).  Bench
files (``--bench board.toml``) are read by :mod:`spinemu.bench.benchfile`.

Parts: :class:`Led`, :class:`Button`, :class:`RcCircuit`,
:class:`Potentiometer`, :class:`Servo`, :class:`Lcd` (HD44780, 4/8-bit),
:class:`SerialLcd`, :class:`I2cEeprom` (24LC256/24LC512), :class:`Stepper`,
:class:`SerialConsole`, and the live decoders :class:`I2cMonitor`,
:class:`SpiMonitor`, :class:`PulseMonitor`.

Also here: input models (:mod:`~spinemu.bench.inputs`: pull modes,
stimuli, ``--input``), UART framing (:mod:`~spinemu.bench.uart`), the I2C,
SPI and pulse decoders (:mod:`~spinemu.bench.i2c`, :mod:`~spinemu.bench.spi`,
:mod:`~spinemu.bench.pwm`), decoded-frame annotation files
(:mod:`~spinemu.bench.annotations`), terminal text
(:mod:`~spinemu.bench.terminal`) and the console's link to a real terminal
(:mod:`~spinemu.bench.live`).
"""
from __future__ import annotations

from .board import Bench, BenchInputs, BenchPinError
from .button import Button
from .console import SerialConsole
from .eeprom import I2cEeprom
from .inputs import PinStimulus, PinWaveforms, parse_input_spec
from .lcd import Lcd, SerialLcd
from .led import Led
from .monitors import I2cMonitor, PulseMonitor, SpiMonitor
from .part import Part, PartWarning, ReactivePart
from .rc import Potentiometer, RcCircuit
from .servo import Servo
from .stepper import Stepper
from .uart import Frame, UartDecoder, UartFormat, UartWaveform, decode_uart, frame_bits

__all__ = ["Bench", "BenchInputs", "BenchPinError", "Part", "ReactivePart", "PartWarning",
           "Led", "Button", "RcCircuit", "Potentiometer", "Servo", "Lcd", "SerialLcd", "I2cEeprom", "Stepper",
           "SerialConsole", "I2cMonitor", "SpiMonitor", "PulseMonitor", "PART_KINDS",
           "PinStimulus", "PinWaveforms", "parse_input_spec",
           "UartFormat", "UartWaveform", "UartDecoder", "Frame", "decode_uart", "frame_bits"]

#: the built-in parts by their name in bench files
PART_KINDS = {cls.kind: cls for cls in (Led, Button, RcCircuit, Potentiometer, Servo, Lcd, SerialLcd, I2cEeprom,
                                        Stepper, SerialConsole, I2cMonitor, SpiMonitor, PulseMonitor)}
