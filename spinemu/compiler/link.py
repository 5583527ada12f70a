"""Linking compiled objects into a Propeller image: object placement, VAR, header.

Placement (observed on OpenSpin 1.00.81): list the objects depth first
(each OBJ line once, in declaration order, an object before its own
children); objects that are identical (same bytes and same children) are
kept once, at their *last* place in that list.  The top object comes first,
at $0010.  A child entry holds the child's offset from its parent and the
VAR offset of that instance.

VAR: each instance's block is its own VAR (long-aligned) followed by the
blocks of its child instances in table order.  The top object's VAR starts
at ``vbase``, right after the last object; the boot frame (8 bytes) follows
the VAR, then the first method's frame (result, parameters, locals).

Clock (Propeller Manual, _CLKMODE/_XINFREQ/_CLKFREQ): without ``_clkmode``
the chip runs on RCFAST (12 MHz).  With a crystal or external input,
``clkfreq`` is ``_xinfreq`` times the PLL factor (or ``_clkfreq`` given
directly); RCFAST and RCSLOW are 12 MHz and 20 kHz.
"""
from __future__ import annotations

from ..diagnostics import Diagnostic
from .. import messages as msg
from ..frontend.constants import encode_clock
from ..image import HEADER_SIZE, ImageHeader, image_checksum

__all__ = ["place_objects", "link", "clock_settings"]


def identity(cobj, compiled: dict, memo: dict):
    """A key that is equal for objects OpenSpin would store once."""
    uid = id(cobj.unit)
    if uid in memo:
        return memo[uid]
    data = bytearray(cobj.data)
    start = cobj.child_table
    data[start:start + 4 * len(cobj.instances)] = bytes(4 * len(cobj.instances))
    kids = tuple(identity(compiled[id(child)], compiled, memo) for _sym, child in cobj.instances)
    memo[uid] = (bytes(data), kids)
    return memo[uid]


def place_objects(top, compiled: dict) -> list:
    """The distinct objects in placement order (top first)."""
    memo: dict = {}
    order: list = []

    def walk(cobj):
        for decl, child in cobj.unit.children:
            ccobj = compiled[id(child)]
            order.append(ccobj)
            walk(ccobj)

    walk(top)
    last: dict = {}
    for i, c in enumerate(order):
        last[identity(c, compiled, memo)] = i
    placed = [top]
    seen = {identity(top, compiled, memo)}
    for i, c in enumerate(order):
        k = identity(c, compiled, memo)
        if last[k] == i and k not in seen:
            placed.append(c)
            seen.add(k)
    return placed, memo


def total_var(cobj, compiled: dict) -> int:
    return cobj.var_size + sum(total_var(compiled[id(child)], compiled) for _s, child in cobj.instances)


def clock_settings(unit, errors: list) -> tuple[int, int]:
    """``(clkfreq, clkmode register value)`` from the top object's constants."""
    consts = unit.constants
    mode_c = consts.get("_clkmode")
    xin_c = consts.get("_xinfreq")
    freq_c = consts.get("_clkfreq")

    def bad(reason, name):
        entry = consts.values.get(name)
        node = entry[1] if entry else None
        pos = node.pos if node is not None else None
        errors.append(Diagnostic(msg.BAD_CLOCK.format(reason=reason), pos.path if pos else unit.path,
                                 pos.line if pos else None, pos.col if pos else None,
                                 unit.spin.source.line(pos.line) if pos else None))

    if mode_c is None:
        if xin_c is not None or freq_c is not None:
            bad("_xinfreq/_clkfreq need _clkmode", "_xinfreq" if xin_c is not None else "_clkfreq")
        return 12_000_000, 0
    mode = mode_c.bits
    reg = encode_clock(mode)
    if reg is None:
        bad("_clkmode must name one clock source and at most one PLL factor", "_clkmode")
        return 12_000_000, 0
    if mode & 0x001:
        return 12_000_000, reg
    if mode & 0x002:
        return 20_000, reg
    mult = (mode >> 6) or 1   # PLL1X..PLL16X are the bits of the factor
    if freq_c is not None and xin_c is not None:
        bad("give either _clkfreq or _xinfreq, not both", "_clkfreq")
        return 12_000_000, reg
    if freq_c is not None:
        return freq_c.bits, reg
    if xin_c is None:
        bad("a crystal or input clock needs _xinfreq or _clkfreq", "_clkmode")
        return 12_000_000, reg
    return (xin_c.bits * mult) & 0xFFFFFFFF, reg


