"""Readable listing of a Propeller 1 image (``spinemu disasm``): header, object tree, code.

Input is a ``.binary`` or ``.eeprom`` image from any compiler.  The listing has:

* the header (clock, clock mode names, pbase/vbase/dbase/pcurr/dcurr, checksum);
* the object tree: every object instance with its code address, size, VAR
  base and children (one object's code serves all its instances);
* per object: the method table, the VAR offsets its code touches, the DAT
  section (hex dump, or PASM where it is cog code: see below) and every
  method's bytecodes with mnemonics and operands, jump targets, called
  methods and the strings after the code;
* when a source map is given, the source line above the code it produced.

Everything about bytecodes comes from :mod:`spinemu.bytecode` (``TABLE``,
``decode_assign``, the operand codecs); PASM from :mod:`spinemu.pasm`.

Which DAT longs are PASM (``pasm=`` argument):

``"auto"`` (default)
    blocks launched by COGINIT: an address of a DAT location (``@entry``)
    that is the second-to-last value on the stack when a method runs
    ``COGINIT``/``COGNEW`` (cognew(@entry, par)).  Each starts at its entry
    (cog address 0) and ends after the highest cog address its reachable
    code runs or names (registers below $1F0), but never past the next
    entry, the end of DAT or 496 longs.  Plus,
    in the rest of DAT, runs of at least :data:`MIN_PLAUSIBLE_RUN` longs
    that all look like unconditional instructions (condition ``if_always``,
    an opcode with a mnemonic); their cog addresses assume ``org 0`` at the
    run's start.
``"launched"``: only COGINIT-launched blocks.  ``"all"``: each object's whole
DAT is one block from ``org 0``.  ``"none"``: hex dump only.  An iterable of
hub addresses: those are the entries (instead of the COGINIT analysis); each
block then runs to the next entry or the end of DAT.

Inside a block, longs with condition ``if_never`` or an opcode without a
mnemonic show as ``long $xxxxxxxx`` (most are data); jump targets get labels
``Lxxx`` (cog address) and ``call`` targets ``Lxxx``/``Lxxx_ret``.

This module reads bytes only; it never imports the compiler (a line table
is passed in as ``source_map``).
"""
from __future__ import annotations

import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable, Mapping, Optional, Union

from .. import bytecode as bc
from .. import pasm as pasm_isa
from ..diagnostics import ImageError
from ..image import ImageHeader, ObjectTable, describe_clkmode, image_checksum, load_image
from .disasm_bytecode import BytecodeInsn, Operand, decode_bytecode

__all__ = [
    "Operand", "BytecodeInsn", "decode_bytecode", "MethodListing", "DatBlock",
    "ObjectListing", "Instance", "ImageListing", "analyse_image", "disassemble_image",
    "MIN_PLAUSIBLE_RUN", "COG_LONGS",
]

MIN_PLAUSIBLE_RUN = 6
COG_LONGS = 496
SourceMap = Union[Mapping[int, tuple], Callable[[int], Optional[tuple]], None]
_TERMINATORS = {"RETURN", "RETURN_VALUE", "ABORT", "ABORT_VALUE", "JMP"}
_COGINIT = {"COGINIT", "COGINIT_RESULT"}


# ----------------------------------------------------------------------------- structure
@dataclass
class MethodListing:
    """One method of an object.

    Attributes:
        index: 1-based method number (table entry).
        start, end: hub addresses of its bytes (``end``: next method or object end).
        local_bytes: size of its locals (from the method table).
        insns: decoded bytecodes.
        strings: ``(hub address, text)`` of the zero-terminated strings after the code.
        padding: ``(hub address, length)`` of trailing zero bytes, if any.
        undecoded: ``(hub address, length)`` of bytes that do not decode
            (an instruction running past the method's end), if any.
    """

    index: int
    start: int
    end: int
    local_bytes: int
    insns: list = field(default_factory=list)
    strings: list = field(default_factory=list)
    padding: Optional[tuple] = None
    undecoded: Optional[tuple] = None


