"""The Propeller 1 chip emulator: runs Spin bytecode and PASM cogs, cycle by cycle.

>>> from spinemu.chip import Chip, RunResult
"""
from .chip import Chip, RunResult

__all__ = ["Chip", "RunResult"]
