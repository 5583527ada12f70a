"""Pins: what the cogs drive, what INA reads, pin waits, and the recorded trace.

:class:`Pins` is a mixin of :class:`spinemu.chip.chip.Chip`.  ``dir`` is the
OR of the running cogs' DIRA; ``out`` the OR of ``DIRA & (OUTA | counter
outputs)`` (Propeller Manual v1.2, "I/O Pins").  A change is recorded at the
cycle of the interpreter instruction that writes the register + 4.  The
record (``pin_events``) holds what each cog wrote to DIRA and OUTA (cogs may
append slightly out of time order); :class:`spinemu.chip.pinfold.PinFold`
folds it in time order, with the counter outputs from the counters' own
history (:mod:`spinemu.chip.countermarks`), into combined pin states: the
live pin listeners (the bench's view of a run, :mod:`.listen`) read them as
the run goes, and at the end they make the :class:`spinemu.trace.PinTrace`.
INA reads driven pins as driven and the others from the input model
(:mod:`spinemu.chip.inputs`); the pins as they were at an earlier cycle are
in :mod:`spinemu.chip.pinhistory`.
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
        """``(dir, out)`` over running cogs at cycle ``t`` (counter outputs included).

        A cog's DIRA/OUTA write shows to other cogs from the recorded change's
        cycle (a Spin bytecode's) or 4 cycles before it (a PASM instruction's);
        see :meth:`~spinemu.chip.registers.Registers.write`.  A Spin bytecode
        that writes a register runs, in the scheduler's order, at its access
        (where it reads), some cycles before its write: a cog reading INA in
        between sees the pins as they were (:attr:`Cog.pin_hist`), as on the
        reference interpreter.
        """
        d = o = 0
        counters = self.counters if self.counters_on else None
        for c in self.cogs:
            h = c.pin_hist
            if h and h[-1][0] > t:
                dira, outa, on = self._pins_before(c, t)
                if not on:
                    continue
            elif c.state != STOPPED:
                dira, outa = c.dira, c.outa
            else:
                continue
            d |= dira
            out = outa
            if counters is not None:
                out |= counters.outputs(c, t)
            o |= dira & out
        return d, o

    def ina(self, t: int) -> int:
        """What INA reads at cycle ``t``: driven pins as driven, the rest from the input model."""
        d, o = self.pin_state(t)
        return o | (self.inputs.levels(t) & ~d & 0xFFFFFFFF)

    @staticmethod
    def _pins_before(c: Cog, t: int) -> tuple:
        """``(dira, outa, running)`` of cog ``c`` as other cogs see them at cycle ``t`` (:attr:`Cog.pin_hist`)."""
        for when, dira, outa, running in reversed(c.pin_hist):
            if when <= t:
                return dira, outa, running
        return 0, 0, False

    def _pin_history(self, c: Cog, when: int, running: bool) -> None:
        h = c.pin_hist
        h.append((when, c.dira, c.outa, running))
        if len(h) > 8:
            del h[:4]

    def record_cog_pins(self, c: Cog, t: int) -> None:
        """Add cog ``c``'s DIRA and OUTA at cycle ``t`` to the pin record (counter outputs are added from
        the counters' own history when the trace is built)."""
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, c.outa, c.state != STOPPED))
        self._pin_history(c, t, c.state != STOPPED)

    def note_pins(self, c: Cog, t: int, seen=None, spin: bool = False) -> None:
        """Cog ``c`` changed DIRA or OUTA at cycle ``t`` (the pins change then; ``seen``, ``spin``: see
        :meth:`~spinemu.chip.registers.Registers.write`)."""
        self._seq += 1
        self.pin_events.append((t, self._seq, c.id, c.dira, c.outa, c.state != STOPPED))
        self._pin_history(c, t if spin else t - 4, c.state != STOPPED)
        if self._pin_waiters:
            self._wake_pin_waiters(t, c, seen)
            if self.counters.feedback_on:       # a feedback output follows its input one clock later
                self._wake_pin_waiters(t + 1, c)
            if self._reactive_inputs:           # a bench part may answer later: the scheduler asks it again
                self._request_preemption()
        if self.pin_hooks:
            for f in self.pin_hooks:
                f(c, t)

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

    def _wake_pin_waiters(self, t: int, writer=None, seen=None) -> None:
        """Resume the cogs whose WAITPEQ/WAITPNE condition holds at cycle ``t``.

        Called from inside another cog's instruction (``writer``'s pin write),
        it also preempts that cog's run loop, so the scheduler sees the woken
        cog.  A Spin waiter resumes a fixed time after ``t``; a PASM waiter
        (``after`` None) at its next poll, a parked PASM loop at the first
        pass that sees the change (``seen``: the writer's access, default
        ``t - 4``; :meth:`PasmEngine.wake_time`).
        """
        woke = False
        for c in list(self._pin_waiters):
            mask, state, equal, after = c.pin_wait
            if ((self.ina(t) & mask) == state) == equal:
                self._pin_waiters.remove(c)
                c.t = t + after if after is not None else c.engine.wake_time(c, t, writer, seen)
                c.pin_wait = None
                c.state = RUNNING
                self._cogs_changed = True
                woke = True
        if woke:
            self._request_preemption()

    def _build_trace(self, end: int) -> PinTrace:
        """The pin trace up to ``end``: the pin record and the counters' outputs, folded by :attr:`pin_fold`
        (the same fold the live pin listeners read)."""
        self.pin_fold.advance(end + 1)
        trace = PinTrace(self.clock_hz, end_cycle=end)
        trace.record(0, 0, 0)
        for t, d, o in self.pin_fold.changes:
            if t > end:
                break
            trace.record(t, d, o)
        return trace