@dataclass
class DatBlock:
    """A piece of DAT: ``kind`` is ``"data"`` or ``"pasm"``.

    For PASM, ``cog_base`` is the hub address of cog address 0, and
    ``reason`` says why it is shown as code (launched where, or plausible).
    """

    kind: str
    start: int
    end: int
    cog_base: int = 0
    reason: str = ""


@dataclass
class ObjectListing:
    """One object's code (shared by all its instances)."""

    table: ObjectTable
    table_end: int
    methods: list
    dat: list
    var_accesses: dict = field(default_factory=dict)   # VAR offset -> set of sizes

    @property
    def base(self) -> int:
        return self.table.base

    @property
    def dat_start(self) -> int:
        return self.table_end

    @property
    def dat_end(self) -> int:
        """Where the first method starts; a method table entry outside the object (a corrupt
        image) does not count: the DAT range never runs past the object, so never past the image."""
        obj_end = self.base + self.table.size
        return min([m.start for m in self.methods if self.table_end <= m.start <= obj_end], default=obj_end)


@dataclass
class Instance:
    """An object instance in the tree: which object, where its VAR lives, its children."""

    name: str
    base: int
    var_base: int
    var_size: int
    children: list = field(default_factory=list)


@dataclass
class ImageListing:
    """Everything :func:`disassemble_image` shows, for renderers other than text."""

    header: ImageHeader
    size: int
    checksum_ok: bool
    root: Instance
    objects: dict           # base address -> ObjectListing
    hub: bytes

    def render(self, source_map: SourceMap = None) -> str:
        """The text listing (see :func:`disassemble_image`)."""
        return _Renderer(self, source_map).render()


# ----------------------------------------------------------------------------- analysis
def analyse_image(image: bytes, *, pasm: Union[str, Iterable[int]] = "auto",
                  name: str = "<image>") -> ImageListing:
    """Decode an image into an :class:`ImageListing`.

    Args:
        image: the bytes of a ``.binary`` or ``.eeprom`` file.
        pasm: which DAT longs to show as PASM (see the module docstring).
        name: file name for error messages.

    Raises:
        ImageError: the bytes are not a usable image (a wrong checksum is
            reported in the listing, not raised).
    """
    hdr = ImageHeader.parse(image)
    vbase = min(hdr.vbase, len(image))
    checksum_ok = image_checksum(bytes(image[:vbase])) == hdr.checksum
    fixed = bytearray(image)
    fixed[5] = image_checksum(bytes(image[:vbase]))
    hub = load_image(bytes(fixed), name)      # structure checks only
    hub = bytes(image[:len(hub)])
    objects: dict[int, ObjectListing] = {}
    total_var = max(0, hdr.dbase - 8 - hdr.vbase)
    root = _walk(hub, hdr.pbase, hdr.vbase, total_var, "top", objects, 0)
    entries = _entries(objects, pasm)
    for obj in objects.values():
        obj.dat = _dat_blocks(hub, obj, entries, pasm)
    return ImageListing(hdr, len(hub), checksum_ok, root, objects, hub)


def _walk(hub, base, var_base, var_size, name, objects, depth) -> Instance:
    if depth > 32:
        raise ImageError(f"object tree deeper than 32 levels at ${base:04X}")
    if base not in objects:
        objects[base] = _object(hub, base)
    table = objects[base].table
    inst = Instance(name, base, var_base, var_size)
    offsets = [var for _, var in table.children]
    for k, (obj_off, var_off) in enumerate(table.children):
        later = [v for v in offsets[k + 1:] if v > var_off]
        size = (min(later) if later else var_size) - var_off
        child_name = f"{name}.obj{len(table.methods) + 1 + k}"
        inst.children.append(_walk(hub, base + obj_off, var_base + var_off, max(0, size),
                                   child_name, objects, depth + 1))
    if offsets:
        inst.var_size = min(offsets)   # the object's own VAR comes before its children's
    return inst


