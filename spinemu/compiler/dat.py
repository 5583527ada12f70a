"""The DAT section: data and PASM, laid out in the object as OpenSpin lays them out.

Two passes: the first places every line (so labels are known), the second
computes values.  Layout rules (Propeller Manual, DAT; observed on OpenSpin
1.00.81):

* ``byte``/``word``/``long`` data is aligned to its size (zero padding);
  inside a line, size overrides (``byte 1, word 2``) are not aligned, hold
  for the rest of the line (``byte 1, word 2, 3`` stores 3 as a word) and
  may not be smaller than the line's size; values are cut to the item size;
  floats only fit ``long`` items;
* an instruction is one aligned long;
* a label takes the address and size of its line's data; a label alone on a
  line takes the current (unaligned) address and the size of the previous
  directive (byte at the start);
* in expressions a label means its cog address (longs from the last
  ``org``); ``@label`` its offset in the object; ``$`` the current cog address;
* ``res n`` reserves cog longs without hub bytes; ``fit n`` checks the cog
  address against ``n`` (default $1F0); ``org``, ``res`` and ``fit`` align
  to a long; ``file "x"`` includes a binary file, looked up as OBJ files are
  (the object's folder, ``-L``, ``SPINEMU_PATH``, installed libraries; any
  letter case with a warning);
* ``:name`` labels are local to the previous plain label.
"""
from __future__ import annotations

import os
import zlib
from dataclasses import dataclass
from typing import Optional

from .. import messages as msg
from ..bytecode import REGISTER_NAMES
from ..frontend.ast import (
    AddrOf, Data, DatFile, Fit, Here, Instruction, LocalLabel, NameRef, ObjConst, Org, RegRef, Res, Str,
    key,
)
from ..diagnostics import Diagnostic
from ..frontend.constants import Const, ConstError, NotConstant, evaluate, to_signed
from ..frontend.objects import not_found_message
from ..frontend.search import AmbiguousName
from ..image import HUB_SIZE as HUB_BYTES

__all__ = ["DatSymbol", "DatResult", "assemble_dat"]


@dataclass
class DatSymbol:
    """A DAT label: ``offset`` in the object (bytes), ``cog`` address (longs), item size."""

    name: str
    size: int
    offset: int
    cog: int
    reserved: bool
    pos: object


@dataclass
class DatResult:
    """DatResul: see the module docstring."""

    data: bytes
    symbols: dict        # key -> DatSymbol (plain labels)
    locals: dict         # (plain key, local key) -> DatSymbol
    spans: list          # [(offset, bytes, pos, note)]


#: register name (lower case) -> cog address, for PASM operands
REGISTER_ADDRESSES = {name.lower(): addr for addr, name in REGISTER_NAMES.items()}


class _Abort(Exception):
    pass


