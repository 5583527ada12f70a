"""Parts on the pins: the one interface every part has, on every engine.

A *part* is a small class for something that hangs on the pins (an LED, a
button, an EEPROM, a servo, an LCD).  It never knows which engine runs the
program: the Propeller's Spin and PASM cogs, the translated Python, or the
BASIC Stamp.  Parts are put on a :class:`~spinemu.bench.board.Bench`
(``bench.add(Servo(pin=16))``), which attaches them to an engine, or attached
alone (``part.attach(engine)``).

A part does two things, each one way:

* **What it puts on the pins** (:meth:`Part.levels`, :meth:`Part.next_change`):
  the part is an *input model* for the pins it drives
  (:meth:`Part.driven_pins`).  The engine asks it whenever the program reads
  its pins, so the answer is exact at every read: a part whose outputs depend
  on what the program drives (an EEPROM answering its master, an RC circuit,
  an LCD's busy flag) derives them from the engine's *drive history*
  (:mod:`spinemu.bench.history`) up to the cycle asked -- the base class for
  those is :class:`ReactivePart`.  ``next_change`` is exact, so that a program
  waiting on the part (WAITPEQ, RCTIME) still skips time.
* **What it sees** (:meth:`Part.on_pins`): the pin states as the run goes,
  after the fact, for parts that only watch (an LED's duty, a servo's angle,
  an LCD's text).  The states are the *wire* levels: what the engine drives,
  and on the pins a part or a stimulus drives, their level.

Besides, a part reports: :meth:`Part.summary` (one line for the end of a
run), :meth:`Part.view` (its line in the live view), ``warnings`` (protocol
violations, as :class:`PartWarning` at the cycle they happened).

Writing one: subclass :class:`Part` (or :class:`ReactivePart`), give it a
``kind`` (its name in bench files), declare its pins, implement what it needs.
"""
from __future__ import annotations

from bisect import bisect_left, bisect_right
from collections import deque

from ..records import FrozenRecord

__all__ = ["Part", "ReactivePart", "PartWarning", "pins_mask", "check_pin"]


class PartWarning(FrozenRecord):
    """A protocol violation or misuse a part saw.

    Attributes:
        cycle: when it happened (engine cycles).
        seconds: the same in seconds.
        part: the part's name.
        message: what happened.
    """

    _fields = ("cycle", "seconds", "part", "message")

    def __init__(self, cycle: int, seconds: float, part: str, message: str):
        self.cycle, self.seconds, self.part, self.message = cycle, seconds, part, message

    def __str__(self) -> str:
        return f"{self.part}: {self.message} (at {self.seconds:.6f} s, cycle {self.cycle:,})"


def pins_mask(pins) -> int:
    """The bit mask of some pin numbers (``None`` entries skipped)."""
    m = 0
    for p in pins:
        if p is not None:
            m |= 1 << p
    return m


def check_pin(value, what: str = "pin") -> int:
    """A pin number 0..31 (whether the engine has it is checked when attaching).

    Raises:
        ValueError: for anything else.
    """
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 31:
        raise ValueError(f"{what} must be a pin number 0..31, not {value!r}")
    return value


