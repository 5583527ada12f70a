"""Method code as a list of items, sized the way OpenSpin sizes them, then turned into spans.

A method body is emitted as items: plain bytes, jumps to labels, pushes of a
label's object address (``case``/``lookup`` end addresses) and pushes of a
string's address (the method's string pool follows its code).  Each item
remembers the source position and a short note, so the same list gives the
binary, the listing and the line table (:class:`Span`).

Sizing follows what OpenSpin 1.00.81 does (observed with probe programs):

* each block statement (``if``, ``case``, ``repeat``) and ``lookup``/``lookdown``
  expression is compiled again and again until two compiles in a row give it
  the same size; each compile of a block compiles the blocks inside it afresh
  (the method body is one such block);
* a forward reference to a label of the block is sized with the label's
  address from the block's previous compile: a jump is short (1 byte,
  -64..63) when that address is in reach of its short form, an address push
  is ``PUSH_IMM1`` when that address is below 256; in the block's first
  compile the label is unknown and the reference is long (2-byte offset,
  ``PUSH_IMM2``); a backward jump is sized from its exact distance;
* a ``next``/``quit`` refers to a label of its loop, an enclosing block: it
  sees the address from the loop's previous compile (long in the loop's first
  compile) while the blocks around it, compiled afresh, start with their own
  jumps long.  So a ``next``/``quit`` that lands exactly 63 bytes past its
  long form can be short in a block's first compile (the jumps before it
  still long) and long in the next one (they shrank): when one byte of the
  block's own jumps shrinks in that compile, the block's size is unchanged
  and that compile is the last one -- its forward jumps keep the addresses of
  the compile before, so a jump to the start of the branch holding the
  ``next``/``quit`` points one byte past it (OpenSpin writes these offsets;
  spinemu writes the same bytes);
* the ``next`` of a loop with its test at the end (``repeat ... while``)
  refers, until the test is reached in the loop's first compile, to the top of
  the loop (OpenSpin sets it when it meets the ``while``/``until``), so there
  a ``next`` near the top is short in the first compile;
* the offset (or address) written is the one the reference was sized with,
  from the last compile of its block;
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

    ``start_as``: another label whose address references to this one use until
    this one is reached in a compile of its block (a loop with its test at the
    end: its ``next`` is the top of the loop until the test is reached).
    """

    __slots__ = ("name", "start_as")

    def __init__(self, name: str = "", start_as: Optional["Label"] = None):
        self.name = name
        self.start_as = start_as

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
_BYTES, _JUMP, _ADDR, _STR, _MARK, _BEGIN, _END = range(7)

#: a block that has not settled after this many compiles keeps its last one
_MAX_COMPILES = 64