class _Assembler:
    def __init__(self, unit, start: int, const_lookup, child_const, report):
        self.unit = unit
        self.start = start
        self.const_lookup = const_lookup
        self.child_const = child_const
        self.report = report
        self.symbols: dict = {}
        self.locals: dict = {}
        self.char_bytes = unit.spin.source.string_bytes
        self.file_cache: dict = {}

    # ------------------------------------------------------------------ values
    def value(self, node, cog_here: int, scope: Optional[str], final: bool) -> Const:
        def resolve(n):
            if isinstance(n, NameRef) and n.index is None:
                c = self.const_lookup(n.name)
                if c is not None:
                    return c
                sym = self.symbols.get(key(n.name))
                if sym is not None:
                    return Const(sym.cog & 0xFFFFFFFF)
                if final:
                    raise ConstError(msg.UNDEFINED.format(name=n.name), n)
                raise NotConstant(n)
            if isinstance(n, LocalLabel):
                sym = self.locals.get((scope, key(n.name)))
                if sym is not None:
                    return Const(sym.cog)
                if final:
                    raise ConstError(msg.UNDEFINED.format(name=":" + n.name), n)
                raise NotConstant(n)
            if isinstance(n, Here):
                return Const(cog_here & 0xFFFFFFFF)
            if isinstance(n, AddrOf) and isinstance(n.target, NameRef) and n.target.index is None:
                sym = self.symbols.get(key(n.target.name))
                if sym is not None:
                    return Const(sym.offset)
                if final:
                    raise ConstError(msg.UNDEFINED.format(name=n.target.name), n.target)
                raise NotConstant(n)
            if isinstance(n, ObjConst):
                return self.child_const(n)
            if isinstance(n, RegRef) and n.bit is None:
                return Const(REGISTER_ADDRESSES[n.name])
            raise NotConstant(n)
        return evaluate(node, resolve, self.char_bytes)

    def const_now(self, node, cog_here, scope) -> int:
        """A value needed in the first pass (counts, org, res): constants only."""
        try:
            v = self.value(node, cog_here, scope, final=True)
        except NotConstant as exc:
            self.report(msg.NEEDS_CONSTANT, exc.node)
            raise _Abort() from None
        except ConstError as exc:
            self.report(exc.message, exc.node)
            raise _Abort() from None
        if v.is_float:
            self.report(msg.FLOAT_NOT_ALLOWED, node)
            raise _Abort()
        return v.bits

    # ------------------------------------------------------------------ passes
    def run(self, lines) -> DatResult:
        self.final = False
        self.walk(lines, emit=False)
        self.final = True
        out = bytearray()
        spans: list = []
        self.walk(lines, emit=True, out=out, spans=spans)
        return DatResult(bytes(out), self.symbols, self.locals, spans)

    def walk(self, lines, emit: bool, out=None, spans=None) -> None:
        hub = self.start           # object offset
        org_hub, org_cog = self.start, 0   # cog address = org_cog + (hub - org_hub) // 4
        res_extra = 0              # longs reserved since the last org
        size_state = 1
        scope = None
        for line in lines:
            body = line.body
            label = line.label
            if label is not None and not label.local:
                scope = key(label.name)
            try:
                if isinstance(body, Data):
                    hub = _align(hub, body.size, out)
                elif isinstance(body, (Instruction, Org, Res, Fit)):
                    hub = _align(hub, 4, out)
                cog_bytes = org_cog * 4 + (hub - org_hub) + res_extra * 4
                cog_here = cog_bytes >> 2
                if label is not None and not emit:
                    lsize = body.size if isinstance(body, Data) else (4 if body is not None
                                                                      and not isinstance(body, DatFile)
                                                                      else size_state)
                    if isinstance(body, DatFile):
                        lsize = 1
                    self.define(label, scope, lsize, hub, cog_here, isinstance(body, Res))
                if body is None:
                    continue
                if isinstance(body, Data):
                    size_state = body.size
                    data = self.data(body, cog_here, scope, emit)
                    if emit:
                        out += data
                        spans.append((hub, bytes(data), line.pos, ""))
                    hub += len(data)
                elif isinstance(body, Instruction):
                    size_state = 4
                    if emit:
                        word = self.instruction(body, cog_here, scope)
                        data = word.to_bytes(4, "little")
                        out += data
                        spans.append((hub, data, line.pos, body.mnemonic))
                    hub += 4
                elif isinstance(body, Org):
                    size_state = 4
                    value = self.const_now(body.value, cog_here, scope) if body.value is not None else 0
                    if value > 0x1F0:
                        self.report(msg.ORG_RANGE.format(value=value), body.value)
                    org_hub, org_cog, res_extra = hub, value, 0
                elif isinstance(body, Res):
                    size_state = 4
                    count = self.const_now(body.value, cog_here, scope) if body.value is not None else 1
                    res_extra += count
                elif isinstance(body, Fit):
                    limit = self.const_now(body.value, cog_here, scope) if body.value is not None else 0x1F0
                    if emit and cog_here > limit:
                        self.report(msg.FIT_EXCEEDED.format(limit=limit, addr=cog_here), body)
                elif isinstance(body, DatFile):
                    data = self.file_data(body)
                    if emit:
                        out += data
                        spans.append((hub, data, line.pos, f'file "{body.filename}"'))
                    hub += len(data)
                    size_state = 1
            except _Abort:
                continue

    def define(self, label, scope, size, hub, cog, reserved) -> None:
        sym = DatSymbol(label.name, size, hub, cog, reserved, label.pos)
        if label.local:
            k = (scope, key(label.name))
            table = self.locals
        else:
            k = key(label.name)
            table = self.symbols
            if self.const_lookup(label.name) is not None:
                self.report(msg.DUPLICATE_SAME_LINE.format(name=label.name), label)
                return
        if k in table:
            self.report(msg.DUPLICATE.format(name=label.name, line=table[k].pos.line), label)
            return
        table[k] = sym

    # ------------------------------------------------------------------ data
    def data(self, body: Data, cog_here: int, scope, emit: bool) -> bytearray:
        out = bytearray()
        size = body.size
        for item in body.items:
            if item.size:
                # an override holds for the rest of the line; it may not be smaller than the line's size
                if item.size < body.size:
                    self.report(msg.OVERRIDE_TOO_SMALL.format(size=_SIZE_WORDS[item.size],
                                                              line=_SIZE_WORDS[body.size]), item)
                    raise _Abort()
                size = item.size
            count = 1
            if item.count is not None:
                count = to_signed(self.const_now(item.count, cog_here, scope))
                if count < 0:
                    count = 0        # OpenSpin stores nothing for a negative count
                elif count > 0x8000:
                    self.report(msg.BAD_COUNT.format(low=0, high="$8000", value=count), item.count)
                    raise _Abort()
            if isinstance(item.value, Str):
                values = list(self.char_bytes(item.value.text))
            elif emit:
                try:
                    v = self.value(item.value, cog_here, scope, final=True)
                except (NotConstant, ConstError) as exc:
                    node = exc.node
                    self.report(getattr(exc, "message", msg.NEEDS_CONSTANT), node)
                    v = Const(0)
                if v.is_float and size != 4:
                    self.report(msg.INTEGER_AND_FLOAT, item.value)
                values = [v.bits]
            else:
                values = [0]
            for v in values:
                out += (v & ((1 << (8 * size)) - 1)).to_bytes(size, "little") * count
        return out

    def file_data(self, body: DatFile) -> bytes:
        """The bytes of ``file "name"``, looked up as OBJ files are (frontend/search.py)."""
        if body.filename in self.file_cache:
            return self.file_cache[body.filename]
        here = os.path.dirname(os.path.abspath(self.unit.path))
        search = self.unit.search
        data = b""
        try:
            found = search.find(body.filename, here)
        except AmbiguousName as exc:
            self.report(msg.AMBIGUOUS_FILE.format(name=body.filename, folder=exc.folder,
                                                  candidates=", ".join(exc.candidates)), body)
            found = False
        if found is None:
            self.report(not_found_message(msg.DAT_FILE_NOT_FOUND, body.filename, search, here), body)
        elif found:
            if found.warning:
                pos = body.pos
                search.warnings.append(Diagnostic(found.warning, pos.path, pos.line, pos.col,
                                                  self.unit.spin.source.line(pos.line), "warning"))
            try:
                with open(found.path, "rb") as fh:
                    data = fh.read(HUB_BYTES + 1)   # more than the hub holds cannot fit in any image
                search.files[found.path] = (len(data), zlib.crc32(data))    # (for the program cache)
                if len(data) > HUB_BYTES:
                    self.report(msg.DAT_FILE_TOO_BIG.format(name=body.filename, size=HUB_BYTES), body)
                    data = b""
            except OSError:
                self.report(msg.DAT_FILE_NOT_FOUND.format(name=body.filename, where=found.path), body)
                data = b""
        self.file_cache[body.filename] = data
        return data

    # ------------------------------------------------------------------ PASM
    def instruction(self, ins: Instruction, cog_here: int, scope) -> int:
        try:
            from ..pasm import PasmError, encode
        except ImportError:  # pragma: no cover - pasm.py arrives from another branch
            self.report(msg.PASM_UNAVAILABLE, ins)
            return 0
        values = []
        for op in ins.operands:
            try:
                v = self.value(op.expr, cog_here, scope, final=True)
            except (NotConstant, ConstError) as exc:
                self.report(getattr(exc, "message", msg.NEEDS_CONSTANT), exc.node)
                return 0
            values.append((op, v.bits))
        dest = src = None
        immediate = False
        mnemonic = ins.mnemonic
        try:
            if mnemonic == "call" and len(values) == 1 and values[0][0].immediate:
                target = values[0][0].expr
                src = values[0][1]
                ret = self.call_return(target, scope)
                if ret is None:
                    return 0
                dest, immediate = ret, True
            elif len(values) == 2:
                dest, src = _field(values[0][1]), _field(values[1][1])
                immediate = values[1][0].immediate
            elif len(values) == 1:
                from ..pasm import INSTRUCTIONS
                form = INSTRUCTIONS[mnemonic].operands
                if "s" in form and "d" not in form:
                    src, immediate = _field(values[0][1]), values[0][0].immediate
                else:
                    dest = _field(values[0][1])
            return encode(mnemonic, condition=ins.cond, effects=ins.effects, dest=dest, src=src,
                          immediate=immediate)
        except PasmError as exc:
            self.report(exc.message, ins)
            return 0

    def call_return(self, target, scope):
        if isinstance(target, NameRef):
            sym = self.symbols.get(key(target.name + "_ret"))
        elif isinstance(target, LocalLabel):
            sym = self.locals.get((scope, key(target.name + "_ret")))
        else:
            sym = None
        if sym is None:
            name = getattr(target, "name", "?")
            self.report(msg.UNDEFINED.format(name=name + "_ret"), target)
            return None
        return sym.cog


def _field(v: int) -> int:
    """An operand for pasm.encode: negative values pass as negatives (OpenSpin ORs them in)."""
    return to_signed(v)


_SIZE_WORDS = {1: "byte", 2: "word", 4: "long"}


def _align(hub: int, size: int, out) -> int:
    pad = (-hub) % size
    if pad and out is not None:
        out += bytes(pad)
    return hub + pad


def assemble_dat(unit, start: int, const_lookup, child_const, report) -> DatResult:
    """Assemble ``unit``'s DAT lines placed at object offset ``start``.

    Args:
        const_lookup: name -> Const or None (the object's CON).
        child_const: ObjConst node -> Const (raises ConstError).
        report: ``report(message, node)`` records an error.
    """
    return _Assembler(unit, start, const_lookup, child_const, report).run(unit.spin.dat)
