"""Signals a bytecode handler raises to hand control back to the scheduler.

They are exceptions because they are rare: the interpreter's hot loop pays
nothing for them (zero-cost ``try`` in CPython 3.11) and checks no flags.
Each carries ``rest``: the cycles from the bytecode's fetch to the start of
the cog's next bytecode, as a normal handler would have returned.
"""
from __future__ import annotations

__all__ = ["Reschedule", "CogStopped", "RebootRequested", "Preempted", "Halted"]


class Reschedule(Exception):
    """The bytecode changed what other cogs do (started or stopped a cog,
    changed pins someone waits on): the scheduler must look again."""

    def __init__(self, rest: int):
        self.rest = rest


class CogStopped(Exception):
    """The running cog stopped itself; ``rest`` = cycles from fetch to the stop."""

    def __init__(self, rest: int):
        self.rest = rest


class RebootRequested(Exception):
    """CLKSET with bit 7 set: the chip reboots."""

    def __init__(self, rest: int):
        self.rest = rest


class Preempted(Exception):
    """Raised *instead of* running the next bytecode: a parked cog was woken
    (fastforward.py) and the scheduler must run it first.  The bytecode has
    not started; the run loop puts the cog back before it."""


class Halted(Exception):
    """A probe (a debugger, the test harness) stops the run *between* two
    bytecodes of one cog (spinemu.chip.probe); ``Chip.advance`` returns
    ``reason``, and the chip can go on from there."""

    def __init__(self, reason: str):
        self.reason = reason
