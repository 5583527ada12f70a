"""The Spin debugger: step cogs by line or bytecode, breakpoints, call stacks and variables by name.

:class:`~spinemu.debugger.session.Debugger` is the Python API; ``spinemu debug
PROG`` (:mod:`spinemu.debugger.commands`) is a small command loop on top of it.
:mod:`spinemu.debugger.frames` reads a cog's call stack from hub RAM.
"""
from __future__ import annotations

__all__ = ["Debugger", "Breakpoint", "Stop"]


def __getattr__(name):
    if name in __all__:
        from . import session
        return getattr(session, name)
    raise AttributeError(name)
