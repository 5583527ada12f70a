"""Input models: what the pins nobody on the chip drives read, for every engine.

An *input model* says what undriven pins read at each clock cycle of an
engine's time base (the Propeller's system clock, the BASIC Stamp's
microseconds):

* ``levels(cycle) -> int``: the pin levels (bit ``p`` = pin ``p``);
* ``next_change(cycle) -> int | None``: the first cycle after ``cycle`` at
  which ``levels`` changes, or ``None``.  Engines skip time in pin waits
  (WAITPEQ/WAITPNE, PULSIN, RCTIME, BUTTON loops) by it, so it must be
  exact, or at worst early (an engine then asks again);
* optionally ``mask``: the pins the model *drives* (a waveform generator, a
  part), as opposed to a pull-up or pull-down that only says what a floating
  pin reads.  Recorded wire levels (:meth:`spinemu.bench.board.Bench.wire_trace`)
  show driven pins only.

The models here:

* :class:`Constant` - every pin at one level (``"pullup"``/``"pulldown"``);
* :class:`PinStimulus` - levels that change at given cycles;
* :class:`Polled` - a plain callable ``f(cycle) -> int``, re-read every
  :data:`CALLABLE_POLL_CYCLES` cycles while a program waits on it;
* :class:`PinWaveforms` - the time-based form users write (``{pin: level |
  [(seconds, level), ...] | f(seconds)}``), as ``--input`` and
  ``run_bs2(inputs=...)`` take it, on any clock;

Parts on the pins are input models too; a bench puts them on top of the
engine's model (:class:`spinemu.bench.board.BenchInputs`).

:func:`parse_input_spec` reads the ``--input`` text for every engine;
:func:`make_input_model` turns a ``Chip(inputs=...)`` argument into a model.
"""
from __future__ import annotations

import bisect
import math
from collections.abc import Callable, Iterable

__all__ = ["Constant", "PinStimulus", "Polled", "PinWaveforms", "InputSpecError",
           "parse_input_spec", "make_input_model", "CALLABLE_POLL_CYCLES", "model_mask"]

#: how often a cog waiting on a plain-callable input model re-reads it
CALLABLE_POLL_CYCLES = 1000
_ALL = 0xFFFFFFFF


def model_mask(model) -> int:
    """The pins an input model drives (its ``mask``; 0 for a pull mode or a model without one)."""
    return int(getattr(model, "mask", 0) or 0)


class Constant:
    """Every pin at one level: a pull-up (``Constant(0xFFFFFFFF)``) or pull-down (``Constant(0)``)."""

    mask = 0

    def __init__(self, level: int):
        self.level = level & _ALL

    def levels(self, cycle: int) -> int:
        return self.level

    def next_change(self, cycle: int) -> int | None:
        return None


class PinStimulus:
    """Pin levels that change at given cycles.

    Args:
        changes: ``(cycle, mask, levels)``: from ``cycle`` on, the pins in
            ``mask`` read the bits of ``levels``.
        initial: the levels before the first change (and of the pins no
            change names).

    Attributes:
        mask: the pins some change names (the pins this stimulus drives).

    >>> s = PinStimulus([(1000, 0x1, 0x1), (5000, 0x1, 0x0)])
    >>> s.levels(999), s.levels(1000), s.next_change(1000), s.next_change(6000)
    (0, 1, 5000, None)
    """

    def __init__(self, changes: Iterable[tuple[int, int, int]], initial: int = 0):
        self.times: list[int] = []
        self.values: list[int] = []
        self.mask = 0
        level = initial & _ALL
        for cycle, mask, levels in sorted(changes, key=lambda ch: ch[0]):
            self.mask |= mask & _ALL
            level = (level & ~mask) | (levels & mask)
            if self.times and self.times[-1] == cycle:
                self.values[-1] = level
            else:
                self.times.append(cycle)
                self.values.append(level)
        self.initial = initial & _ALL
        # keep only real changes, so that next_change is exact
        times, values, last = [], [], self.initial
        for t, v in zip(self.times, self.values):
            if v != last:
                times.append(t)
                values.append(v)
                last = v
        self.times, self.values = times, values

    def levels(self, cycle: int) -> int:
        i = bisect.bisect_right(self.times, cycle)
        return self.values[i - 1] if i else self.initial

    def next_change(self, cycle: int) -> int | None:
        i = bisect.bisect_right(self.times, cycle)
        return self.times[i] if i < len(self.times) else None


class Polled:
    """A plain callable ``f(cycle) -> int`` as an input model, re-read every ``poll_cycles``.

    Since it cannot say when it changes, a program waiting on it sees a
    change at the first poll at or after it.
    """

    mask = 0

    def __init__(self, fn: Callable[[int], int], poll_cycles: int = CALLABLE_POLL_CYCLES):
        self.fn = fn
        self.poll_cycles = max(1, int(poll_cycles))

    def levels(self, cycle: int) -> int:
        return int(self.fn(cycle)) & _ALL

    def next_change(self, cycle: int) -> int | None:
        return cycle + self.poll_cycles


def make_input_model(inputs, *, pull_up: bool):
    """The input model for a ``Chip(inputs=...)`` argument.

    Args:
        inputs: ``None`` (the pull mode), ``"pullup"``, ``"pulldown"``, an
            input model, or a callable ``f(cycle) -> int``.
        pull_up: what ``None`` means.

    Raises:
        ValueError: for a string other than ``"pullup"``/``"pulldown"`` or another object.
    """
    if inputs is None:
        return Constant(_ALL if pull_up else 0)
    if isinstance(inputs, str):
        if inputs == "pullup":
            return Constant(_ALL)
        if inputs == "pulldown":
            return Constant(0)
        raise ValueError(f"inputs must be 'pullup', 'pulldown' or a stimulus, not {inputs!r}")
    if hasattr(inputs, "levels") and hasattr(inputs, "next_change"):
        return inputs
    if callable(inputs):
        return Polled(inputs)
    raise ValueError("inputs must be 'pullup', 'pulldown', an object with levels()/next_change(), or a callable")