def _object(hub: bytes, base: int) -> ObjectListing:
    table = ObjectTable.parse(hub, base)
    if base + table.size > len(hub):
        raise ImageError(f"object at ${base:04X} claims {table.size} bytes, past the image end")
    table_end = base + 4 * (1 + len(table.methods) + len(table.children))
    obj_end = base + table.size
    starts = sorted({base + off for off, _ in table.methods} | {obj_end})
    methods = []
    for index, (off, local_bytes) in enumerate(table.methods, start=1):
        start = base + off
        end = next(s for s in starts if s > start) if start < obj_end else start
        methods.append(MethodListing(index, start, end, local_bytes))
    obj = ObjectListing(table, table_end, methods, [])
    for m in methods:
        _decode_method(hub, obj, m)
    return obj


def _decode_method(hub: bytes, obj: ObjectListing, m: MethodListing) -> None:
    code_end = m.end
    pos = m.start
    last_target = 0
    while pos < code_end:
        try:
            insn = decode_bytecode(hub[:m.end], pos)
        except ImageError:
            m.undecoded = (pos, m.end - pos)
            return
        m.insns.append(insn)
        pos = insn.end
        for o in insn.operands:
            if insn.op.base == "OBJ" and o.kind == "offset" and insn.op.access == "ADDR" \
                    and m.start < obj.base + o.value < code_end and obj.base + o.value >= pos:
                code_end = obj.base + o.value          # strings follow the code
            if insn.op.base == "VAR" and o.kind == "offset":
                obj.var_accesses.setdefault(o.value, set()).add(insn.op.size)
        if insn.op.code in range(0x40, 0x60):
            obj.var_accesses.setdefault(insn.op.var_offset, set()).add(4)
        target = insn.target
        if target is not None:
            last_target = max(last_target, target)
        if insn.op.mnemonic in _TERMINATORS and last_target < pos and not any(hub[pos:code_end]):
            break
    _strings_and_padding(hub, m, pos)


def _strings_and_padding(hub: bytes, m: MethodListing, pos: int) -> None:
    rest = hub[pos:m.end]
    if not any(rest):
        if rest:
            m.padding = (pos, len(rest))
        return
    while pos < m.end:
        nul = hub.find(0, pos, m.end)
        if nul < 0:
            m.strings.append((pos, hub[pos:m.end].decode("latin-1")))
            return
        if nul == pos:   # zeros after the last string: padding
            m.padding = (pos, m.end - pos)
            return
        m.strings.append((pos, hub[pos:nul].decode("latin-1")))
        pos = nul + 1


def _entries(objects: dict, pasm) -> dict:
    """hub address of each PASM entry -> why (COGINIT analysis or given)."""
    if isinstance(pasm, str):
        if pasm not in ("auto", "launched", "all", "none"):
            raise ValueError(f"pasm must be auto, launched, all, none or hub addresses, not {pasm!r}")
        if pasm in ("all", "none"):
            return {}
        found = {}
        for obj in objects.values():
            for m in obj.methods:
                for addr, at in _launches(obj, m):
                    found.setdefault(addr, f"launched by COGINIT at ${at:04X} (method {m.index})")
        return found
    return {int(a): "entry given by the caller" for a in pasm}


def _launches(obj: ObjectListing, m: MethodListing):
    """(DAT hub address, COGINIT address) for cognew/coginit(@dat, ...) in one method.

    A tiny stack model: constants (``PUSH_0``, ``PUSH_IMMn``...) push their
    value, ``ADDR_x_OBJ`` of a DAT location pushes that address (indexed
    forms too, when the index is a constant: ``@code[0]``), other
    instructions push or pop unknowns by their table effect, and anything of
    unknown effect forgets the stack.  COGINIT takes (id, code address, par).
    """
    stack: list = []                    # ("addr", hub) / ("const", value) / None
    for insn in m.insns:
        op = insn.op
        if op.mnemonic in _COGINIT and len(stack) >= 2 and stack[-2] and stack[-2][0] == "addr":
            yield stack[-2][1], insn.addr
        if op.base == "OBJ" and op.access == "ADDR":
            addr = obj.base + insn.operands[0].value
            if op.indexed:
                index = stack.pop() if stack else None
                addr = addr + op.size * index[1] if index and index[0] == "const" else -1
            stack.append(("addr", addr) if obj.dat_start <= addr < obj.dat_end else None)
            continue
        const = _constant(insn)
        if const is not None:
            stack.append(("const", const))
            continue
        if op.pops is None or op.pushes is None or insn.assign is not None or insn.target is not None:
            stack.clear()
            continue
        del stack[max(0, len(stack) - op.pops):]
        stack += [None] * op.pushes