def link(top, compiled: dict, errors: list):
    """Place objects, fill child tables, build the header.

    Returns:
        ``(image bytes, placed objects, {id(unit): hub address}, total VAR bytes)``
    """
    placed, _memo = place_objects(top, compiled)
    addr = {}
    cursor = HEADER_SIZE
    memo: dict = {}
    key_addr = {}
    for c in placed:
        k = identity(c, compiled, memo)
        key_addr[k] = cursor
        cursor += c.size
    for cobj in compiled.values():
        addr[id(cobj.unit)] = key_addr[identity(cobj, compiled, memo)]
    image = bytearray(cursor)
    for c in placed:
        base = addr[id(c.unit)]
        data = bytearray(c.data)
        var_off = c.var_size
        for i, (_sym, child) in enumerate(c.instances):
            at = c.child_table + 4 * i
            # past $FFFF only in a program over 64 KB, which memory_check reports below
            data[at:at + 2] = ((addr[id(child)] - base) & 0xFFFF).to_bytes(2, "little")
            data[at + 2:at + 4] = (var_off & 0xFFFF).to_bytes(2, "little")
            var_off += total_var(compiled[id(child)], compiled)
        c.linked = bytes(data)
        image[base:base + len(data)] = data
    vbase = cursor
    var_total = total_var(top, compiled)
    dbase = vbase + var_total + 8
    first = top.methods[0] if top.methods else None
    if first is None or not first.public:
        source = top.unit.spin.source
        line, col = source.end_position()
        errors.append(Diagnostic(msg.NO_PUB, source.path, line, col, source.line(line)))
        return bytes(image), placed, addr, var_total
    pcurr = HEADER_SIZE + first.offset
    dcurr = dbase + 4 + 4 * first.nparams + first.locals_size
    clkfreq, clkmode = clock_settings(top.unit, errors)
    header = ImageHeader(clkfreq, clkmode, 0, HEADER_SIZE, vbase & 0xFFFF, dbase & 0xFFFF, pcurr & 0xFFFF,
                         dcurr & 0xFFFF)       # too big for a word: memory_check reports the program too big
    image[0:HEADER_SIZE] = header.pack()
    image[5] = image_checksum(bytes(image))
    memory_check(top.unit, vbase, var_total, errors)
    return bytes(image), placed, addr, var_total


def memory_check(unit, vbase: int, var_total: int, errors: list) -> None:
    """Program, VAR, stack (_stack longs, 16 if not given) and _free must fit in hub RAM.

    OpenSpin 1.00.81 counts ``vbase/4 + VAR/4 + _stack + _free + 1`` longs
    against 8192 (observed with probes).
    """
    stack = unit.constants.get("_stack")
    free = unit.constants.get("_free")
    stack_longs = stack.bits if stack is not None else 16
    free_longs = free.bits if free is not None else 0
    if stack_longs + free_longs > 8192:
        node = unit.constants.values.get("_stack", unit.constants.values.get("_free"))[1]
        errors.append(Diagnostic(msg.STACK_FREE_TOO_BIG, node.pos.path, node.pos.line, node.pos.col,
                                 unit.spin.source.line(node.pos.line)))
        return
    over = (vbase + 3) // 4 + var_total // 4 + stack_longs + free_longs + 1 - 8192
    if over > 0:
        errors.append(Diagnostic(msg.FILE_TOO_BIG.format(longs=over), unit.spin.source.path))
