"""The bench: what the world outside the chip does on the pins, written once for every engine.

The bench sits below the engines in the import graph: it never imports
``spinemu.chip``, ``spinemu.translate`` or ``spinemu.pbasic``; the engines
and the command line use it.  A part attaches to an *engine* through a small
interface, so that it never knows which engine drives it:

* ``engine.clock_hz`` - cycles per second of the engine's time base;
* ``engine.inputs`` - the input model (``levels(cycle)``,
  ``next_change(cycle)``) for the pins nobody on the chip drives; a part
  that drives pins wraps it (:class:`~spinemu.bench.inputs.PinOverride`);
* ``engine.add_pin_listener(listener, interval_cycles)`` - the engine calls
  ``listener(changes, upto, present)`` at least every ``interval_cycles``:
  ``changes`` are the pin states ``(cycle, dir, out)`` that became final, in
  time order; nothing changes before ``upto`` any more; an input change at
  or after ``present`` is still seen by the program (see
  ``spinemu.chip.listen``).

Modules:

* :mod:`~spinemu.bench.uart` - asynchronous serial framing: encoder,
  streaming decoder, decoding a recorded trace;
* :mod:`~spinemu.bench.console` - :class:`SerialConsole`, a serial terminal
  on the TX/RX pins of a run;
* :mod:`~spinemu.bench.inputs` - composing input models;
* :mod:`~spinemu.bench.terminal` - terminal control codes to text;
* :mod:`~spinemu.bench.live` - a console connected to the real terminal
  (live output, keys typed, real-time pacing), for the command line.
"""
from __future__ import annotations

from .console import SerialConsole
from .inputs import PinOverride
from .uart import Frame, UartDecoder, UartFormat, UartWaveform, decode_uart, frame_bits

__all__ = ["SerialConsole", "PinOverride", "UartFormat", "UartWaveform", "UartDecoder", "Frame",
           "decode_uart", "frame_bits"]