class Part:
    """Something on the pins (see the module docstring).

    Args:
        name: how reports call it (default: its kind and pins).

    Attributes:
        kind: the part's name in bench files (``"led"``, ``"servo"``...).
        reactive: its levels depend on what the engine drives (it reads the
            drive history); engines then re-check pin waits after every drive.
        warnings: :class:`PartWarning` entries, in time order.
        clock_hz: the engine's clock, once attached.
    """

    kind = "part"
    #: the constructor's parameters that are pins (bench files check them against the engine)
    pin_parameters = ("pin",)
    reactive = False
    #: the part lets go of its driven pins at times (:meth:`released` says which): they then read
    #: what the engine's own input model says
    releases = False

    def __init__(self, *, name: str | None = None):
        self._name = name
        self.warnings: list[PartWarning] = []
        self.clock_hz: int | None = None
        self.port = None

    @property
    def name(self) -> str:
        if self._name:
            return self._name
        pins = self.driven_pins() + tuple(p for p in self.watched_pins() if p not in self.driven_pins())
        return f"{self.kind} " + "/".join(f"P{p}" for p in pins) if pins else self.kind

    # ------------------------------------------------------------------ pins
    def driven_pins(self) -> tuple:
        """The pins whose level this part sets (it is their input model)."""
        return ()

    def watched_pins(self) -> tuple:
        """The pins this part looks at."""
        return ()

    @property
    def driven_mask(self) -> int:
        """:meth:`driven_pins` as a bit mask."""
        return pins_mask(self.driven_pins())

    # ------------------------------------------------------------------ attaching
    def attach(self, engine):
        """Put this part alone on ``engine`` (a one-part :class:`~spinemu.bench.board.Bench`).

        Returns:
            the bench.
        """
        from .board import Bench
        bench = Bench([self])
        bench.attach(engine)
        return bench

    def connect(self, port) -> None:
        """Called by the bench when it attaches to an engine (``port``: ``clock_hz``, ``pin_count``,
        ``history``).  Subclasses that need set-up extend it."""
        if self.port is not None:
            raise RuntimeError(f"{self.name} is attached to a run already; make a new part for another run")
        self.port = port
        self.clock_hz = port.clock_hz

    # ------------------------------------------------------------------ input model
    def levels(self, cycle: int) -> int:
        """The levels this part puts on its driven pins at ``cycle`` (other bits are ignored)."""
        return 0

    def next_change(self, cycle: int) -> int | None:
        """The first cycle after ``cycle`` at which :meth:`levels` changes (given the drives so far), or None."""
        return None

    def released(self, cycle: int) -> int:
        """For a part that ``releases``: the driven pins it leaves alone at ``cycle`` (bit mask)."""
        return 0

    # ------------------------------------------------------------------ observer
    def on_pins(self, changes: list, upto: int, present: int) -> None:
        """The wire states ``(cycle, dir, out)`` that became final, in time order; nothing changes before
        ``upto`` any more; an input change at or after ``present`` is still seen by the program."""

    def finish(self, end_cycle: int) -> None:
        """The run ended at ``end_cycle`` (after the last :meth:`on_pins`)."""

    # ------------------------------------------------------------------ reports
    def summary(self) -> str:
        """One line: what the part did in the run."""
        return self.name

    def view(self) -> str:
        """Its line in the live view (what it shows or does now)."""
        return self.summary()

    def seconds(self, cycle: int) -> float:
        return cycle / self.clock_hz if self.clock_hz else 0.0

    def warn(self, cycle: int, message: str) -> None:
        """Report a protocol violation at ``cycle``."""
        self.warnings.append(PartWarning(cycle, self.seconds(cycle), self.name, message))


