"""What the pins nobody drives read: the input model behind INA.

A pin is driven when some running cog has its DIRA bit set; INA then reads the
driven level.  Every other pin reads what the input model says.  The input
models are the bench's, shared by every engine (:mod:`spinemu.bench.inputs`):
``"pullup"``/``"pulldown"``, :class:`~spinemu.bench.inputs.PinStimulus`
(levels that change at given cycles), any object with ``levels(cycle)`` and
``next_change(cycle)`` (parts on the pins, :mod:`spinemu.bench`), or a plain
callable ``f(cycle) -> int`` polled every :data:`CALLABLE_POLL_CYCLES`
cycles while a cog waits on it.  ``WAITPEQ``/``WAITPNE`` on undriven pins
wake exactly at ``next_change``.

This module only names them for the chip's users.
"""
from __future__ import annotations

from ..bench.inputs import CALLABLE_POLL_CYCLES, PinStimulus, make_input_model

__all__ = ["PinStimulus", "make_input_model", "CALLABLE_POLL_CYCLES"]
