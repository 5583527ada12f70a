"""Compiling one object (one .spin file) into its own bytes, before linking.

An object's bytes (Propeller Manual, "Memory Organization"; spinemu.image)::

    word size  byte methods+1  byte instances      (size: all of this, long-aligned)
    long per method:   word code offset, word local-variable bytes
    long per instance: word child offset, word VAR offset  (filled by the linker)
    DAT, then each method's code followed by its strings

The same file always compiles to the same bytes, so it is compiled once.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from ..diagnostics import Diagnostic
from .. import messages as msg
from ..frontend.ast import AddrOf, NameRef, ObjConst, key
from ..frontend.constants import Const, ConstError, NotConstant, Undefined, evaluate
from ..frontend.objects import child_constant
from .code import Span
from .dat import DatSymbol, assemble_dat
from .stmts import MethodCompiler
from .symbols import MethodSymbol, ObjectSymbols, ObjSymbol, layout_vars, method_order

__all__ = ["CompiledObject", "MethodInfo", "ObjectCompiler"]


@dataclass
class MethodInfo:
    """MethodInf: see the module docstring."""

    name: str
    index: int
    public: bool
    offset: int          # code offset in the object
    end: int             # offset after its code and strings
    locals_size: int
    nparams: int
    pos: object
    #: ``(name, frame offset, longs, "result" | "param" | "local")``, result first (debug info)
    slots: list = field(default_factory=list)


@dataclass
class CompiledObject:
    """An object's own bytes and what the linker, listing and translator need to know."""

    unit: object
    data: bytearray
    n_methods: int
    instances: list                  # [(ObjSymbol, child unit)] one per table entry
    var_size: int                    # own VAR bytes (long-aligned)
    symbols: ObjectSymbols
    methods: list                    # [MethodInfo] in table order
    spans: list                      # [Span] object-relative
    dat_start: int
    dat_symbols: dict = field(default_factory=dict)

    @property
    def size(self) -> int:
        return len(self.data)

    @property
    def child_table(self) -> int:
        """Offset of the first child entry in the table."""
        return 4 * (1 + self.n_methods)


def _frame_slots(method, frame: dict) -> list:
    """The named longs of ``method``'s frame (see MethodInfo.slots)."""
    slots = [(method.result or "result", 0, 1, "result")]
    first_local = 4 + 4 * len(method.params)
    for sym in sorted(frame.values(), key=lambda s: s.offset):
        if sym.offset:
            slots.append((sym.name, sym.offset, sym.count, "param" if sym.offset < first_local else "local"))
    return slots