# ----------------------------------------------------------------------------- time-based waveforms
class PinWaveforms:
    """Levels given per pin in seconds, as an input model on a clock.

    Args:
        spec: ``{pin: level | [(seconds, level), ...] | f(seconds) -> 0|1}``:
            a constant level, steps (the level holds from each time on; before
            the first step the pin reads ``base``), or a callable.
        clock_hz: cycles per second of the engine's time base.
        base: the levels of the pins the spec does not name (the pull mode:
            ``0xFFFFFFFF`` pull-up, ``0`` pull-down), and of stepped pins
            before their first step.
        pin_count: the engine's pins (32 on the Propeller, 16 on the BASIC Stamp).
        poll_cycles: how often a callable is re-read while a program waits
            on it (default: every microsecond of the clock).

    Attributes:
        pins: the pins the spec names (bit mask).
        mask: those with constant or stepped levels (a callable's pins are
            not in recorded wire levels: it would have to be sampled).

    Raises:
        ValueError: for a pin outside ``0..pin_count-1``, a negative or
            non-finite time.

    >>> w = PinWaveforms({3: 1, 5: [(0, 0), (0.5, 1)]}, clock_hz=1_000)
    >>> w.levels(0), w.levels(500), w.next_change(0), bin(w.pins)
    (8, 40, 500, '0b101000')
    """

    def __init__(self, spec: dict, clock_hz: int, *, base: int = 0, pin_count: int = 32,
                 poll_cycles: int | None = None):
        changes = []
        self.pins = 0
        self._calls: list[tuple[int, Callable]] = []
        self.clock_hz = clock_hz
        for pin, value in (spec or {}).items():
            pin = int(pin)
            if not 0 <= pin < pin_count:
                raise ValueError(f"input pin {pin} does not exist (pins are 0..{pin_count - 1})")
            bit = 1 << pin
            self.pins |= bit
            if callable(value):
                self._calls.append((bit, value))
            elif isinstance(value, (list, tuple)):
                for seconds, level in value:
                    seconds = float(seconds)
                    if not math.isfinite(seconds) or seconds < 0:
                        raise ValueError(f"input pin {pin}: time {seconds!r} is not a number of seconds >= 0")
                    changes.append((int(round(seconds * clock_hz)), bit, bit if level else 0))
            else:
                changes.append((0, bit, bit if value else 0))
        self._stim = PinStimulus(changes, initial=base)
        self._call_mask = sum(bit for bit, _ in self._calls)
        self.mask = self.pins & ~self._call_mask
        self.poll_cycles = max(1, poll_cycles if poll_cycles is not None else clock_hz // 1_000_000)

    def levels(self, cycle: int) -> int:
        v = self._stim.levels(cycle)
        if self._calls:
            v &= ~self._call_mask
            t = cycle / self.clock_hz
            for bit, fn in self._calls:
                if fn(t):
                    v |= bit
        return v

    def next_change(self, cycle: int) -> int | None:
        nxt = self._stim.next_change(cycle)
        if self._calls:
            poll = cycle + self.poll_cycles
            return poll if nxt is None or poll < nxt else nxt
        return nxt


# ----------------------------------------------------------------------------- the --input text
class InputSpecError(ValueError):
    """A malformed ``--input`` text; the message says what was expected."""


#: The latest time a stimulus step may name: about 32 years (any later time is never reached).
MAX_SECONDS = 1e9


def parse_input_spec(text: str) -> dict:
    """Read an input stimulus as written on the command line, for any engine.

    ``"P3=1"`` holds P3 high; ``"5=0@0,1@0.25"`` sets P5 low at 0 s and high
    at 0.25 s; several pins are separated by ``;``.  Times are seconds, 0 to
    :data:`MAX_SECONDS`; levels are 0 or 1.

    Returns:
        ``{pin: level}`` or ``{pin: [(seconds, level), ...]}`` (the ``spec`` of
        :class:`PinWaveforms`).

    Raises:
        InputSpecError: for text that is not of that form.

    >>> parse_input_spec("3=1;P5=0@0,1@0.25")
    {3: 1, 5: [(0.0, 0), (0.25, 1)]}
    """
    out: dict = {}
    for part in text.split(";"):
        part = part.strip()
        if not part:
            continue
        pin, eq, rest = part.partition("=")
        try:
            if not eq:
                raise ValueError
            pin_n = int(pin.strip().upper().removeprefix("P"), 10)
            if "@" not in rest:
                out[pin_n] = _level(rest)
                continue
            steps = []
            for item in rest.split(","):
                lv, at, t = item.partition("@")
                seconds = float(t)
                if not at or not math.isfinite(seconds) or not 0 <= seconds <= MAX_SECONDS:
                    raise ValueError
                steps.append((seconds, _level(lv)))
            out[pin_n] = steps
        except ValueError:
            raise InputSpecError(f"cannot read {part!r}; expected e.g. 'P3=1' or 'P5=0@0,1@0.25'") from None
    return out


def _level(text: str) -> int:
    v = int(text.strip(), 10)
    if v not in (0, 1):
        raise ValueError
    return v
