"""How long BS2 instructions take: the two timing modes, in one configurable place.

``exact``: instructions take no time; only commands with a stated duration
advance the clock (PAUSE n = n ms, PULSOUT, FREQOUT, SEROUT bit times,
NAP/SLEEP...).  Deterministic; what exact-value tests use.

``realistic``: every instruction also costs interpreter time, taken from
published BS2 measurements:

========================  =======  ==================================================
instruction               us       source
========================  =======  ==================================================
HIGH, LOW                 140      Tracy Allen, EME Systems, "BS2 instruction timing"
                                   (emesystems.com/OLDSITE/BS2speed.htm, scope
                                   measurement of a HIGH/LOW/HIGH/GOTO loop: 710 us)
GOTO (and the jumps       290      same page (710 - 3 x 140)
that LOOP, ELSE, EXIT
and CASE bodies compile
to)
PAUSE (fetch)             300      Parallax BASIC Stamp manual, PAUSE: "about 0.3 ms to
                                   fetch the PAUSE" (a loop around PAUSE n takes ~n+1 ms)
everything else           250      Parallax: the BS2 runs about 3000-4000 instructions/s
                                   (250-330 us each); README section 5 default
DEBUG, per character      1041.7   9600 baud, 10 bits per character
EEPROM WRITE, per byte    5000     [OPEN] 24LC16B maximum write-cycle time
========================  =======  ==================================================

Statements that compile to no BS2 token (labels, declarations, DO, ENDIF,
ENDSELECT) cost nothing in both modes.  Pin changes happen at the *end* of
the instruction that makes them (README 5).

The column's stepper demo in realistic mode: GOSUB 250 + assignment 250 +
GOTO 290 + READ 250 + PAUSE 300 + RETURN 250 + NEXT 250 = 1840 us on top of
PAUSE 15, so a step every 16.84 ms (README 6.3 window: 16.7-17.3 ms).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union

__all__ = ["Timing", "get_timing", "REALISTIC_US", "DEFAULT_US", "FREE_KINDS"]

#: Measured costs (microseconds); see the module docstring for sources.
REALISTIC_US = {
    "high": 140,
    "low": 140,
    "goto": 290,
    "pause": 300,
}

#: Everything not measured (README section 5).
DEFAULT_US = 250

#: Instruction kinds that the tokenizer emits no token for.
FREE_KINDS = frozenset({"nop", "do", "endif", "endselect", "label"})


@dataclass(frozen=True)
class Timing:
    """A timing mode: per-kind instruction costs and serial/EEPROM extras (us)."""

    name: str
    costs: dict = field(default_factory=dict)
    default_us: int = 0
    debug_char_us: float = 0.0          # DEBUG/DEBUGIN time per character
    eeprom_write_us: int = 0            # extra time per byte written by WRITE

    @property
    def realistic(self) -> bool:
        return self.default_us > 0

    def cost(self, kind: str) -> int:
        if kind in FREE_KINDS:
            return 0
        return self.costs.get(kind, self.default_us)


EXACT = Timing("exact")
REALISTIC = Timing("realistic", dict(REALISTIC_US), DEFAULT_US,
                   debug_char_us=10 * 1_000_000 / 9600, eeprom_write_us=5000)


def get_timing(mode: Union[str, Timing]) -> Timing:
    """``"exact"``, ``"realistic"`` or a custom :class:`Timing`.

    >>> get_timing("realistic").cost("goto"), get_timing("exact").cost("goto")
    (290, 0)
    """
    if isinstance(mode, Timing):
        return mode
    key = str(mode).lower()
    if key in ("exact", "ideal"):
        return EXACT
    if key == "realistic":
        return REALISTIC
    raise ValueError(f"unknown timing mode {mode!r} (use 'exact' or 'realistic')")