class ObjectCompiler:
    """Compiles an ObjectUnit; errors go to ``errors`` (Diagnostics)."""

    def __init__(self, unit, errors: list, undefined: set):
        self.unit = unit
        self.errors = errors
        self.undefined = undefined
        self.source = unit.spin.source
        self.char_bytes = self.source.string_bytes
        self.symbols = ObjectSymbols(unit.constants)

    # ------------------------------------------------------------------ context for MethodCompiler
    def error(self, message: str, node, undefined: Optional[str] = None) -> None:
        if undefined is not None:
            k = (self.unit.path, key(undefined))
            if k in self.undefined:
                return
            self.undefined.add(k)
        pos = node.pos
        self.errors.append(Diagnostic(message, pos.path, pos.line, pos.col, self.source.line(pos.line)))

    def _stale_hints(self, stale: list) -> None:
        """A hint for each jump or address OpenSpin's sizing writes with a stale address (code.py)."""
        for pos, address, off in stale:
            if pos is None:
                continue
            what = "address" if address else "jump"
            where = "past its target" if off > 0 else "before its target"
            text = self.source.line(pos.line) or ""
            self.unit.hints.append(Diagnostic(msg.HINT_STALE_JUMP.format(
                what=what, off=abs(off), s="" if abs(off) == 1 else "s", where=where),
                pos.path, pos.line, pos.col, text, "warning"))

    def error_at(self, message: str, pos) -> None:
        self.errors.append(Diagnostic(message, pos.path, pos.line, pos.col, self.source.line(pos.line)))

    def const(self, name: str) -> Optional[Const]:
        return self.unit.constants.get(name)

    def resolve_const(self, node):
        """Constants for ``constant()`` and counts; a DAT label (with or without @) is its offset."""
        if isinstance(node, AddrOf) and isinstance(node.target, NameRef) and node.target.index is None:
            node = node.target
            if not isinstance(self.symbols.get(node.name), DatSymbol):
                return None
        if isinstance(node, NameRef) and node.index is None:
            c = self.const(node.name)
            if c is not None:
                return c
            sym = self.symbols.get(node.name)
            if sym is None:
                raise Undefined(node.name, node)
            if isinstance(sym, DatSymbol):
                return Const(sym.offset)
            return None
        if isinstance(node, ObjConst):
            return self.child_const(node)
        return None

    def child_const(self, node) -> Const:
        return child_constant(self.unit, node)

    def has_method(self, name: str) -> bool:
        return isinstance(self.symbols.get(name), MethodSymbol)

    def child_method(self, objsym: ObjSymbol, name: str):
        pubs = [m for m in objsym.unit.spin.methods if m.public]
        for i, m in enumerate(pubs):
            if key(m.name) == key(name):
                return i + 1, len(m.params)
        return None

    def count_of(self, node) -> int:
        try:
            c = evaluate(node, self.resolve_const, self.char_bytes)
        except NotConstant as exc:
            self.error(msg.NEEDS_CONSTANT, exc.node)
            return 1
        except ConstError as exc:
            self.error(exc.message, exc.node, getattr(exc, "name", None))
            return 1
        if c.is_float or c.signed < 0:
            self.error(msg.BAD_COUNT.format(low=0, high="$FFFF", value=c.signed), node)
            return 1
        return c.bits

    # ------------------------------------------------------------------ compile
    def compile(self) -> CompiledObject:
        spin = self.unit.spin
        syms = self.symbols
        report = lambda message, node: self.error(message, node)
        methods = method_order(spin.methods)
        if not methods or not methods[0].public:
            line, col = self.source.end_position()
            self.errors.append(Diagnostic(msg.NO_PUB, self.source.path, line, col, self.source.line(line)))
        for i, m in enumerate(methods):
            sym = MethodSymbol(m.name, i + 1, m.public, m, len(m.params))
            if syms.add(m.name, sym, m, report):
                syms.methods.append(sym)
        instances = []
        index = len(methods) + 1
        crossing = None         # the OBJ line that takes the table past 255 entries (OpenSpin reports it)
        for decl, child in self.unit.children:
            count = 1 if decl.count is None else self.count_of(decl.count)
            if not 1 <= count <= 255:
                self.error(msg.OBJECT_COUNT, decl.count)
                count = 1
            osym = ObjSymbol(decl.name, index, count, child, decl)
            syms.add(decl.name, osym, decl, report)
            syms.objects.append(osym)
            for _ in range(count):
                instances.append((osym, child))
            index += count
            if crossing is None and len(methods) + len(instances) > 255:
                crossing = decl
        if len(methods) + len(instances) > 255:
            self.error(msg.TOO_MANY_METHODS, crossing or methods[-1])
        var_syms, var_size = layout_vars(spin.vars, self.count_of)
        if var_size > 0x8000:
            self.error(msg.TOO_MUCH_VAR, spin.vars[-1])
        for v in var_syms:
            syms.add(v.name, v, v, report)
        syms.vars, syms.var_size = var_syms, var_size
        table_size = 4 * (1 + len(methods) + len(instances))
        dat = assemble_dat(self.unit, table_size, self.const, self.child_const, report)
        for k, sym in dat.symbols.items():
            if k in syms.table:
                self.error(msg.DUPLICATE_SAME_LINE.format(name=sym.name), sym)
            else:
                syms.table[k] = sym
        spans = [Span(off, data, pos, note) for off, data, pos, note in dat.spans]
        offset = table_size + len(dat.data)
        infos = []
        code_bytes = bytearray()
        for sym in syms.methods:
            errors_before = len(self.errors)
            mc = MethodCompiler(self, sym.node)
            buf = mc.compile()
            if len(self.errors) > errors_before:
                mspans, end = [], offset        # no image is made anyway
            else:
                try:
                    mspans, end = buf.layout(offset)
                except ValueError:
                    self.error(msg.JUMP_TOO_FAR, sym.node)
                    mspans, end = [], offset
                self._stale_hints(buf.stale)
            infos.append(MethodInfo(sym.name, sym.index, sym.public, offset, end, mc.locals_size,
                                    sym.nparams, sym.node.pos, _frame_slots(sym.node, mc.frame)))
            for s in mspans:
                code_bytes += s.data
            spans.extend(mspans)
            offset = end
        size = (offset + 3) & ~3
        data = bytearray(size)
        # A word past $FFFF (an object or a frame over 64 KB) is already an error (here, or in the
        # memory check after linking); the table is made anyway, as the other errors are collected.
        data[0:2] = (size & 0xFFFF).to_bytes(2, "little")
        data[2] = (len(methods) + 1) & 0xFF
        data[3] = len(instances) & 0xFF
        for i, info in enumerate(infos):
            data[4 + 4 * i: 8 + 4 * i] = (info.offset & 0xFFFF).to_bytes(2, "little") + \
                (info.locals_size & 0xFFFF).to_bytes(2, "little")
        data[table_size:table_size + len(dat.data)] = dat.data
        data[table_size + len(dat.data):offset] = code_bytes
        spans.insert(0, Span(0, bytes(data[:table_size]), None, "object table"))
        if size > offset:
            spans.append(Span(offset, bytes(size - offset), None, "padding"))
        return CompiledObject(self.unit, data, len(methods), instances, var_size, syms, infos, spans,
                              table_size, dat.symbols)
