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
:class:`SerialLcd`, :class:`I2cEeprom` (24LC256/24LC512), :class:`Stepper`
(coils or a step/dir driver, through the stepper motor model
:class:`~spinemu.bench.stepper_motor.StepperMotor`: steps per run, shaft
position, missed steps), :class:`SerialConsole`, and the live decoders
:class:`I2cMonitor`, :class:`SpiMonitor`, :class:`PulseMonitor`.

Also here: input models (:mod:`~spinemu.bench.inputs`: pull modes,
stimuli, ``--input``), UART framing (:mod:`~spinemu.bench.uart`), the I2C,
SPI and pulse decoders (:mod:`~spinemu.bench.i2c`, :mod:`~spinemu.bench.spi`,
:mod:`~spinemu.bench.pwm`), decoded-frame annotation files
(:mod:`~spinemu.bench.annotations`), terminal text
(:mod:`~spinemu.bench.terminal`) and the console's link to a real terminal
(:mod:`~spinemu.bench.live`).
"""
from __future__ import annotations

import importlib

__all__ = ["Bench", "BenchInputs", "BenchPinError", "Part", "ReactivePart", "PartWarning",
           "Led", "Button", "RcCircuit", "Potentiometer", "Servo", "Lcd", "SerialLcd", "I2cEeprom", "Stepper",
           "SerialConsole", "I2cMonitor", "SpiMonitor", "PulseMonitor", "PART_KINDS",
           "PinStimulus", "PinWaveforms", "parse_input_spec",
           "UartFormat", "UartWaveform", "UartDecoder", "Frame", "decode_uart", "frame_bits",
           "StepperMotor", "motor_from_trace"]

# names are imported on first use, so that an engine importing one module (the chip: input models)
# does not load every part
_WHERE = {
    "Bench": "board", "BenchInputs": "board", "BenchPinError": "board", "Part": "part", "ReactivePart": "part",
    "PartWarning": "part", "Led": "led", "Button": "button", "RcCircuit": "rc", "Potentiometer": "rc",
    "Servo": "servo", "Lcd": "lcd", "SerialLcd": "lcd", "I2cEeprom": "eeprom", "Stepper": "stepper",
    "SerialConsole": "console", "I2cMonitor": "monitors", "SpiMonitor": "monitors", "PulseMonitor": "monitors",
    "PinStimulus": "inputs", "PinWaveforms": "inputs", "parse_input_spec": "inputs",
    "UartFormat": "uart", "UartWaveform": "uart", "UartDecoder": "uart", "Frame": "uart", "decode_uart": "uart",
    "frame_bits": "uart", "StepperMotor": "stepper_motor", "motor_from_trace": "stepper_motor",
}
_KINDS = ("Led", "Button", "RcCircuit", "Potentiometer", "Servo", "Lcd", "SerialLcd", "I2cEeprom", "Stepper",
          "SerialConsole", "I2cMonitor", "SpiMonitor", "PulseMonitor")


def __getattr__(name: str):
    if name == "PART_KINDS":
        #: the built-in parts by their name in bench files
        value = {cls.kind: cls for cls in (__getattr__(n) for n in _KINDS)}
    elif name in _WHERE:
        value = getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value
