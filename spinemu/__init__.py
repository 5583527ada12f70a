"""spinemu: run, compile, trace and translate Parallax Propeller 1 Spin programs, and run BASIC Stamp 2 PBASIC.

The public API is listed in ``__all__``; see docs/api.md.
"""
from .diagnostics import SpinError
from .trace import PinTrace

__version__ = "0.1.0"

__all__ = ["SpinError", "PinTrace", "__version__"]
