"""Debug information: what the compiler knows about an image that the image does not say.

The tools that look into a running chip (runtime warnings, the debugger, the
profiler, the test harness) need names and places: which method a hub
address belongs to, each method's result, parameters and locals by frame
offset, each object instance's VAR and DAT by name, and the Spin file, line
and column of every bytecode.  :class:`DebugInfo` holds exactly that, as
plain data; :meth:`spinemu.compiler.CompiledProgram.debug_info` builds it
(without changing a byte of the image) and the chip and the tools read it.

A Spin frame (Propeller Manual v1.2, "Memory Organization"; spinemu.chip.spin)
is laid out from ``dbase``: the result long at ``+0``, the parameters at
``+4, +8, ...``, then the locals; the call's return information sits in the
eight bytes below ``dbase`` (``-2`` return address, ``-4`` caller's dbase,
``-6`` caller's vbase, ``-8`` caller's pbase with the frame flags).

This module is a shared leaf: it imports nothing from the project.

>>> m = MethodDebug("pause", False, 2, "demo.spin", 0x40, 0x58, 70,
...                 [FrameSlot("result", 0, 1, "result"), FrameSlot("ms", 4, 1, "param"),
...                  FrameSlot("c", 8, 1, "local")])
>>> m.nparams, m.slot_at(8).name
(1, 'c')
"""
from __future__ import annotations

import bisect
from collections.abc import Iterator

from .records import FrozenRecord, Record

__all__ = ["FrameSlot", "MethodDebug", "Variable", "ObjectDebug", "Instance", "DebugInfo"]


class FrameSlot(FrozenRecord):
    """One named long (or array of longs) in a method's frame.

    Attributes:
        name: as written in the source (``result`` or the result's own name).
        offset: bytes from the frame base (``dbase``).
        count: longs (1, or the array's length).
        kind: ``"result"``, ``"param"`` or ``"local"``.
    """

    _fields = ("name", "offset", "count", "kind")

    def __init__(self, name: str, offset: int, count: int, kind: str):
        self.name, self.offset, self.count, self.kind = name, offset, count, kind


class MethodDebug(Record):
    """A method of an object, placed in hub RAM.

    Attributes:
        name, public, index: as in the source; ``index`` is its 1-based number
            in the object's method table.
        path: the source file.
        start, end: hub addresses of its first bytecode and just past its code
            and string pool.
        line: the line of its ``PUB``/``PRI``.
        slots: the frame's named longs, result first.
    """

    _fields = ("name", "public", "index", "path", "start", "end", "line", "slots")

    def __init__(self, name: str, public: bool, index: int, path: str, start: int, end: int, line: int,
                 slots: list | None = None):
        self.name, self.public, self.index, self.path = name, public, index, path
        self.start, self.end, self.line = start, end, line
        self.slots = [] if slots is None else slots

    @property
    def nparams(self) -> int:
        return sum(1 for s in self.slots if s.kind == "param")

    @property
    def params(self) -> list:
        return [s for s in self.slots if s.kind == "param"]

    @property
    def locals(self) -> list:
        return [s for s in self.slots if s.kind == "local"]

    @property
    def first_local(self) -> int:
        """Frame offset of the first local (past the result and the parameters)."""
        return 4 + 4 * self.nparams

    def slot_at(self, offset: int) -> FrameSlot | None:
        """The named slot covering frame offset ``offset`` (bytes), if any."""
        for s in self.slots:
            if s.offset <= offset < s.offset + 4 * s.count:
                return s
        return None


class Variable(FrozenRecord):
    """A VAR variable or a DAT label of one object instance.

    Attributes:
        name: as written in the source.
        section: ``"VAR"`` or ``"DAT"``.
        addr: hub address of its first element.
        size: bytes per element (1, 2 or 4).
        count: elements (for a DAT label: up to the next label).
    """

    _fields = ("name", "section", "addr", "size", "count")

    def __init__(self, name: str, section: str, addr: int, size: int, count: int):
        self.name, self.section, self.addr, self.size, self.count = name, section, addr, size, count

    @property
    def end(self) -> int:
        return self.addr + self.size * self.count

    def describe(self) -> str:
        """``long stack[64]`` style."""
        kind = {1: "byte", 2: "word", 4: "long"}.get(self.size, "long")
        return f"{kind} {self.name}" + (f"[{self.count}]" if self.count != 1 else "")


class ObjectDebug(Record):
    """One compiled object (a .spin file), placed once at ``base`` however many instances use it."""

    _fields = ("path", "base", "size", "methods", "dat", "table_size", "code_start")
    _repr_fields = ("path", "base", "size", "table_size", "code_start")

    def __init__(self, path: str, base: int, size: int, methods: list | None = None,
                 dat: list | None = None, table_size: int = 4, code_start: int = 0):
        self.path, self.base, self.size = path, base, size
        self.methods = [] if methods is None else methods   # [MethodDebug] in table order
        self.dat = [] if dat is None else dat               # [Variable] with absolute addresses
        self.table_size = table_size                        # bytes of its method and object table
        self.code_start = code_start                        # hub address of its first method's code


