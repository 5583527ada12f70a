"""The compiler's public API: :func:`compile_file`, :func:`compile_source`, :class:`CompiledProgram`.

>>> prog = compile_source("PUB main\\n  outa[0]~~\\n")
>>> prog.binary[:4].hex(), len(prog.binary)
('001bb700', 32)
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Optional

from ..diagnostics import CompileError, Diagnostic
from ..frontend.objects import load_program
from ..frontend.source import SourceText
from ..image import to_eeprom
from .hints import program_hints
from .link import link, total_var
from .objcode import ObjectCompiler
from ..linetable import LineTable

__all__ = ["compile_file", "compile_source", "CompiledProgram", "LineTable", "InstanceLayout"]


@dataclass
class InstanceLayout:
    """Where one object instance lives in hub RAM (for the Spin->Python translator).

    Attributes:
        path: its source file.
        name: the OBJ name that made it (``""`` for the top object).
        pbase: hub address of the object (its table; DAT and code follow).
        vbase: hub address of its VAR block.
        var: VAR name -> ``(offset from vbase, element size, count)``.
        dat: DAT label -> ``(offset from pbase, size, cog address)``.
        methods: method name -> ``(index, hub address of its code)``.
        constants: constant name -> 32-bit value.
        children: one InstanceLayout per object-table entry.
    """

    path: str
    name: str
    pbase: int
    vbase: int
    var: dict = field(default_factory=dict)
    dat: dict = field(default_factory=dict)
    methods: dict = field(default_factory=dict)
    constants: dict = field(default_factory=dict)
    children: list = field(default_factory=list)


@dataclass
class CompiledProgram:
    """A compiled program: the image and its views.

    Attributes:
        binary: the ``.binary`` image (what OpenSpin writes with ``-b``).
        line_table: :class:`LineTable` from hub address to Spin source line.
        layout: the top object's :class:`InstanceLayout` (with its children).
        warnings: diagnostics of severity "warning": the compiler's hints (spinemu.compiler.hints),
            things that compile but are rarely meant; they change no byte of the image.
        objects: the compiled objects in placement order.
    """

    binary: bytes
    line_table: LineTable
    layout: InstanceLayout
    warnings: list
    objects: list
    addresses: dict

    def eeprom(self) -> bytes:
        """The 32 KB EEPROM image (what OpenSpin writes with ``-e``)."""
        return to_eeprom(self.binary)

    def dat_symbols(self) -> list:
        """``(hub address, cog address, label)`` for every DAT label of every object."""
        out = []
        todo = [self.layout]
        while todo:
            lay = todo.pop()
            todo.extend(lay.children)
            for label, (offset, _size, cog) in lay.dat.items():
                out.append(((lay.pbase + offset) & 0xFFFF, cog, label))
        return sorted(set(out))

    def dat_labels(self) -> dict:
        """Hub address -> ``"'label' in file.spin"`` for every DAT label of every object.

        The chip names a PASM cog's start address with it (``Chip(labels=...)``).
        """
        out: dict = {}
        todo = [self.layout]
        while todo:
            lay = todo.pop()
            todo.extend(lay.children)
            name = os.path.basename(lay.path)
            for label, (offset, _size, _cog) in lay.dat.items():
                out.setdefault((lay.pbase + offset) & 0xFFFF, f"'{label}' in {name}")
        return out

    def debug_info(self):
        """Names and places for tools that look into a running chip (:class:`spinemu.debuginfo.DebugInfo`).

        Built from the compiler's own records on first use; the image is not touched.
        """
        info = getattr(self, "_debug_info", None)
        if info is None:
            from .debug import build_debug_info
            info = self._debug_info = build_debug_info(self)
        return info

    def listing(self, addresses: bool = True) -> str:
        """The listing: every object's bytes next to the source lines that made them.

        Args:
            addresses: print hub addresses (golden test listings leave them out).
        """
        from .listing import format_listing

        return format_listing(self, addresses)


def _instance_layout(cobj, name, pbase_of, vbase, compiled) -> InstanceLayout:
    unit = cobj.unit
    pbase = pbase_of[id(unit)]
    lay = InstanceLayout(unit.path, name, pbase, vbase)
    for v in cobj.symbols.vars:
        lay.var[v.name] = (v.offset, v.size, v.count)
    for sym in cobj.dat_symbols.values():
        lay.dat[sym.name] = (sym.offset, sym.size, sym.cog)
    for m in cobj.methods:
        lay.methods[m.name] = (m.index, pbase + m.offset)
    for k, (value, node) in unit.constants.values.items():
        lay.constants[node.name] = value.bits
    off = vbase + cobj.var_size
    for sym, child in cobj.instances:
        ccobj = compiled[id(child)]
        lay.children.append(_instance_layout(ccobj, sym.name, pbase_of, off, compiled))
        off += total_var(ccobj, compiled)
    return lay


def _compile_unit(top_unit) -> CompiledProgram:
    errors: list[Diagnostic] = []
    undefined: set = set()
    compiled: dict = {}

    def visit(unit):
        if id(unit) in compiled:
            return
        for _decl, child in unit.children:
            visit(child)
        compiled[id(unit)] = ObjectCompiler(unit, errors, undefined).compile()

    visit(top_unit)
    if errors:
        raise CompileError(diagnostics=_sorted(errors))
    top = compiled[id(top_unit)]
    image, placed, addr, _var_total = link(top, compiled, errors)
    if errors:
        raise CompileError(diagnostics=_sorted(errors))
    entries = []
    for c in placed:
        base = addr[id(c.unit)]
        for s in c.spans:
            if s.pos is not None and s.data:
                entries.append((base + s.offset, base + s.offset + len(s.data), s.pos.path, s.pos.line,
                                s.pos.col))
    vbase = int.from_bytes(image[8:10], "little")
    layout = _instance_layout(top, "", addr, vbase, compiled)
    warnings = list(top_unit.search.warnings) + program_hints(c.unit for c in compiled.values())
    return CompiledProgram(image, LineTable(entries), layout, warnings, placed, addr)


def _sorted(errors: list) -> list:
    seen = set()
    out = []
    for d in errors:
        k = (d.path, d.line, d.column, d.message)
        if k not in seen:
            seen.add(k)
            out.append(d)
    return out


def compile_file(path: str, include_dirs=(), defines=(), search=None) -> CompiledProgram:
    """Compile a Spin program (top object ``path``) to a Propeller image.

    Args:
        path: the top object's .spin file.
        include_dirs: more folders to look for OBJ and ``file`` names in (after the source's
            folder; then come the ``SPINEMU_PATH`` folders and the installed tools' libraries).
        defines: names defined for ``#ifdef`` in every file (OpenSpin's ``-D``).
        search: a :class:`spinemu.frontend.search.SearchPath` to use instead (``include_dirs``
            is then ignored).

    Raises:
        ParseError: syntax errors.
        CompileError: anything else wrong (unknown names, missing objects, ...).

    A name found only in another letter case is used with a warning (``prog.warnings``).
    """
    return _compile_unit(load_program(os.fspath(path), include_dirs, defines=defines, search=search))


def compile_source(text: str, name: str = "main.spin", include_dirs=(),
                   files: Optional[dict] = None, defines=()) -> CompiledProgram:
    """Compile Spin source text (and optional extra files ``{name: text}`` for its OBJ lines).

    Diagnostics name the top file ``name``.  OBJ files are looked for among
    ``files`` (written to a temporary folder), then in ``include_dirs``.
    """
    import tempfile

    with tempfile.TemporaryDirectory(prefix="spinemu-") as tmp:
        for fname, body in (files or {}).items():
            with open(os.path.join(tmp, fname), "w", encoding="utf-8") as fh:
                fh.write(body)
        source = SourceText(name, text)
        return _compile_unit(load_program(os.path.join(tmp, os.path.basename(name)), include_dirs, source,
                                          defines=defines))
