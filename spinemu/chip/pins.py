"""Pins: what the cogs drive, what INA reads, pin waits, and the recorded trace.

:class:`Pins` is a mixin of :class:`spinemu.chip.chip.Chip`.  ``dir`` is the
OR of the running cogs' DIRA; ``out`` the OR of ``DIRA & (OUTA | counter
outputs)`` (Propeller Manual v1.2, "I/O Pins").  A change is recorded at the
cycle of the interpreter instruction that writes the register + 4; the
record is sorted and folded into a :class:`spinemu.trace.PinTrace` at the end
of the run (cogs may run slightly out of time order).  INA reads driven pins
as driven and the others from the input model (:mod:`spinemu.chip.inputs`).
Live pin listeners (the bench's view of a run) are in :mod:`.listen`.
"""
from __future__ import annotations

from ..trace import PinTrace
from .cog import PIN_WAIT, RUNNING, STOPPED, Cog
from .control import Reschedule

__all__ = ["Pins"]

_NEVER = 1 << 62


class Pins:
    """Pin state, INA, WAITPEQ/WAITPNE and the pin record of a chip (mixin)."""

    def pin_state(self, t: int) -> tuple[int, int]:
        """``(dir, out)`` over running cogs at cycle ``t`` (counter outputs included)."""
        d = o = 0
        counters = self.counters if self.counters_on else None
        for c in self.cogs:
            if c.state != STOPPED:
                d |= c.dira
                out = c.outa
                if counters is not None:
                    out |= counters.outputs(c, t)
                o |= c.dira & out
        return d, o

    def ina(self, t: int) -> int:
        """What INA reads at cycle ``t``: driven pins as driven, the rest from the input model."""
        d, o = self.pin_state(t)
        return o | (self.inputs.levels(t) & ~d & 0xFFFFFFFF)

    def record_cog_pins(self, c: Cog, t: int) -> None:
        """Add cog ``c``'s pin drive at cycle ``t`` to the pin record."""
        out = c.outa
        if self.counters_on:
            out |= self.counters.outputs(c, t)
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, out, c.state != STOPPED))

    def note_pins(self, c: Cog, t: int) -> None:
        """Cog ``c`` changed DIRA, OUTA or a counter at cycle ``t`` (the pins change then)."""
        self.record_cog_pins(c, t)
        if self._pin_waiters:
            self._wake_pin_waiters(t)

    def wait_pins(self, c: Cog, mask: int, state: int, equal: bool, tf: int) -> int:
        issue, after = self.timing.waitpin[equal]
        t = tf + issue
        if ((self.ina(t) & mask) == state) == equal:
            return issue + after
        c.pin_wait = (mask, state, equal, after)
        c.state = PIN_WAIT
        self._cogs_changed = True
        self._pin_waiters.append(c)
        self._ext_seen = max(self._ext_seen, t)
        raise Reschedule(_NEVER - tf)

    def _wake_pin_waiters(self, t: int) -> None:
        """Resume the cogs whose WAITPEQ/WAITPNE condition holds at cycle ``t``.

        Called from inside another cog's bytecode (a pin write), it also
        preempts that cog's run loop, so the scheduler sees the woken cog.
        """
        woke = False
        for c in list(self._pin_waiters):
            mask, state, equal, after = c.pin_wait
            if ((self.ina(t) & mask) == state) == equal:
                self._pin_waiters.remove(c)
                c.pin_wait = None
                c.state = RUNNING
                self._cogs_changed = True
                c.t = t + after
                woke = True
        if woke:
            self._request_preemption()

    def _build_trace(self, end: int) -> PinTrace:
        trace = PinTrace(self.clock_hz, end_cycle=end)
        trace.record(0, 0, 0)
        state = {}
        for t, _, cog_id, dira, outa, running in sorted(self.pin_events):
            if t > end:
                break
            if running:
                state[cog_id] = (dira, outa)
            else:
                state.pop(cog_id, None)
            d = o = 0
            for dd, oo in state.values():
                d |= dd
                o |= dd & oo
            trace.record(t, d, o)
        return trace
