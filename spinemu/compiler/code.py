"""Method code as a list of items, sized the way OpenSpin sizes them, then turned into spans.

A method body is emitted as items: plain bytes, jumps to labels, pushes of a
label's object address (``case``/``lookup`` end addresses) and pushes of a
string's address (the method's string pool follows its code).  Each item
remembers the source position and a short note, so the same list gives the
binary, the listing and the line table (:class:`Span`).

Sizing follows what OpenSpin 1.00.81 does (observed with probe programs):

* every forward reference is first assumed long (a 2-byte jump offset, a
  2-byte ``PUSH_IMM2`` address);
* then the method is laid out again and again; a forward jump is short
  (1 byte, -64..63) when the distance measured to the target's address *of
  the previous pass* fits, an address push is ``PUSH_IMM1`` when that address
  is below 256; a backward jump is sized from its exact distance;
* this stops when a pass changes no size.  Sizes only ever shrink, so a
  forward jump that needs exactly 63 stays long -- except a ``next`` in
  ``repeat ... while/until``, measured from the end of its long form, which
  becomes short (see :class:`Label`).
* string addresses always use the 2-byte offset form (``87 80 xx``);
* the string pool is in source order (an ``other`` case block is compiled
  before the other blocks but its strings keep their place);
* in an assignment whose target has a string in it (``a[strsize(string("x"))]
  := ...``), the strings of the value get addresses but no place in the pool:
  OpenSpin allocates the target's strings, then the value's, then goes back
  to the target and allocates its strings again from where they started, so
  the strings that follow are written over the value's (those addresses then
  hold other text).  The same happens to the arguments of ``obj[i].m(...)``
  when ``i`` holds a string.  spinemu makes the same image.
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass
from typing import Optional

from ..bytecode import encode_signed

__all__ = ["Label", "CodeBuffer", "Span"]


class Label:
    """A place in a method's code (bound by :meth:`CodeBuffer.mark`).

    ``late``: forward jumps to it are sized from the end of their long form
    (OpenSpin does this for ``next`` in ``repeat ... while/until``: a jump of
    exactly 63 bytes there is short, elsewhere long).
    """

    __slots__ = ("name", "late")

    def __init__(self, name: str = "", late: bool = False):
        self.name = name
        self.late = late

    def __repr__(self) -> str:  # pragma: no cover - debugging aid
        return f"Label({self.name!r})"


@dataclass
class Span:
    """Bytes at an offset (object-relative until linked) with their source and a note."""

    offset: int
    data: bytes
    pos: object      # frontend Pos or None
    note: str


# item kinds
_BYTES, _JUMP, _ADDR, _STR, _MARK = range(5)


class CodeBuffer:
    """Collects a method's items; :meth:`layout` sizes them and returns spans."""

    def __init__(self):
        self.items: list = []
        self.pos = None
        self.strings: list[bytes] = []
        self._string_index: dict = {}
        #: per string: the rewinding contexts it is in, ((context, "target"|"value"), ...) outermost first
        self._paths: list = []
        self._path: list = []
        self._contexts = 0

    # -- emitting
    def emit(self, data, note: str = "") -> None:
        """Plain bytes (an int, a bytes object or a list of ints)."""
        if isinstance(data, int):
            data = bytes((data,))
        elif not isinstance(data, (bytes, bytearray)):
            data = bytes(data)
        self.items.append([_BYTES, bytes(data), self.pos, note])

    def jump(self, prefix: bytes, target: Label, note: str = "") -> None:
        """``prefix`` (opcode and maybe an operator byte) then a jump offset to ``target``."""
        self.items.append([_JUMP, bytes(prefix), self.pos, note, target, 2])

    def push_address(self, target: Label, note: str = "") -> None:
        """Push the object address of ``target`` (PUSH_IMM1 or PUSH_IMM2)."""
        self.items.append([_ADDR, b"", self.pos, note, target, 2])

    def push_string(self, data: bytes, note: str = "", where=None) -> None:
        """Push the address of a zero-terminated string kept in the method's pool.

        Args:
            where: the string's source position (orders the pool).
        """
        index = len(self.strings)
        self.strings.append(data + b"\0")
        self._string_index[index] = (where.line, where.col) if where is not None else (0, index)
        self._paths.append(tuple(self._path))
        self.items.append([_STR, b"", self.pos, note, index])

    def new_context(self) -> int:
        """A new rewinding context (an assignment whose target holds a string, ...): see :meth:`part`."""
        self._contexts += 1
        return self._contexts

    @contextmanager
    def part(self, context: int, role: str):
        """Strings pushed inside the block belong to ``context``'s ``"target"`` or ``"value"``.

        OpenSpin allocates a context's target strings, then its value strings, then
        allocates the target strings again from where they started: the value strings
        keep their addresses but the pool goes on from the end of the target strings.
        """
        self._path.append((context, role))
        try:
            yield
        finally:
            self._path.pop()

    def mark(self, label: Label) -> None:
        self.items.append([_MARK, b"", self.pos, "", label])

    # -- sizing
    def layout(self, start: int) -> tuple[list, int]:
        """Size every item for code starting at object offset ``start``.

        Returns:
            ``(spans, end)``: the spans of code and string pool, and the
            offset just past the pool.

        Raises:
            ValueError: a jump does not fit in 15 bits.
        """
        items = self.items
        prev: Optional[dict] = None
        while True:
            addr = start
            here: dict = {}
            changed = False
            for item in items:
                kind = item[0]
                if kind == _BYTES:
                    addr += len(item[1])
                elif kind == _MARK:
                    here[item[4]] = addr
                elif kind == _STR:
                    addr += 3
                elif kind == _JUMP:
                    target = item[4]
                    end_short = addr + len(item[1]) + 1
                    if target in here:
                        size = 1 if here[target] - end_short >= -64 else 2
                    elif prev is None:
                        size = 2
                    else:
                        size = 1 if -64 <= prev[target] - end_short - target.late <= 63 else 2
                    if size != item[5]:
                        changed = True
                        item[5] = size
                    addr += len(item[1]) + size
                else:  # _ADDR
                    if prev is None:
                        size = 2
                    else:
                        size = 1 if prev[item[4]] < 0x100 else 2
                    if size != item[5]:
                        changed = True
                        item[5] = size
                    addr += 1 + size
            if prev is not None and not changed:
                break
            prev = here
        return self._spans(start, here, addr)

    def label_offsets(self, start: int) -> dict:
        """``{label: object offset}`` of every marked label, for code laid out at ``start``."""
        self.layout(start)
        at, addr = {}, start
        for item in self.items:
            kind = item[0]
            if kind == _MARK:
                at[item[4]] = addr
            elif kind == _BYTES:
                addr += len(item[1])
            elif kind == _STR:
                addr += 3
            else:                           # a jump or an address push, as layout sized it
                addr += len(item[1]) + item[5] if kind == _JUMP else 1 + item[5]
        return at

    def _pool(self, order: list, at: int) -> tuple[dict, list]:
        """Each string's address, and the strings that stay in the pool (in order), for a pool at ``at``."""
        offsets: dict = {}
        kept = []
        resume: dict = {}
        prev: tuple = ()
        for i in order:
            path = self._paths[i]
            k = 0
            while k < min(len(prev), len(path)) and prev[k] == path[k]:
                k += 1
            for context, role in reversed(prev[k:]):
                if role == "value":
                    at = resume[context]
            for context, role in path[k:]:
                if role == "value":
                    resume[context] = at
            offsets[i] = at
            at += len(self.strings[i])
            if all(role != "value" for _, role in path):
                kept.append(i)
            prev = path
        return offsets, kept

    def _spans(self, start: int, labels: dict, code_end: int) -> tuple[list, int]:
        spans = []
        addr = start
        order = sorted(range(len(self.strings)), key=lambda i: self._string_index[i])
        pool_offset, kept = self._pool(order, code_end)
        for item in self.items:
            kind = item[0]
            if kind == _MARK:
                continue
            if kind == _BYTES:
                data = item[1]
            elif kind == _JUMP:
                size = item[5]
                offset = labels[item[4]] - (addr + len(item[1]) + size)
                data = item[1] + encode_signed(offset, force_long=(size == 2))
            elif kind == _ADDR:
                value = labels[item[4]]
                data = bytes((0x38, value)) if item[5] == 1 else bytes((0x39, value >> 8, value & 0xFF))
            else:  # _STR
                value = pool_offset[item[4]]
                data = bytes((0x87, 0x80 | (value >> 8), value & 0xFF))
            if data:
                spans.append(Span(addr, data, item[2], item[3]))
            addr += len(data)
        for i in kept:
            s = self.strings[i]
            spans.append(Span(addr, s, None, "string"))
            addr += len(s)
        return spans, addr