class ReactivePart(Part):
    """A part whose outputs follow from what the engine drove on its watched pins.

    The base class keeps the bookkeeping that makes the outputs exact:
    subclasses see every change of their watched pins' drive state in time
    order (:meth:`on_drive`) and say what they output from which cycle on
    (:meth:`output`); :meth:`levels` and :meth:`next_change` answer from that
    record, after working through the drive history up to the cycle asked.
    A response to a drive at cycle ``x`` starts at ``x + 1`` at the earliest.
    When an engine records a drive earlier than drives already worked
    through (the Propeller's cogs run a little apart), the part goes back to
    a checkpoint before it and works forward again.

    Subclasses implement :meth:`reset` (the state at power-up, in
    ``self.s``), :meth:`on_drive` and :meth:`initial_levels`; state other
    than ``self.s`` that changes must be saved by overriding :meth:`save`
    and :meth:`restore`.
    """

    reactive = True
    #: checkpoints kept for going back after a late drive
    CHECKPOINTS = 24

    def connect(self, port) -> None:
        super().connect(port)
        self._hist = port.history
        self._mask = pins_mask(self.watched_pins())
        self._mark = 0
        self._restart()

    # ------------------------------------------------------------------ for subclasses
    def reset(self) -> None:
        """Set ``self.s`` to the state at power-up."""
        self.s = None

    def initial_levels(self) -> int:
        """The outputs before any drive."""
        return 0

    def on_drive(self, cycle: int, dir_mask: int, out_mask: int) -> None:
        """The watched pins' drives changed at ``cycle`` (masks limited to the watched pins)."""

    def save(self):
        """The part's state for a checkpoint (default: a deep copy of ``self.s``)."""
        from copy import deepcopy      # (here: only checkpoints need it, and it is slow to import)
        return deepcopy(self.s)

    def restore(self, state) -> None:
        from copy import deepcopy
        self.s = deepcopy(state)

    def output(self, cycle: int, levels: int) -> None:
        """From ``cycle`` on, this part outputs ``levels`` (replacing what it had predicted from there on)."""
        if cycle <= self._now:
            cycle = self._now + 1
        times, values = self._times, self._values
        i = bisect_left(times, cycle)
        del times[i:]
        del values[i:]
        if values[-1] != levels:
            times.append(cycle)
            values.append(levels)

    def output_at(self, cycle: int) -> int:
        """What this part outputs at ``cycle`` as recorded and predicted so far."""
        return self._values[bisect_right(self._times, cycle) - 1]

    @property
    def now(self) -> int:
        """The cycle of the drive being worked through."""
        return self._now

    # ------------------------------------------------------------------ input model
    def levels(self, cycle: int) -> int:
        self._sync(cycle)
        return self._values[bisect_right(self._times, cycle) - 1]

    def next_change(self, cycle: int) -> int | None:
        end = self._hist.recorded_end()
        self._sync(end if end > cycle else cycle)
        times = self._times
        i = bisect_right(times, cycle)
        return times[i] if i < len(times) else None

    def finish(self, end_cycle: int) -> None:
        self._sync(end_cycle + 1)

    def drive_log(self) -> list:
        """The watched pins' drive states worked through: ``(cycle, dir, out)``."""
        return list(self._log)

    # ------------------------------------------------------------------ bookkeeping
    def _restart(self) -> None:
        self.reset()
        self._times = [0]
        self._values = [self.initial_levels()]
        self._done = 0
        self._now = -1
        self._last = (0, 0)
        self._log: list = []
        self._checkpoints: deque = deque(maxlen=self.CHECKPOINTS)
        self._warn_from = len(self.warnings)

    def _sync(self, target: int) -> None:
        """Work through the drives before ``target``."""
        lo, self._mark = self._hist.recorded_since(self._mark)
        if lo is not None and lo < self._done:
            self._late(lo)
        if target <= self._done:
            return
        mask = self._mask
        last = self._last
        first = True
        for c, d, o in self._hist.changes(self._done, target):
            state = (d & mask, o & d & mask)
            if state == last:
                continue
            if first:
                self._checkpoint()
                first = False
            last = self._last = state
            self._log.append((c,) + state)
            self._now = c
            self.on_drive(c, state[0], state[1])
        self._done = target

    def _checkpoint(self) -> None:
        done = self._done
        i = bisect_left(self._times, done)
        self._checkpoints.append((done, self.save(), len(self._log), self._last, self._now,
                                  list(zip(self._times[i:], self._values[i:])), len(self.warnings)))

    def _late(self, lo: int) -> None:
        """A drive at ``lo`` was recorded after drives later than it were worked through."""
        log = self._log
        i = bisect_left(log, (lo,))
        before = log[i - 1][1:] if i else (0, 0)
        redo = []
        mask = self._mask
        last = before
        for c, d, o in self._hist.changes(lo, self._done):
            state = (d & mask, o & d & mask)
            if state != last:
                redo.append((c,) + state)
                last = state
        if redo == log[i:]:
            return                              # nothing this part watches changed
        for k in range(len(self._checkpoints) - 1, -1, -1):
            if self._checkpoints[k][0] <= lo:
                done, state, n_log, last, now, tail, n_warn = self._checkpoints[k]
                while len(self._checkpoints) > k:
                    self._checkpoints.pop()
                self.restore(state)
                del self._log[n_log:]
                j = max(1, bisect_left(self._times, done))
                del self._times[j:]
                del self._values[j:]
                for t, v in tail:
                    if self._values[-1] != v:
                        self._times.append(t)
                        self._values.append(v)
                del self.warnings[n_warn:]
                self._done, self._last, self._now = done, last, now
                return
        del self.warnings[self._warn_from:]
        self._restart()                         # no checkpoint that early: from the start