def _constant(insn: BytecodeInsn) -> Optional[int]:
    name = insn.op.mnemonic
    if name in ("PUSH_NEG1", "PUSH_0", "PUSH_1"):
        return {"PUSH_NEG1": -1, "PUSH_0": 0, "PUSH_1": 1}[name]
    if name == "PUSH_MASK":
        return bc.mask_value(insn.operands[0].value)
    if name.startswith("PUSH_IMM"):
        return insn.operands[0].value
    return None


def _dat_blocks(hub: bytes, obj: ObjectListing, entries: dict, pasm) -> list:
    start, end = obj.dat_start, obj.dat_end
    if start >= end:
        return []
    if pasm == "none":
        return [DatBlock("data", start, end)]
    if pasm == "all":
        return [DatBlock("pasm", start, end, start, "whole DAT shown as PASM (org 0 at its start)")]
    mine = sorted(a for a in entries if start <= a < end)
    blocks = []
    pos = start
    for k, entry in enumerate(mine):
        limit = min([end, entry + 4 * COG_LONGS] + mine[k + 1:k + 2])
        stop = _extent(hub, entry, limit) if isinstance(pasm, str) else limit
        if entry > pos:
            blocks += _data_or_plausible(hub, pos, entry, pasm == "auto")
        blocks.append(DatBlock("pasm", entry, stop, entry, entries[entry]))
        pos = stop
    if pos < end:
        blocks += _data_or_plausible(hub, pos, end, pasm == "auto")
    return blocks


def _extent(hub: bytes, entry: int, limit: int) -> int:
    """End of a launched block: past the last long its reachable code runs or names.

    Walks the code from the entry (cog address 0), following fall-through
    (also over ``if_never`` longs, which the cog runs as no-ops) and immediate
    jump targets; the block ends
    after the highest cog address reached or used as an operand (below
    ``$1F0``), but not past ``limit``.
    """
    longs = (limit - entry) // 4
    if longs <= 0:
        return limit
    words = struct.unpack_from(f"<{longs}I", hub, entry)
    seen, todo, highest = set(), [0], 0
    while todo:
        a = todo.pop()
        if a in seen or a >= longs:
            continue
        seen.add(a)
        d = pasm_isa.decode(words[a])
        if d.cond == 0:                      # if_never: a no-op the cog steps over
            highest = max(highest, a)
            todo.append(a + 1)
            continue
        highest = max(highest, a, d.dest if d.dest < 0x1F0 else 0)
        if not d.immediate and d.src < 0x1F0:
            highest = max(highest, d.src)
        if d.jump_target is not None:
            todo.append(d.jump_target)
        ends = d.cond == 0xF and d.mnemonic in ("jmp", "ret")
        if not ends:
            todo.append(a + 1)
    return min(limit, entry + 4 * (highest + 1))


def _shown_as_code(word: int) -> bool:
    """Inside a PASM block: everything but ``if_never`` longs and opcodes without mnemonic."""
    d = pasm_isa.decode(word)
    return d.cond != 0 and d.instr.kind != "data"


def _could_be_code(word: int) -> bool:
    """For the plausibility scan: shown as code, and not the all-ones long of bitmaps."""
    return word != 0xFFFFFFFF and _shown_as_code(word)


