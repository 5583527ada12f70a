"""The Propeller 1 chip emulator: runs Spin bytecode images cycle by cycle.

>>> from spinemu.chip import Chip, RunResult
"""
from .chip import Chip, RunResult

__all__ = ["Chip", "RunResult"]
