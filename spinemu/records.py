"""Value classes for the modules every ``spinemu run`` imports, without :mod:`dataclasses`.

Importing :mod:`dataclasses` costs a run's start-up about 8 ms (it imports
:mod:`inspect`, and with it ``ast``, ``dis`` and ``tokenize``), and each class
it makes a little more; for a short run that is a tenth of its time.  The
classes a run needs (diagnostics, pin traces, the image header, the bytecode
table, run results, warnings, debug information) derive from :class:`Record`
instead: each writes its own ``__init__`` and names its fields in ``_fields``,
which give equality, ``repr`` and :meth:`Record.replace` as a dataclass would.
The compiler's and the translator's own classes stay dataclasses.

>>> class Point(Record):
...     _fields = ("x", "y")
...     def __init__(self, x, y=0):
...         self.x, self.y = x, y
>>> Point(1) == Point(1, 0), Point(1).replace(y=2)
(True, Point(x=1, y=2))
"""
from __future__ import annotations

__all__ = ["Record", "FrozenRecord"]


class Record:
    """A value with named fields: ``==`` compares them (same class only), ``repr`` shows them.

    Subclasses set ``_fields`` (the ``__init__`` parameters, in order) and, to
    leave some out of ``repr``, ``_repr_fields``.  Like a dataclass with
    ``eq=True``, a record is unhashable unless it is a :class:`FrozenRecord`.
    """

    __slots__ = ()
    _fields: tuple = ()
    _repr_fields: tuple | None = None

    def __eq__(self, other):
        if other.__class__ is not self.__class__:
            return NotImplemented
        return all(getattr(self, f) == getattr(other, f) for f in self._fields)

    __hash__ = None     # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = self._fields if self._repr_fields is None else self._repr_fields
        return f"{self.__class__.__qualname__}({', '.join(f'{f}={getattr(self, f)!r}' for f in shown)})"

    def replace(self, **changes):
        """A copy with some fields changed (as :func:`dataclasses.replace`)."""
        values = {f: getattr(self, f) for f in self._fields}
        values.update(changes)
        return self.__class__(**values)


class FrozenRecord(Record):
    """A :class:`Record` meant to stay as made: hashable by its fields (nothing stops a change)."""

    __slots__ = ()

    def __hash__(self) -> int:
        return hash(tuple(getattr(self, f) for f in self._fields))
