"""A bench: the parts around one program, attached to any engine the same way.

:class:`Bench` holds parts (``bench.add(Servo(pin=16))``), checks that no two
of them drive one pin, and attaches them to an engine before its run:

* the engine's input model becomes :class:`BenchInputs`: the parts' levels
  on the pins they drive, the engine's own model (pull mode, ``--input``
  stimuli) on the others;
* one pin listener hands every part the *wire* states as the run goes
  (``on_pins``): the engine's drives, and on the pins a part or a stimulus
  drives, their level (so a live I2C decoder sees the EEPROM's ACKs);
* after the run, each part finishes (``finish``) and reports.

The engine interface a bench needs (the Propeller chip, the Python engine's
chip and the BASIC Stamp machine all offer it):

* ``clock_hz``, ``pin_count``;
* ``inputs``: the input model, which the bench replaces by its own on top;
* ``drive_history``: what the engine drove (:mod:`spinemu.bench.history`);
* ``add_pin_listener(listener, interval_cycles)``: the engine calls
  ``listener(changes, upto, present)`` as it runs (see :mod:`spinemu.bench`)
  and, after the last call, ``listener.run_ended(end_cycle)``.

:meth:`Bench.wire_trace` gives a run's trace with the parts' levels in it
(what a logic analyser on the board would record), for VCD files and the
protocol decoders.
"""
from __future__ import annotations

from collections.abc import Iterable

from ..trace import PinTrace
from .inputs import model_mask
from .part import Part, PartWarning

__all__ = ["Bench", "BenchInputs", "Port", "BenchPinError"]

_NEVER = 1 << 62


class BenchPinError(ValueError):
    """Two parts drive one pin, or a part's pin does not exist on the engine.

    Attributes:
        part: the part at fault (its ``origin``, if it came from a bench
            file, says where it was written).
        pin: the pin.
    """

    def __init__(self, message: str, part=None, pin: int | None = None):
        super().__init__(message)
        self.part, self.pin = part, pin


class Port:
    """What a part sees of the engine: ``clock_hz``, ``pin_count`` and the drive ``history``."""

    def __init__(self, engine):
        self.clock_hz = int(engine.clock_hz)
        self.pin_count = int(getattr(engine, "pin_count", 32))
        self.history = engine.drive_history


class BenchInputs:
    """The input model of an engine with a bench: each part's levels on its pins, ``base`` elsewhere.

    Attributes:
        mask: the pins driven by a part or by ``base`` (a stimulus).
        reactive: some part's levels depend on what the engine drives.
    """

    def __init__(self, base, parts: list):
        self.base = base
        self.parts = [(p, p.driven_mask) for p in parts if p.driven_mask]
        self.part_mask = 0
        for _, m in self.parts:
            self.part_mask |= m
        self.keep = ~self.part_mask & 0xFFFFFFFF
        self.mask = self.part_mask | model_mask(base)
        self.reactive = bool(getattr(base, "reactive", False) or any(p.reactive for p, _ in self.parts))
        self._steady = [(p, m) for p, m in self.parts if not getattr(p, "releases", False)]
        self._releasing = [(p, m) for p, m in self.parts if getattr(p, "releases", False)]

    def levels(self, cycle: int) -> int:
        v = self.base.levels(cycle) & self.keep
        for p, m in self._steady:
            v |= p.levels(cycle) & m
        if self._releasing:
            base = self.base.levels(cycle)
            for p, m in self._releasing:
                free = p.released(cycle) & m
                v |= (p.levels(cycle) & m & ~free) | (base & free)
        return v

    def next_change(self, cycle: int) -> int | None:
        best = self.base.next_change(cycle)
        for p, _ in self.parts:
            t = p.next_change(cycle)
            if t is not None and (best is None or t < best):
                best = t
        return best

    def sources(self) -> list:
        """The models whose changes show on the wire: the parts, and ``base`` if it drives pins."""
        out = [p for p, _ in self.parts]
        if model_mask(self.base):
            out.append(self.base)
        return out


