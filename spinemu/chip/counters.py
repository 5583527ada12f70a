"""Counter modules CTRA/CTRB: NCO and DUTY outputs on pins, PHS accumulation, event-driven.

Each cog has two counters (Propeller Manual v1.2, "CTRA, CTRB"; AN001
"Propeller Counters").  The CTR register holds the mode (bits 30..26), the
PLL divider (25..23), BPIN (14..9) and APIN (5..0).  Every clock, while the
mode's condition holds, ``PHS += FRQ``.

Modelled:

* ``%00100`` NCO single-ended: APIN = PHS[31];
* ``%00101`` NCO differential: APIN = PHS[31], BPIN = !PHS[31];
* ``%00110`` DUTY single-ended: APIN = the carry out of ``PHS += FRQ``;
* ``%00111`` DUTY differential: APIN = carry, BPIN = !carry;
* ``%11111`` LOGIC always: PHS accumulates every clock (no output).

A counter output reaches its pin only where the cog's DIRA bit is set; the
cog then drives ``OUTA | counter outputs``.  Nothing runs per clock: PHS is
``PHS0 + FRQ * (t - t0)``, and pin edges are computed in closed form and
written to the pin record lazily (before the cog changes its counter or pin
registers, when it stops, and at the end of the run).  WAITPEQ/WAITPNE wake on
counter edges too.

Not modelled (a warning says so when a program selects them): the PLL modes
(%00001-%00011; video is not emulated) and the input-driven modes
(%01000-%11110: POS/NEG detectors, edge counters, logic functions of pins),
in which PHS then stays where it was.
"""
from __future__ import annotations

from typing import Optional

__all__ = ["Counters", "MODE_NCO", "MODE_DUTY"]

_M = 0xFFFFFFFF
MODE_NCO, MODE_NCO_DIFF, MODE_DUTY, MODE_DUTY_DIFF, MODE_ALWAYS = 0b00100, 0b00101, 0b00110, 0b00111, 0b11111
_OUTPUT_MODES = {MODE_NCO, MODE_NCO_DIFF, MODE_DUTY, MODE_DUTY_DIFF}
_ACCUMULATING = _OUTPUT_MODES | {MODE_ALWAYS}
#: counter edges recorded in one run before the record stops (a 40 MHz DUTY output
#: would otherwise fill memory); a warning tells when it happens
MAX_EDGES = 2_000_000


class _Counter:
    __slots__ = ("ctr", "frq", "phs0", "t0", "flushed", "mode")

    def __init__(self):
        self.ctr = self.frq = self.phs0 = self.t0 = self.flushed = self.mode = 0

    def phs(self, t: int) -> int:
        if self.mode in _ACCUMULATING:
            return (self.phs0 + self.frq * (t - self.t0)) & _M
        return self.phs0

    def outputs(self, t: int) -> int:
        """The pin mask this counter drives high at cycle ``t``."""
        mode = self.mode
        if mode not in _OUTPUT_MODES:
            return 0
        if mode <= MODE_NCO_DIFF:
            level = (self.phs(t) >> 31) & 1
        else:                           # DUTY: the carry of the update that ended at t
            s = self.phs0 + self.frq * (t - self.t0)
            level = 1 if self.frq and t > self.t0 and (s >> 32) != ((s - self.frq) >> 32) else 0
        if level:
            return 1 << (self.ctr & 31)
        return 1 << ((self.ctr >> 9) & 31) if mode & 1 else 0

    def edges(self, t_from: int, t_to: int):
        """Cycles in ``(t_from, t_to]`` at which :meth:`outputs` changes, in order."""
        mode, frq = self.mode, self.frq
        if mode not in _OUTPUT_MODES or frq == 0:
            return
        base = self.phs0 + frq * (t_from - self.t0)          # S(t_from), unbounded
        if mode in (MODE_NCO, MODE_NCO_DIFF):
            step = 1 << 31
            k = base // step + 1                               # next multiple of 2**31 to cross
            while True:
                t = t_from + -(-(k * step - base) // frq)
                if t > t_to:
                    return
                yield t
                k += 1
        else:
            step = 1 << 32
            k = base // step + 1
            while True:
                t = t_from + -(-(k * step - base) // frq)      # carry out during the clock ending at t
                if t > t_to:
                    return
                yield t
                if t + 1 <= t_to:
                    yield t + 1
                k += 1


class Counters:
    """The sixteen counters of a chip, and their effect on pins."""

    def __init__(self, chip):
        self.chip = chip
        self.units = [(_Counter(), _Counter()) for _ in range(8)]
        self.edges_recorded = 0
        self.warned = set()

    # register access (from spinemu.chip.registers) -------------------------
    def write(self, c, which: int, v: int, t: int) -> None:
        """CTRA(0)/CTRB(1)/FRQA(2)/FRQB(3)/PHSA(4)/PHSB(5) of cog ``c`` := ``v`` at cycle ``t``."""
        self.flush(c, t)
        unit = self.units[c.id][which & 1]
        unit.phs0, unit.t0 = unit.phs(t), t
        kind = which >> 1
        if kind == 0:
            unit.ctr = v
            unit.mode = (v >> 26) & 31
            if unit.mode and unit.mode not in _ACCUMULATING and unit.mode not in self.warned:
                self.warned.add(unit.mode)
                self.chip.warnings.append(
                    f"cog {c.id} set counter mode %{unit.mode:05b}, which spinemu does not model "
                    "(only NCO, DUTY and LOGIC-always are): its PHS stays put and it drives no pin")
        elif kind == 1:
            unit.frq = v
        else:
            unit.phs0 = v
        name = ("ctra", "ctrb", "frqa", "frqb", "phsa", "phsb")[which]
        setattr(c, name, v)
        if unit.mode in _OUTPUT_MODES:
            self.chip.counters_on = True
        self.chip.note_pins(c, t)

    def phs(self, c, ab: int, t: int) -> int:
        return self.units[c.id][ab].phs(t)

    # pins ------------------------------------------------------------------
    def outputs(self, c, t: int) -> int:
        """Pins cog ``c``'s counters drive high at ``t`` (before DIRA gating)."""
        a, b = self.units[c.id]
        return (a.outputs(t) if a.mode in _OUTPUT_MODES else 0) | (b.outputs(t) if b.mode in _OUTPUT_MODES else 0)

    def flush(self, c, t: int) -> None:
        """Record cog ``c``'s counter pin edges up to cycle ``t``."""
        a, b = self.units[c.id]
        start = max(a.flushed, b.flushed)
        a.flushed = b.flushed = max(start, t)
        if not (a.mode in _OUTPUT_MODES or b.mode in _OUTPUT_MODES) or t <= start or not c.dira:
            return
        times = sorted(set(a.edges(start, t)) | set(b.edges(start, t)))
        if self.edges_recorded + len(times) > MAX_EDGES:
            if "edges" not in self.warned:
                self.warned.add("edges")
                self.chip.warnings.append(
                    f"counter output edges exceed {MAX_EDGES:,}: later counter edges are not recorded in the trace")
            return
        self.edges_recorded += len(times)
        for te in times:
            self.chip.record_cog_pins(c, te)

    def next_edge(self, t: int) -> Optional[int]:
        """The first counter edge of any running cog after ``t`` (for WAITPEQ/WAITPNE)."""
        best = None
        for c in self.chip.cogs:
            if c.state == "stopped":
                continue
            for unit in self.units[c.id]:
                for te in unit.edges(t, t + (1 << 40)):
                    if best is None or te < best:
                        best = te
                    break
        return best
