"""The bench: what hangs on the pins, written once for every engine.

A part sees pin levels with their clock cycles, in time order, and never
knows which engine (the Propeller emulator, the translated Python, the BASIC
Stamp interpreter) drives it; it can equally be fed a recorded
:class:`~spinemu.trace.PinTrace`.  The bench imports nothing from the
engines (chip, translate, pbasic) or the front end.

Parts:

* :mod:`spinemu.bench.stepper_motor` - a stepper motor on four coil pins or
  on a step/direction driver: shaft position, speed and acceleration over
  time, and the steps it misses when the step rate jumps too far.
"""