class Bench:
    """Parts around one program (see the module docstring).

    Args:
        parts: parts to add at once.
        name: a name for reports (the bench file's).

    >>> from spinemu.bench import Bench, Led, Servo
    >>> bench = Bench([Led(pin=16)])
    >>> servo = bench.add(Servo(pin=17))
    >>> [p.name for p in bench.parts]
    ['LED P16', 'servo P17']
    """

    def __init__(self, parts: Iterable[Part] = (), *, name: str | None = None):
        self.parts: list[Part] = []
        self.name = name
        self.clock_hz: int | None = None
        self.end_cycle: int | None = None
        self.inputs: BenchInputs | None = None
        #: called as ``on_time(cycle)`` after the parts have seen the pins up to ``cycle`` (live views)
        self.on_time = None
        self._attached = False
        for p in parts:
            self.add(p)

    def add(self, part: Part) -> Part:
        """Put ``part`` on the bench and return it.

        Raises:
            BenchPinError: if a pin it drives is driven by a part already there.
            RuntimeError: once the bench is attached.
        """
        if self._attached:
            raise RuntimeError("add parts before the bench is attached to a run")
        if not isinstance(part, Part):
            raise TypeError(f"a bench holds parts (spinemu.bench.Part), not {type(part).__name__}")
        for other in self.parts:
            both = set(part.driven_pins()) & set(other.driven_pins())
            if both:
                pin = min(both)
                raise BenchPinError(f"P{pin} is driven by two parts: {other.name} and {part.name}", part, pin)
        self.parts.append(part)
        return part

    def find(self, kind: str) -> list:
        """The parts of one kind (``"eeprom"``, ``"servo"``...)."""
        return [p for p in self.parts if p.kind == kind]

    # ------------------------------------------------------------------ attaching
    def attach(self, engine, interval_cycles: int | None = None) -> None:
        """Connect every part to ``engine`` before its run.

        Args:
            engine: a :class:`spinemu.chip.Chip` (either engine), a BASIC
                Stamp machine, or anything with the interface above.
            interval_cycles: how often the parts see the pins (default: a
                hundredth of a second).

        Raises:
            BenchPinError: for a pin the engine does not have.
            RuntimeError: if this bench is attached already.
        """
        if self._attached:
            raise RuntimeError("a bench is attached to one run; make a new one for another run")
        port = Port(engine)
        for p in self.parts:
            for pin in set(p.driven_pins()) | set(p.watched_pins()):
                if not 0 <= pin < port.pin_count:
                    raise BenchPinError(f"{p.name}: P{pin} does not exist on this engine "
                                        f"(pins are 0..{port.pin_count - 1})", p, pin)
        self._attached = True
        self.clock_hz = port.clock_hz
        for p in self.parts:
            p.connect(port)
        self.inputs = BenchInputs(engine.inputs, self.parts)
        engine.inputs = self.inputs
        self._wire = _WireView(self.inputs)
        engine.add_pin_listener(_Listener(self), interval_cycles or max(1, port.clock_hz // 100))

    def _listen(self, changes: list, upto: int, present: int) -> None:
        wire = self._wire.advance(changes, upto if upto < _NEVER else present)
        for p in self.parts:
            p.on_pins(wire, upto, present)
            if p.reactive and upto < _NEVER:
                p.levels(upto)                  # worked through up to now, for live views
        if self.on_time is not None:
            self.on_time(upto)

    def _ended(self, end_cycle: int) -> None:
        self.end_cycle = end_cycle
        for p in self.parts:
            p.finish(end_cycle)

    # ------------------------------------------------------------------ results
    @property
    def warnings(self) -> list[PartWarning]:
        """Every part's warnings, in time order."""
        return sorted((w for p in self.parts for w in p.warnings), key=lambda w: w.cycle)

    def summary(self) -> list[str]:
        """One line per part: what it did."""
        return [p.summary() for p in self.parts]

    def view(self) -> list[tuple[str, str]]:
        """``(name, state)`` of every part now (the live view's rows)."""
        return [(p.name, p.view() if p.port is not None else "") for p in self.parts]

    def wire_trace(self, trace: PinTrace) -> PinTrace:
        """``trace`` with the levels the bench put on the pins it drives.

        A pin a part (or a stimulus) drives counts as driven whenever the
        engine does not drive it, at the level the part puts on it; where the
        engine drives it, the engine's level is recorded (as INA reads it).

        Raises:
            RuntimeError: before the bench was attached to a run.
        """
        if self.inputs is None:
            raise RuntimeError("the bench was not attached to a run")
        view = _WireView(self.inputs)
        end = trace.end_cycle
        changes = view.advance([c for c in trace.changes if c[0] <= end], end + 1)
        out = PinTrace(trace.clock_hz, [], end, trace.pin_count, dict(trace.pin_names))
        if not changes or changes[0][0] != 0:
            out.record(0, 0, 0)
        for c, d, o in changes:
            out.record(c, d, o)
        return out


class _Listener:
    """The bench's pin listener (an object, so that the engine can tell it the run ended)."""

    def __init__(self, bench: Bench):
        self.bench = bench

    def __call__(self, changes, upto, present):
        self.bench._listen(changes, upto, present)

    def run_ended(self, end_cycle: int) -> None:
        self.bench._ended(end_cycle)


class _WireView:
    """Engine drive states merged with the input model's levels on the pins the bench drives."""

    def __init__(self, inputs: BenchInputs):
        self.inputs = inputs
        self.mask = inputs.mask
        self.sources = inputs.sources()
        self.to = 0                 # input levels are merged before this cycle
        self.drive = (0, 0)
        self.levels: int | None = None
        self.state = (0, 0)

    def _input_changes(self, a: int, b: int) -> list:
        times = set()
        if self.levels is None:
            times.add(a)
        for src in self.sources:
            t = a - 1
            while True:
                t = src.next_change(t)
                if t is None or t >= b:
                    break
                times.add(t)
        mask = self.mask
        levels = self.inputs.levels
        return [(t, levels(t) & mask) for t in sorted(times)]

    def advance(self, changes: list, upto: int) -> list:
        """The wire states for the drive ``changes`` before ``upto`` (time order)."""
        mask = self.mask
        if not mask:
            return changes
        inputs = self._input_changes(self.to, upto) if upto > self.to else []
        self.to = max(self.to, upto)
        out = []
        i = j = 0
        n, m = len(changes), len(inputs)
        d, o = self.drive
        lv = self.levels if self.levels is not None else 0
        while i < n or j < m:
            if j >= m or (i < n and changes[i][0] <= inputs[j][0]):
                t, d, o = changes[i]
                i += 1
            else:
                t, lv = inputs[j]
                j += 1
            if (i < n and changes[i][0] == t) or (j < m and inputs[j][0] == t):
                continue                        # the state after everything at this cycle
            free = mask & ~d
            state = (d | mask, (o & d) | (lv & free))
            if state != self.state:
                self.state = state
                out.append((t,) + state)
        self.drive = (d, o)
        if m:
            self.levels = lv
        return out
