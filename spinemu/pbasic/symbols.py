"""Names, RAM allocation, constants and the EEPROM DATA image of a program.

Follows Parallax's tokenizer as observed (tests/data/pbasic/tokenizer_facts.json):

* one case-insensitive name space for labels, constants, variables and pins;
  predefined names (``INS``, ``OUTB``, ``B3``, ``CR``...) cannot be redefined;
* variables are allocated words first, then bytes, nibbles and bits, each
  group in declaration order, packed upward from ``W0`` (RAM byte 6); bits
  start at the nibble boundary after the last nibble (``n VAR Nib : b VAR
  Bit`` puts ``b`` at ``B0.BIT4``); aliases take no storage;
* modifiers (``.HIGHBYTE``, ``.NIB2``, ``.BIT9``) may be chained from larger
  to smaller; a modifier as large as the variable is error 139, an index
  past the variable error 140;
* ``CON`` values are 16-bit, evaluated left to right, forward references
  allowed; a division by zero is error 113;
* ``DATA`` is laid out from address 0 in source order; ``@n`` moves the
  pointer, ``Word`` stores low byte first, ``v(n)`` repeats, ``(n)`` reserves
  undefined bytes; a DATA label is the address of its first item (after an
  initial ``@``); writing a location twice is error 115, past 2047 error 114.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional

from ..diagnostics import CompileError, split_lines
from . import messages as M
from . import nodes as N
from .exprs import eval_const
from .words import MODIFIERS, PREDEFINED_CONSTANTS, RESERVED, predefined_variables

__all__ = ["Var", "Symbol", "SymbolTable", "RAM_BITS", "USER_RAM_START"]

RAM_BITS = 256            # 32 bytes
USER_RAM_START = 48       # W0 = RAM byte 6
_SIZES = {"BIT": 1, "NIB": 4, "BYTE": 8, "WORD": 16}


@dataclass(frozen=True)
class Var:
    """A view of RAM: ``width`` bits at ``bitoff``; ``count`` elements if an array."""

    bitoff: int
    width: int
    count: int = 1

    def modified(self, mods, error: Callable) -> "Var":
        """Apply modifiers like ``.HIGHBYTE.BIT2``; ``error(msg, pos)`` raises."""
        v = self
        for name, pos in mods:
            spec = MODIFIERS.get(name.upper())
            if spec is None:
                raise error(M.MODIFIER_UNKNOWN, pos)
            size, idx = spec
            if size >= v.width:
                raise error(M.MODIFIER_TOO_BIG, pos)
            parts = v.width // size
            if idx is None:
                idx = parts - 1
            if idx >= parts:
                raise error(M.MODIFIER_RANGE, pos)
            v = Var(v.bitoff + idx * size, size)
        return v


@dataclass
class Symbol:
    """One user or predefined name."""

    name: str
    kind: str                 # "const", "var", "pin", "label", "data"
    pos: Optional[N.Pos] = None
    value: Optional[int] = None
    var: Optional[Var] = None
    decl: Optional[N.Stmt] = None
    type_name: str = ""       # Bit/Nib/Byte/Word for declared variables


@dataclass
class SymbolTable:
    path: str
    source: str
    symbols: dict = field(default_factory=dict)       # UPPER -> Symbol
    var_order: list = field(default_factory=list)     # user variables, declaration order
    eeprom: bytearray = field(default_factory=lambda: bytearray(2048))
    defined: bytearray = field(default_factory=lambda: bytearray(2048))
    reserved_bytes: bytearray = field(default_factory=lambda: bytearray(2048))
    counts: dict = field(default_factory=lambda: {"words": 0, "bytes": 0, "nibbles": 0, "bits": 0})
    _data_guess: dict = field(default_factory=dict)

    # ------------------------------------------------------------ errors
    def error(self, message: str, pos: Optional[N.Pos]) -> CompileError:
        lines = split_lines(self.source)
        line = pos.line if pos else None
        src = lines[line - 1] if line and 0 < line <= len(lines) else None
        return CompileError(message, path=self.path, line=line,
                            column=pos.column if pos else None, source_line=src,
                            length=pos.length if pos else 1)

    # ------------------------------------------------------------ building
    def build(self, items: list) -> None:
        """Declare everything, then allocate RAM, resolve constants, lay out DATA."""
        for name, (off, width) in predefined_variables().items():
            self.symbols[name] = Symbol(name, "var", var=Var(off, width))
        for name, value in PREDEFINED_CONSTANTS.items():
            self.symbols[name] = Symbol(name, "const", value=value)
        decls = [it for it in items if isinstance(it, N.Stmt) and it.kind.startswith("decl_")]
        for it in items:
            if isinstance(it, N.Label):
                self._declare(it.name, "label", it.pos, None, label=True)
        for d in decls:
            name_tok = d.args[0]
            if name_tok is None:          # DATA without a label
                continue
            kind = {"decl_var": "var", "decl_alias": "var", "decl_con": "const",
                    "decl_pin": "pin", "decl_data": "data"}[d.kind]
            self._declare(str(name_tok), kind, _tok_pos(name_tok), d)
        self._allocate(decls)
        self._layout_data(decls)
        for d in decls:
            if d.kind == "decl_con":
                self.const_value(str(d.args[0]))
            elif d.kind == "decl_pin":
                self.const_value(str(d.args[0]))

    def _declare(self, name: str, kind: str, pos: N.Pos, decl, label: bool = False) -> None:
        key = name.upper()
        if key in RESERVED:
            raise self.error(M.RESERVED_NAME.format(name), pos)
        if key in self.symbols:
            old = self.symbols[key]
            msg = M.DUPLICATE_LABEL if label and old.kind == "label" else M.DUPLICATE.format(name)
            raise self.error(msg, pos)
        self.symbols[key] = Symbol(name, kind, pos, decl=decl)

    # ------------------------------------------------------------ RAM
    def _allocate(self, decls: list) -> None:
        groups = {16: [], 8: [], 4: [], 1: []}
        for d in decls:
            if d.kind == "decl_var":
                name, vtype, size_expr = d.args
                width = _SIZES[str(vtype).upper()]
                count = 1
                if size_expr is not None:
                    count = self.const_expr(size_expr)
                    if not 1 <= count <= RAM_BITS // width:
                        msg = M.ARRAY_SIZE_ZERO if count == 0 else M.ARRAY_SIZE.format(208 // width)
                        raise self.error(msg, _expr_pos(size_expr))
                groups[width].append((d, width, count))
        off = USER_RAM_START
        names = {16: "words", 8: "bytes", 4: "nibbles", 1: "bits"}
        for width in (16, 8, 4, 1):
            for d, w, count in groups[width]:
                # groups start aligned to their own size (a no-op after larger sizes)
                off = -(-off // w) * w
                if off + w * count > RAM_BITS:
                    raise self.error(M.OUT_OF_VARIABLE_SPACE.format(
                        str(d.args[0]), off + w * count - RAM_BITS), _tok_pos(d.args[0]))
                sym = self.symbols[str(d.args[0]).upper()]
                sym.var = Var(off, w, count)
                sym.type_name = str(d.args[1]).capitalize()
                self.var_order.append(sym)
                self.counts[names[width]] += count
                off += w * count
        for d in decls:
            if d.kind == "decl_alias":
                self._resolve_alias(self.symbols[str(d.args[0]).upper()], set())

    def _resolve_alias(self, sym: Symbol, seen: set) -> Var:
        if sym.var is not None:
            return sym.var
        if sym.name.upper() in seen:
            raise self.error(M.UNDEFINED.format(sym.name), sym.pos)
        seen.add(sym.name.upper())
        ref: N.Ref = sym.decl.args[1]
        if ref.index is not None:
            raise self.error(M.ALIAS_INDEX, _expr_pos(ref.index))
        target = self.symbols.get(ref.key)
        if target is None:
            raise self.error(M.UNDEFINED.format(ref.name), ref.pos)
        if target.kind == "pin":
            base = Var(self.const_value(ref.name), 1)      # alias of a PIN: its OUT/IN bit
        elif target.kind != "var":
            raise self.error(M.EXPECTED_VARIABLE, ref.pos)
        else:
            base = self._resolve_alias(target, seen)
        sym.var = base.modified(ref.mods, self.error)
        sym.type_name = "alias"
        self.var_order.append(sym)
        return sym.var

    # ------------------------------------------------------------ constants
    def const_value(self, name: str, _stack: Optional[set] = None) -> int:
        """The value of a constant-like name (CON, PIN, DATA label, predefined)."""
        sym = self.symbols.get(name.upper())
        if sym is None:
            raise KeyError(name)
        if sym.value is not None:
            return sym.value
        if sym.kind == "data":
            raise KeyError(name)        # not laid out yet
        if sym.kind not in ("const", "pin"):
            raise KeyError(name)
        stack = _stack or set()
        if sym.name.upper() in stack:
            raise self.error(M.UNDEFINED.format(sym.name), sym.pos)
        stack.add(sym.name.upper())
        value = self.const_expr(sym.decl.args[1], stack)
        if sym.kind == "pin" and value > 15:
            raise self.error(M.PIN_RANGE, _expr_pos(sym.decl.args[1]))
        sym.value = value
        return value

    def const_expr(self, e, _stack: Optional[set] = None) -> int:
        def lookup(name: str) -> int:
            sym = self.symbols.get(name.upper())
            if sym is None:
                raise self.error(M.UNDEFINED.format(name), _find_ref(e, name))
            if sym.kind in ("var", "label"):
                raise self.error(M.EXPECTED_CONSTANT, _find_ref(e, name))
            if sym.kind == "data" and sym.value is None:
                return self._data_guess.get(name.upper(), 0)
            return self.const_value(name, set(_stack or ()))

        def on_error(msg, pos):
            return self.error(msg, pos)
        return eval_const(e, lookup, path=self.path, on_error=on_error)

    # ------------------------------------------------------------ DATA
    def _layout_data(self, decls: list) -> None:
        datas = [d for d in decls if d.kind == "decl_data"]
        self._data_guess = {}
        for _ in range(6):              # labels may be used before they are placed
            guess = self._place(datas, emit=False)
            if guess == self._data_guess:
                break
            self._data_guess = guess
        self._place(datas, emit=True)
        for d in datas:
            if d.args[0] is not None:
                key = str(d.args[0]).upper()
                self.symbols[key].value = self._data_guess[key]

    def _place(self, datas: list, emit: bool) -> dict:
        labels = {}
        ptr = 0
        for d in datas:
            items = [it for it in d.args[1:] if it is not None]
            if d.args[0] is not None:
                first_at = items and items[0].kind == "data_at"
                if first_at:
                    ptr = self._const_item(items[0].args[0], emit)
                labels[str(d.args[0]).upper()] = ptr
            for it in items:
                if it.kind == "data_at":
                    ptr = self._const_item(it.args[0], emit)
                    if emit and ptr > 2047:
                        raise self.error(M.LOCATION_RANGE, _expr_pos(it.args[0]))
                    continue
                word = it.args[0] is not None
                if it.kind == "data_reserve":
                    n = self._const_item(it.args[1], emit) * (2 if word else 1)
                    for _ in range(n):
                        ptr = self._store(ptr, None, it.args[1], emit)
                    continue
                value_expr, rep_expr = it.args[1], it.args[2]
                reps = 1 if rep_expr is None else self._const_item(rep_expr, emit)
                if isinstance(value_expr, N.Str) and not word and len(value_expr.text) != 1 \
                        and rep_expr is None:
                    values = [ord(ch) & 0xFF for ch in value_expr.text]
                    for v in values:
                        ptr = self._store(ptr, v, value_expr, emit)
                    continue
                value = self._const_item(value_expr, emit) if emit else 0
                for _ in range(reps):
                    if word:
                        ptr = self._store(ptr, value & 0xFF, value_expr, emit)
                        ptr = self._store(ptr, value >> 8, value_expr, emit)
                    else:
                        ptr = self._store(ptr, value & 0xFF, value_expr, emit)
        return labels

    def _const_item(self, e, emit: bool) -> int:
        try:
            return self.const_expr(e)
        except CompileError:
            if emit:
                raise
            return 0

    def _store(self, addr: int, value: Optional[int], expr, emit: bool) -> int:
        if emit:
            if addr > 2047:
                raise self.error(M.LOCATION_RANGE, _expr_pos(expr))
            if self.defined[addr] or self.reserved_bytes[addr]:
                raise self.error(M.LOCATION_USED, _expr_pos(expr))
            if value is None:
                self.reserved_bytes[addr] = 1
            else:
                self.eeprom[addr] = value
                self.defined[addr] = 1
        return addr + 1

    # ------------------------------------------------------------ lookups
    def lookup(self, name: str) -> Optional[Symbol]:
        return self.symbols.get(name.upper())

    def variables(self) -> list[tuple[str, Var, str]]:
        """User variables in declaration order: (name, view, type)."""
        return [(s.name, s.var, s.type_name) for s in self.var_order]


def _tok_pos(tok) -> N.Pos:
    return N.Pos(tok.line, tok.column, max(1, len(str(tok))))


def _expr_pos(e) -> N.Pos:
    from .exprs import leftmost_leaf
    return leftmost_leaf(e).pos


def _find_ref(e, name: str) -> N.Pos:
    """Position of the first reference to ``name`` inside ``e``."""
    stack = [e]
    while stack:
        x = stack.pop()
        if isinstance(x, N.Ref) and x.name.upper() == name.upper():
            return x.pos
        for attr in ("left", "right", "operand", "index"):
            sub = getattr(x, attr, None)
            if sub is not None:
                stack.append(sub)
    return _expr_pos(e)