class Instance(Record):
    """One instance of an object: the top object, or a child named by an OBJ line.

    Attributes:
        name: the dotted OBJ path from the top (``""`` for the top, ``"motor"``,
            ``"motor.uart"``; arrays as ``"leds[1]"``).
        obj: the :class:`ObjectDebug`.
        vbase: hub address of this instance's VAR block.
        var: its VAR variables (absolute addresses).
        children: one Instance per object-table entry.
    """

    _fields = ("name", "obj", "vbase", "var", "children")
    _repr_fields = ("name", "obj", "vbase")

    def __init__(self, name: str, obj: ObjectDebug, vbase: int, var: list | None = None,
                 children: list | None = None):
        self.name, self.obj, self.vbase = name, obj, vbase
        self.var = [] if var is None else var
        self.children = [] if children is None else children

    def variables(self) -> list:
        """VAR then DAT, as :class:`Variable` records."""
        return list(self.var) + list(self.obj.dat)

    def find(self, name: str) -> Variable | None:
        low = name.lower()
        for v in self.variables():
            if v.name.lower() == low:
                return v
        return None

    def label(self) -> str:
        base = self.obj.path.replace("\\", "/").rsplit("/", 1)[-1]
        return f"{self.name} ({base})" if self.name else base


class DebugInfo:
    """Names and places of one compiled program (see the module docstring).

    Args:
        top: the top object's :class:`Instance` (with its children).
        objects: every :class:`ObjectDebug` in placement order.
        positions: ``(start, end, path, line, col)`` ranges of hub addresses
            in address order.
        sources: ``path -> list of source lines`` (for messages and listings).
    """

    def __init__(self, top: Instance, objects: list, positions: list, sources: dict):
        self.top = top
        self.objects = objects
        self._positions = sorted(positions)
        self._starts = [p[0] for p in self._positions]
        self.sources = sources
        self.methods = sorted((m for o in objects for m in o.methods), key=lambda m: m.start)
        self._method_starts = [m.start for m in self.methods]
        self._by_vbase: dict = {}
        for inst in self.instances():
            self._by_vbase.setdefault((inst.obj.base, inst.vbase), inst)
        vars_ = sorted(((v.addr, v.end, v.name, inst, v) for inst in self.instances() for v in inst.var),
                       key=lambda e: (e[0], -e[1]))
        dats = {}
        for inst in self.instances():
            for v in inst.obj.dat:
                dats.setdefault((v.addr, v.name), (v.addr, v.end, v.name, inst, v))
        self._areas = sorted(vars_ + list(dats.values()), key=lambda e: (e[0], -e[1]))
        self._area_starts = [a[0] for a in self._areas]

    # ------------------------------------------------------------------ places
    def position(self, addr: int) -> tuple | None:
        """``(path, line, col)`` of the Spin source that made the byte at ``addr``."""
        i = bisect.bisect_right(self._starts, addr) - 1
        if i < 0:
            return None
        start, end, path, line, col = self._positions[i]
        return (path, line, col) if start <= addr < end else None

    def source_line(self, path: str, line: int) -> str | None:
        lines = self.sources.get(path)
        if lines is None or not 1 <= line <= len(lines):
            return None
        return lines[line - 1]

    def line_starts(self) -> Iterator[tuple]:
        """``(hub address, path, line)`` where each run of bytes of one source line starts."""
        last = None
        for start, _end, path, line, _col in self._positions:
            if (path, line) != last:
                yield start, path, line
                last = (path, line)

    # ------------------------------------------------------------------ code
    def method_at(self, addr: int) -> MethodDebug | None:
        """The method whose code (or string pool) holds hub address ``addr``."""
        i = bisect.bisect_right(self._method_starts, addr) - 1
        if i < 0:
            return None
        m = self.methods[i]
        return m if addr < m.end else None

    def object_at(self, addr: int) -> ObjectDebug | None:
        for o in self.objects:
            if o.base <= addr < o.base + o.size:
                return o
        return None

    def code_ranges(self) -> list:
        """``(start, end)`` hub ranges holding object tables, method code and strings (not DAT)."""
        out = []
        for o in self.objects:
            out.append((o.base, o.base + o.table_size))
            out.append((o.code_start, o.base + o.size))
        return [(a, b) for a, b in out if b > a]

    # ------------------------------------------------------------------ data
    def instances(self) -> Iterator[Instance]:
        """Every instance, depth first from the top."""
        stack = [self.top]
        while stack:
            inst = stack.pop(0)
            yield inst
            stack[0:0] = inst.children

    def instance(self, pbase: int, vbase: int) -> Instance | None:
        """The instance a frame with these ``pbase`` and ``vbase`` belongs to."""
        return self._by_vbase.get((pbase, vbase))

    def instance_named(self, name: str) -> Instance | None:
        low = name.lower()
        for inst in self.instances():
            if inst.name.lower() == low:
                return inst
        return None

    def variable_at(self, addr: int) -> tuple | None:
        """``(Instance, Variable)`` of the VAR variable or DAT label whose bytes hold ``addr``.

        The innermost (smallest) one when several contain it.
        """
        i = bisect.bisect_right(self._area_starts, addr) - 1
        best = None
        while i >= 0:
            start, end, _name, inst, v = self._areas[i]
            if start <= addr < end and (best is None or end - start < best[1].end - best[1].addr):
                best = (inst, v)
            if start < addr - 0x8000:
                break
            i -= 1
        return best

    def find_variable(self, dotted: str, context: Instance | None = None) -> tuple | None:
        """``(Instance, Variable)`` for ``name`` or ``obj.name`` / ``obj.sub.name``.

        A plain name is looked up in ``context`` (default: the top object),
        then in the top object.
        """
        if "." in dotted:
            inst_name, _, name = dotted.rpartition(".")
            inst = self.instance_named(inst_name)
            if inst is None:
                return None
            v = inst.find(name)
            return (inst, v) if v is not None else None
        for inst in ([context] if context is not None else []) + [self.top]:
            v = inst.find(dotted)
            if v is not None:
                return inst, v
        return None
