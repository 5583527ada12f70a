"""Which Spin source line made each byte of a compiled image (:class:`LineTable`).

Kept apart from the compiler so that a run of a program whose compiled form
was cached (spinemu.progcache) needs no compiler module.
"""
from __future__ import annotations

import bisect

__all__ = ["LineTable"]


class LineTable:
    """Hub address -> ``(path, line)`` of the Spin source that made the byte there.

    Call it with an address (``table(0x28)``) or use :meth:`get`;
    :meth:`position` adds the column of the statement.

    Args:
        entries: ``(start, end, path, line)`` or ``(start, end, path, line, col)``.
    """

    def __init__(self, entries):
        entries = sorted(entries)
        self._starts = [e[0] for e in entries]
        self._cols = [e[4] if len(e) > 4 else 1 for e in entries]
        self._entries = [tuple(e[:4]) for e in entries]

    def __call__(self, addr: int):
        i = bisect.bisect_right(self._starts, addr) - 1
        if i < 0:
            return None
        start, end, path, line = self._entries[i]
        return (path, line) if start <= addr < end else None

    get = __call__

    def position(self, addr: int):
        """``(path, line, col)`` of the statement that made the byte at ``addr``, or ``None``."""
        i = bisect.bisect_right(self._starts, addr) - 1
        if i < 0:
            return None
        start, end, path, line = self._entries[i]
        return (path, line, self._cols[i]) if start <= addr < end else None

    def __len__(self) -> int:
        return len(self._entries)

    def items(self, columns: bool = False):
        """``(start, end, path, line)`` ranges in address order (``columns``: with the column too)."""
        if columns:
            return [e + (col,) for e, col in zip(self._entries, self._cols)]
        return list(self._entries)
