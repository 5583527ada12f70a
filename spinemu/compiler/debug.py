"""Debug information from a compiled program (:class:`spinemu.debuginfo.DebugInfo`).

Everything comes from records the compiler keeps anyway: the placed objects
and their method table (:class:`~spinemu.compiler.objcode.MethodInfo`, with
each frame's named slots), the VAR and DAT symbols, the instance layout and
the spans' source positions.  Nothing here changes the image.
"""
from __future__ import annotations

from ..debuginfo import DebugInfo, FrameSlot, Instance, MethodDebug, ObjectDebug, Variable

__all__ = ["build_debug_info"]


def _object_debug(cobj, base: int) -> ObjectDebug:
    unit = cobj.unit
    methods = []
    for m in cobj.methods:
        slots = [FrameSlot(*s) for s in m.slots] or [FrameSlot("result", 0, 1, "result")]
        methods.append(MethodDebug(m.name, m.public, m.index, unit.path, base + m.offset, base + m.end,
                                   m.pos.line, slots))
    code_start = base + (cobj.methods[0].offset if cobj.methods else cobj.size)
    syms = sorted(cobj.dat_symbols.values(), key=lambda s: s.offset)
    dat = []
    for i, s in enumerate(syms):
        nxt = syms[i + 1].offset if i + 1 < len(syms) else code_start - base
        size = s.size or 4
        count = max(1, (nxt - s.offset) // size) if not s.reserved else 1
        dat.append(Variable(s.name, "DAT", base + s.offset, size, count))
    return ObjectDebug(unit.path, base, cobj.size, methods, dat, cobj.child_table + 4 * len(cobj.instances),
                       code_start)


def build_debug_info(prog) -> DebugInfo:
    """The :class:`DebugInfo` of ``prog`` (a :class:`~spinemu.compiler.CompiledProgram`)."""
    objects = []
    by_base: dict = {}
    for cobj in prog.objects:
        base = prog.addresses[id(cobj.unit)]
        od = _object_debug(cobj, base)
        objects.append(od)
        by_base[base] = od

    def instance(lay, name: str) -> Instance:
        od = by_base[lay.pbase]
        var = [Variable(n, "VAR", lay.vbase + off, size, count) for n, (off, size, count) in lay.var.items()]
        inst = Instance(name, od, lay.vbase, var)
        counts: dict = {}
        for child in lay.children:
            counts[child.name.lower()] = counts.get(child.name.lower(), 0) + 1
        seen: dict = {}
        for child in lay.children:
            k = child.name.lower()
            cname = child.name
            if counts[k] > 1:
                cname = f"{child.name}[{seen.get(k, 0)}]"
                seen[k] = seen.get(k, 0) + 1
            inst.children.append(instance(child, f"{name}.{cname}" if name else cname))
        return inst

    positions = prog.line_table.items(columns=True)
    sources = {}
    for cobj in prog.objects:
        text = cobj.unit.spin.source
        sources[cobj.unit.path] = text.text.splitlines()
    return DebugInfo(instance(prog.layout, ""), objects, positions, sources)
