"""An object's symbols: constants, VAR, DAT labels, methods and child objects.

VAR layout (Propeller Manual, VAR; observed on OpenSpin): all longs in
declaration order, then all words, then all bytes; the block is rounded up
to a whole long.  Methods are numbered from 1, PUB methods first (in source
order), then PRI methods.  Child instances follow the methods in the object
table: ``OBJ a : "x"`` is entry ``methods + 1``, arrays take one entry per
element.  Names are case-insensitive and must be unique in an object.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from .. import messages as msg
from ..frontend.ast import key

__all__ = ["VarSymbol", "MethodSymbol", "ObjSymbol", "LocalSymbol", "ObjectSymbols"]


@dataclass
class VarSymbol:
    """A VAR variable: ``size`` of one element in bytes, ``offset`` from the object's VAR base."""

    name: str
    size: int
    offset: int
    count: int
    pos: object


@dataclass
class MethodSymbol:
    """MethodSymbo: see the module docstring."""

    name: str
    index: int            # 1-based method number
    public: bool
    node: object          # ast.Method
    nparams: int


@dataclass
class ObjSymbol:
    """An OBJ line: ``index`` is the object-table entry of its first instance."""

    name: str
    index: int
    count: int
    unit: object          # frontend ObjectUnit
    decl: object


@dataclass
class LocalSymbol:
    """``result`` (offset 0), a parameter or a local: ``offset`` from the frame base."""

    name: str
    offset: int
    count: int


@dataclass
class ObjectSymbols:
    """Lookup table of one object; ``get`` is case-insensitive."""

    consts: object                                   # frontend ConstantTable
    table: dict = field(default_factory=dict)        # key -> symbol (not constants)
    var_size: int = 0
    methods: list = field(default_factory=list)      # [MethodSymbol] in table order
    objects: list = field(default_factory=list)      # [ObjSymbol]
    vars: list = field(default_factory=list)         # [VarSymbol] in layout order

    def get(self, name: str):
        return self.table.get(key(name))

    def add(self, name: str, sym, node, report) -> bool:
        k = key(name)
        if k in self.table or self.consts.get(name) is not None:
            report(msg.DUPLICATE_SAME_LINE.format(name=name), node)
            return False
        self.table[k] = sym
        return True


def layout_vars(decls: list, count_of) -> tuple[list, int]:
    """``(symbols, size)`` for VAR declarations; ``count_of(expr)`` folds an array size."""
    syms = []
    offset = 0
    for size in (4, 2, 1):
        for d in decls:
            if d.size != size:
                continue
            count = 1 if d.count is None else count_of(d.count)
            syms.append(VarSymbol(d.name, size, offset, count, d.pos))
            offset += size * count
    return syms, (offset + 3) & ~3


def method_order(methods: list) -> list:
    """PUB methods first, then PRI, each in source order."""
    return [m for m in methods if m.public] + [m for m in methods if not m.public]


def frame_locals(method, count_of, check=None) -> tuple[dict, int]:
    """Frame symbols of ``method`` (result, parameters, locals) and the locals' size in bytes.

    ``check(name, pos, table)`` may refuse a name (it reports why).
    """
    table: dict = {}
    offset = 0
    if method.result is not None and key(method.result) != "result":
        if check is None or check(method.result, method.pos, table):
            table[key(method.result)] = LocalSymbol(method.result, 0, 1)
    offset = 4
    for name, pos in method.params:
        if check is None or check(name, pos, table):
            table[key(name)] = LocalSymbol(name, offset, 1)
        offset += 4
    start = offset
    for local in method.locals:
        count = 1 if local.count is None else count_of(local.count)
        if check is None or check(local.name, local.pos, table):
            table[key(local.name)] = LocalSymbol(local.name, offset, count)
        offset += 4 * count
    return table, offset - start


def find_first(methods: list) -> Optional[object]:
    for m in methods:
        if m.public:
            return m
    return None