class _Block:
    """A block of a method's items (``items[lo:hi]``, between its markers) and what its compiles gave."""

    __slots__ = ("lo", "hi", "parts", "own", "outer", "cache")

    def __init__(self, lo: int):
        self.lo = lo
        self.hi = lo
        self.parts: list = []       # item indexes and inner blocks, in order
        self.own: list = []         # labels marked in the block itself
        self.outer: tuple = ()      # labels of enclosing blocks referred to inside
        self.cache: dict = {}       # (start, outer addresses) -> what the compile gave


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
        #: after :meth:`layout`: references written with a stale address (see :meth:`_stale`)
        self.stale: list = []

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

    @contextmanager
    def block(self):
        """The items emitted inside form a block (a statement or expression OpenSpin compiles until it settles)."""
        self.items.append([_BEGIN, b"", self.pos, ""])
        try:
            yield
        finally:
            self.items.append([_END, b"", self.pos, ""])

    # -- sizing
    def _blocks(self) -> _Block:
        """The method body as a block, with the blocks inside it."""
        items = self.items
        root = _Block(0)
        stack = [root]
        owner: dict = {}
        refs: list = []             # (blocks around it, label) of every reference
        for i, item in enumerate(items):
            kind = item[0]
            if kind == _BEGIN:
                blk = _Block(i + 1)
                stack[-1].parts.append(blk)
                stack.append(blk)
                continue
            if kind == _END:
                blk = stack.pop()
                blk.hi = i
                continue
            stack[-1].parts.append(i)
            if kind == _MARK:
                stack[-1].own.append(item[4])
                owner[item[4]] = stack[-1]
            elif kind == _JUMP or kind == _ADDR:
                refs.append((tuple(stack), item[4]))
        root.hi = len(items)
        outer: dict = {}
        for path, label in refs:
            home = owner.get(label)
            for blk in reversed(path):
                if blk is home:
                    break
                outer.setdefault(id(blk), (blk, {}))[1][label] = None
                if label.start_as is not None:
                    outer[id(blk)][1][label.start_as] = None
        for blk, labels in outer.values():
            blk.outer = tuple(labels)
        return root

    def layout(self, start: int) -> tuple[list, int]:
        """Size every item for code starting at object offset ``start``.

        Returns:
            ``(spans, end)``: the spans of code and string pool, and the
            offset just past the pool.

        Raises:
            ValueError: a jump does not fit in 15 bits.
        """
        items = self.items
        at: dict = {}               # label -> its address in the latest compile that reached it
        used: list = [None] * len(items)    # per reference: the address it was sized with

        def compile_block(blk: _Block, begin: int) -> int:
            key = (begin,) + tuple(at.get(label) for label in blk.outer)
            known = blk.cache.get(key)
            if known is not None:
                end, sizes, addrs, marks = known
                for i, size, addr in zip(range(blk.lo, blk.hi), sizes, addrs):
                    if size is not None:
                        items[i][5] = size
                        used[i] = addr
                at.update(marks)
                return end
            for label in blk.own:
                at.pop(label, None)
            size = None
            for _ in range(_MAX_COMPILES):
                end = compile_parts(blk.parts, begin)
                if end - begin == size:
                    break
                size = end - begin
            span = range(blk.lo, blk.hi)
            blk.cache[key] = (end, [items[i][5] if items[i][0] in (_JUMP, _ADDR) else None for i in span],
                              [used[i] for i in span],
                              {items[i][4]: at[items[i][4]] for i in span if items[i][0] == _MARK})
            return end

        def compile_parts(parts: list, addr: int) -> int:
            for part in parts:
                if type(part) is _Block:
                    addr = compile_block(part, addr)
                    continue
                item = items[part]
                kind = item[0]
                if kind == _BYTES:
                    addr += len(item[1])
                elif kind == _MARK:
                    at[item[4]] = addr
                elif kind == _STR:
                    addr += 3
                else:
                    label = item[4]
                    target = at.get(label)
                    if target is None and label.start_as is not None:
                        target = at.get(label.start_as)
                    used[part] = target
                    if kind == _JUMP:
                        reach = target - (addr + len(item[1]) + 1) if target is not None else None
                        item[5] = 1 if reach is not None and -64 <= reach <= 63 else 2
                        addr += len(item[1]) + item[5]
                    else:
                        item[5] = 1 if target is not None and target < 0x100 else 2
                        addr += 1 + item[5]
            return addr

        end = compile_block(self._blocks(), start)
        self.stale = self._stale(start, used)
        return self._spans(start, used, end)

    def _stale(self, start: int, used: list) -> list:
        """``(pos, is an address push, bytes off)`` of every jump or address push written with an address
        its label no longer has (see "stale" in the module docstring): the image, like OpenSpin's, goes
        elsewhere."""
        actual = self.label_addresses(start)
        return [(item[2], item[0] == _ADDR, used[i] - actual[item[4]]) for i, item in enumerate(self.items)
                if (item[0] == _JUMP or item[0] == _ADDR) and used[i] != actual.get(item[4], used[i])]

    def label_offsets(self, start: int) -> dict:
        """``{label: object offset}`` of every marked label, for code laid out at ``start``."""
        self.layout(start)
        return self.label_addresses(start)

    def label_addresses(self, start: int) -> dict:
        """``{label: object offset}`` with the sizes the last :meth:`layout` gave."""
        at, addr = {}, start
        for item in self.items:
            kind = item[0]
            if kind == _MARK:
                at[item[4]] = addr
            elif kind == _BYTES:
                addr += len(item[1])
            elif kind == _STR:
                addr += 3
            elif kind == _JUMP or kind == _ADDR:    # as layout sized it
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

    def _spans(self, start: int, used: list, code_end: int) -> tuple[list, int]:
        spans = []
        addr = start
        order = sorted(range(len(self.strings)), key=lambda i: self._string_index[i])
        pool_offset, kept = self._pool(order, code_end)
        for i, item in enumerate(self.items):
            kind = item[0]
            if kind == _MARK or kind == _BEGIN or kind == _END:
                continue
            if kind == _BYTES:
                data = item[1]
            elif kind == _JUMP:
                size = item[5]
                offset = used[i] - (addr + len(item[1]) + size)
                data = item[1] + encode_signed(offset, force_long=(size == 2))
            elif kind == _ADDR:
                value = used[i]
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