def _data_or_plausible(hub: bytes, start: int, end: int, guess: bool) -> list:
    """Split a DAT range into data and runs that look like code.

    A run is a stretch of longs that all have a condition other than
    ``if_never`` and an opcode with a mnemonic (and are not ``$FFFFFFFF``,
    common in bitmaps), with at least :data:`MIN_PLAUSIBLE_RUN` different
    values, at least 3/4 of them ``if_always`` (random data is ``if_always``
    one time in 16, ASCII text almost never) and at least half of them made
    of three or more different bytes (bitmaps and fills are not).
    """
    if not guess:
        return [DatBlock("data", start, end)]
    blocks, pos, run = [], start, []
    first = start + (-start % 4)
    last = first + 4 * ((end - first) // 4)
    for a in range(first, last + 4, 4):
        d = pasm_isa.decode(struct.unpack_from("<I", hub, a)[0]) if a < last else None
        if d is not None and _could_be_code(d.word):
            run.append(d)
            continue
        always = sum(x.cond == 0xF for x in run)
        distinct = len({x.word for x in run})
        varied = sum(len(set(x.word.to_bytes(4, "little"))) >= 3 for x in run)
        if distinct >= MIN_PLAUSIBLE_RUN and 4 * always >= 3 * len(run) and 2 * varied >= len(run):
            blocks += _plausible(pos, a - 4 * len(run), a)
            pos = a
        run = []
    if pos < end:
        blocks.append(DatBlock("data", pos, end))
    return blocks


def _plausible(pos: int, run: int, stop: int) -> list:
    out = [DatBlock("data", pos, run)] if run > pos else []
    why = f"{(stop - run) // 4} longs that look like code (org 0 assumed at their start)"
    return out + [DatBlock("pasm", run, stop, run, why)]


# ----------------------------------------------------------------------------- text
def disassemble_image(image: bytes, *, source_map: SourceMap = None,
                      pasm: Union[str, Iterable[int]] = "auto", name: str = "<image>") -> str:
    """A readable listing of a Propeller 1 image.

    Args:
        image: the bytes of a ``.binary`` or ``.eeprom`` file.
        source_map: hub address -> ``(path, line)`` or ``(path, line, text)``,
            as a mapping or a callable (``None`` when unknown); the source
            line is shown above the first instruction of each change.  The
            text is read from ``path`` when not given.
        pasm: which DAT longs are PASM: ``"auto"``, ``"launched"``, ``"all"``,
            ``"none"`` or hub addresses of entry points (module docstring).
        name: file name for the heading and error messages.

    Returns:
        The listing, one string.

    Raises:
        ImageError: the bytes are not a usable image.
    """
    return analyse_image(image, pasm=pasm, name=name).render(source_map)


class _Renderer:
    def __init__(self, listing: ImageListing, source_map: SourceMap):
        self.l = listing
        self.out: list[str] = []
        self.source_map = source_map
        self.last_source = None
        self.files: dict[str, list] = {}
        self.instances: dict[int, list] = {}
        self._collect(listing.root)

    def _collect(self, inst: Instance) -> None:
        self.instances.setdefault(inst.base, []).append(inst)
        for child in inst.children:
            self._collect(child)

    def render(self) -> str:
        self.header()
        self.tree(self.l.root, 1)
        for base in sorted(self.l.objects):
            self.object(self.l.objects[base])
        return "\n".join(self.out) + "\n"

    def emit(self, text: str = "") -> None:
        self.out.append(text.rstrip())

    # header and tree
    def header(self) -> None:
        h, size = self.l.header, self.l.size
        self.emit(f"Propeller image, {size} bytes")
        self.emit(f"  clock     {h.clkfreq:,} Hz, clkmode ${h.clkmode:02X} ({describe_clkmode(h.clkmode)})")
        state = "OK" if self.l.checksum_ok else f"WRONG (contents give ${image_checksum(self.l.hub):02X})"
        self.emit(f"  checksum  ${h.checksum:02X} {state}")
        self.emit(f"  pbase ${h.pbase:04X}  vbase ${h.vbase:04X}  dbase ${h.dbase:04X}"
                  f"  pcurr ${h.pcurr:04X}  dcurr ${h.dcurr:04X}")
        var = h.dbase - 8 - h.vbase
        self.emit(f"  VAR       ${h.vbase:04X}-${h.vbase + var - 1:04X} ({var} bytes); "
                  f"boot frame at ${h.dbase - 8:04X}; stack from ${h.dcurr:04X}")
        self.emit()
        self.emit("Object tree (instance: object code, VAR)")

    def tree(self, inst: Instance, depth: int) -> None:
        obj = self.l.objects[inst.base]
        self.emit(f"{'  ' * depth}{inst.name:<{24 - 2 * depth}} object ${inst.base:04X} "
                  f"({obj.table.size} bytes, {len(obj.methods)} methods)  "
                  f"VAR ${inst.var_base:04X} ({inst.var_size} bytes own)")
        for child in inst.children:
            self.tree(child, depth + 1)

    # one object
    def object(self, obj: ObjectListing) -> None:
        names = ", ".join(i.name for i in self.instances.get(obj.base, []))
        self.emit()
        self.emit(f"Object ${obj.base:04X}-${obj.base + obj.table.size - 1:04X} "
                  f"({obj.table.size} bytes; instances: {names})")
        for m in obj.methods:
            self.emit(f"  method {m.index:<3} ${m.start:04X}  locals {m.local_bytes} bytes")
        for k, (obj_off, var_off) in enumerate(obj.table.children):
            self.emit(f"  obj {len(obj.methods) + 1 + k:<6} object ${obj.base + obj_off:04X}  VAR +{var_off}")
        if obj.var_accesses:
            used = ", ".join(f"{'/'.join(_SIZE[s] for s in sorted(sizes))} +{off}"
                             for off, sizes in sorted(obj.var_accesses.items()))
            self.emit(f"  VAR used: {used}")
        for block in obj.dat:
            self.dat(block)
        for m in obj.methods:
            self.method(obj, m)

    def dat(self, block: DatBlock) -> None:
        self.emit()
        if block.kind == "data":
            self.emit(f"  DAT ${block.start:04X}-${block.end - 1:04X} data")
            self.hexdump(block.start, block.end)
            return
        longs = (block.end - block.start) // 4
        self.emit(f"  DAT ${block.start:04X}-${block.end - 1:04X} PASM, cog $000-${longs - 1:03X}: {block.reason}")
        words = struct.unpack_from(f"<{longs}I", self.l.hub, block.start)
        symbols, returns = _pasm_symbols(words)
        for k, w in enumerate(words):
            hub_addr = block.start + 4 * k
            self.source(hub_addr)
            if _shown_as_code(w):
                text = pasm_isa.disassemble(w, k, symbols, ret_as_jmp=k not in returns)
            else:
                text = f"{symbols.get(k, ''):<12} {'':<12} long    ${w:08X}"
            self.emit(f"    ${hub_addr:04X} ${k:03X}  {w:08X}  {text}")
        tail = block.start + 4 * longs
        if tail < block.end:
            self.dat(DatBlock("data", tail, block.end))

    def hexdump(self, start: int, end: int) -> None:
        for a in range(start, end, 16):
            self.source(a)
            chunk = self.l.hub[a:min(a + 16, end)]
            text = "".join(chr(b) if 32 <= b < 127 else "." for b in chunk)
            self.emit(f"    ${a:04X}  {chunk.hex(' '):<47}  |{text}|")

    def method(self, obj: ObjectListing, m: MethodListing) -> None:
        self.emit()
        entry = "  (image entry point)" if m.start == self.l.header.pcurr else ""
        self.emit(f"  method {m.index}  ${m.start:04X}-${m.end - 1:04X}  locals {m.local_bytes} bytes{entry}")
        targets = {i.target for i in m.insns}
        for insn in m.insns:
            self.source(insn.addr)
            mark = ">" if insn.addr in targets else " "
            comment = self.comment(obj, m, insn)
            self.emit(f"    ${insn.addr:04X}{mark} {insn.data.hex(' '):<18} {insn.text()}"
                      + (f"  ' {comment}" if comment else ""))
        for addr, text in m.strings:
            self.emit(f"    ${addr:04X}  string {_quote(text)}")
        if m.padding:
            self.emit(f"    ${m.padding[0]:04X}  padding, {m.padding[1]} zero bytes")
        if m.undecoded:
            addr, length = m.undecoded
            self.emit(f"    ${addr:04X}  {length} bytes that do not decode (an instruction runs past the end):")
            self.hexdump(addr, addr + length)

    def comment(self, obj: ObjectListing, m: MethodListing, insn: BytecodeInsn) -> str:
        op = insn.op
        if op.mnemonic == "CALL":
            return _method_at(obj, insn.operands[0].value)
        if op.mnemonic in ("CALL_OBJ", "CALL_OBJ_X"):
            entry, meth = insn.operands[0].value, insn.operands[1].value
            child = entry - len(obj.methods) - 1
            if 0 <= child < len(obj.table.children):
                target = self.l.objects.get(obj.base + obj.table.children[child][0])
                where = _method_at(target, meth) if target else "?"
                return f"object ${obj.base + obj.table.children[child][0]:04X} {where}"
            return "no such child object"
        if op.base == "OBJ" and insn.operands and insn.operands[0].kind == "offset":
            addr = obj.base + insn.operands[0].value
            text = dict(m.strings).get(addr)
            if text is not None:
                return _quote(text)
            return f"hub ${addr:04X}" + (" (DAT)" if obj.dat_start <= addr < obj.dat_end else "")
        return ""

    def source(self, addr: int) -> None:
        if self.source_map is None:
            return
        where = self.source_map(addr) if callable(self.source_map) else self.source_map.get(addr)
        if not where or tuple(where[:2]) == self.last_source:
            return
        self.last_source = tuple(where[:2])
        path, line = where[0], where[1]
        text = where[2] if len(where) > 2 else self.source_text(path, line)
        self.emit(f"    ' {Path(path).name}:{line}  {text.strip()}")

    def source_text(self, path: str, line: int) -> str:
        if path not in self.files:
            try:
                self.files[path] = Path(path).read_text(encoding="latin-1").splitlines()
            except OSError:
                self.files[path] = []
        lines = self.files[path]
        return lines[line - 1] if 1 <= line <= len(lines) else ""


_SIZE = {1: "byte", 2: "word", 4: "long"}


def _quote(text: str) -> str:
    return '"' + "".join(c if 32 <= ord(c) < 127 and c != '"' else f"\\x{ord(c):02X}" for c in text) + '"'


def _method_at(obj: ObjectListing, index: int) -> str:
    if 1 <= index <= len(obj.methods):
        return f"method {index} at ${obj.methods[index - 1].start:04X}"
    return f"method {index} (not in the table)"


def _pasm_symbols(words) -> tuple[dict, set]:
    """Labels for a PASM block and the cog addresses of subroutine returns.

    ``Lxxx`` names jump targets; a ``jmpret`` with ``wr`` and ``#`` whose
    destination holds a ``jmp #``-form long is a call: its return gets
    ``Lxxx_ret``.  ``ret``-form longs that no call returns through are
    ``jmp #$000`` (the same long) and make ``L000`` a target.
    """
    symbols, returns = {}, set()
    decoded = [pasm_isa.decode(w) for w in words]
    for d in decoded:
        if d.mnemonic == "jmpret" and d.immediate and d.writes and d.dest < len(words):
            ret = decoded[d.dest]
            if ret.opcode == 0b010111 and not ret.writes and ret.immediate:
                returns.add(d.dest)
    for addr, d in enumerate(decoded):
        target = d.jump_target
        if d.mnemonic == "ret" and addr not in returns and _shown_as_code(d.word):
            target = 0
        if target is not None and target < len(words):
            symbols[target] = f"L{target:03X}"
    for addr in returns:
        src = next(d.src for d in decoded if d.mnemonic == "jmpret" and d.dest == addr and d.immediate)
        symbols[addr] = f"L{src:03X}_ret"
    return symbols, returns
