"""The listing: the image's bytes beside the Spin lines that made them.

It is a second view of the compiler's spans (the binary is the first): the
source line of each instruction comes from the spans, the mnemonics from the
opcode table in spinemu.bytecode.  Layout::

    ; object stepper.spin at $00C4 (size $01FC)
    ; PUB setMode(m)
    ;   54|  mode := m & %1111
    $0113  64            PUSH_LOC_4
    $0114  37 23         PUSH_MASK       $0000000F

With ``addresses=False`` (golden test files) the address column and object
addresses are left out and jumps show their relative offset, so goldens do
not churn when unrelated code moves.
"""
from __future__ import annotations

import bisect
import os

from ..bytecode import TABLE, decode_assign, decode_signed, decode_unsigned, instruction_length, \
    mask_value, register_name

__all__ = ["format_listing", "describe_instruction"]

_BYTES_PER_ROW = 8


def describe_instruction(code: bytes, pos: int, base: int = 0, addresses: bool = True) -> str:
    """Mnemonic and operands of the instruction at ``code[pos]`` (``base``: hub address of code[0])."""
    op = TABLE[code[pos]]
    fmt = op.fmt.split("+")[0]
    p = pos + 1
    text = op.mnemonic
    arg = ""
    if fmt == "jump":
        off, p = decode_signed(code, p)
        arg = f"${base + p + off:04X}" if addresses else f"{off:+d}"
    elif fmt == "offset":
        off, p = decode_unsigned(code, p)
        arg = f"+{off}"
    elif fmt == "method":
        arg = f"method {code[p]}"
        p += 1
    elif fmt == "obj_method":
        arg = f"object {code[p]} method {code[p + 1]}"
        p += 2
    elif fmt == "mask":
        arg = f"${mask_value(code[p]):08X}"
        p += 1
    elif fmt.startswith("imm"):
        n = int(fmt[3:])
        arg = f"${int.from_bytes(code[p:p + n], 'big'):X}"
        p += n
    elif fmt == "reg":
        reg = code[p]
        access = ("PUSH", "POP", "USING", "?")[(reg >> 5) & 3]
        arg = f"{access} {register_name(0x1E0 + (reg & 0x1F))}"
        p += 1
    end = pos + instruction_length(code, pos)
    if p < end:  # an assignment operator (and maybe its jump)
        aop = decode_assign(code[p])
        arg += (" " if arg else "") + (aop.text if aop else f"?{code[p]:02X}")
        if aop is not None and aop.has_jump:
            off, q = decode_signed(code, p + 1)
            arg += f" ${base + q + off:04X}" if addresses else f" {off:+d}"
    return f"{text:<16}{arg}".rstrip()


def _pasm_text(chunk: bytes) -> str:
    """An instruction long as PASM (spinemu.pasm's disassembler), if that module is there."""
    try:
        from ..pasm import disassemble
    except ImportError:  # pragma: no cover - the PASM table comes from another branch
        return ""
    return " ".join(disassemble(int.from_bytes(chunk, "little")).split())


def _hex_rows(data: bytes):
    for i in range(0, len(data), _BYTES_PER_ROW):
        yield i, " ".join(f"{b:02X}" for b in data[i:i + _BYTES_PER_ROW])


def format_listing(prog, addresses: bool = True) -> str:
    out: list[str] = []
    for cobj in prog.objects:
        base = prog.addresses[id(cobj.unit)]
        data = getattr(cobj, "linked", None) or bytes(cobj.data)
        name = os.path.basename(cobj.unit.path)
        out.append(f"; object {name}" + (f" at ${base:04X} (size ${cobj.size:04X})" if addresses else ""))
        source = cobj.unit.spin.source
        starts = [s.offset for s in cobj.spans]

        def span_at(off):
            i = bisect.bisect_right(starts, off) - 1
            return cobj.spans[i] if i >= 0 else None

        def emit(off, chunk, text):
            for i, row in _hex_rows(chunk):
                prefix = f"${base + off + i:04X}  " if addresses else "  "
                out.append(f"{prefix}{row:<24}  {text if i == 0 else ''}".rstrip())

        code_start = cobj.methods[0].offset if cobj.methods else cobj.size
        last_line = None
        # object table and DAT
        for span in cobj.spans:
            if span.offset >= code_start:
                break
            if span.pos is not None and span.pos.line != last_line:
                last_line = span.pos.line
                out.append(f";{last_line:5d}| {(source.line(last_line) or '').rstrip()}")
            chunk = data[span.offset:span.offset + len(span.data)]
            emit(span.offset, chunk, _pasm_text(chunk) if span.note and len(chunk) == 4
                 and span.note not in ("object table",) else span.note)
        for m in cobj.methods:
            node = m.pos
            head = (source.line(node.line) or "").strip()[3:].split("'")[0].strip() or m.name
            out.append(f"; {'PUB' if m.public else 'PRI'} {head}")
            off = m.offset
            code_end = next((s.offset for s in cobj.spans if s.offset >= m.offset and s.note == "string"),
                            m.end)
            while off < code_end:
                span = span_at(off)
                if span is not None and span.pos is not None and span.pos.line != last_line:
                    last_line = span.pos.line
                    out.append(f";{last_line:5d}| {(source.line(last_line) or '').rstrip()}")
                n = instruction_length(data, off)
                emit(off, data[off:off + n], describe_instruction(data, off, base, addresses))
                off += n
            while off < m.end:
                end = data.index(0, off) + 1
                emit(off, data[off:end], "string " + repr(data[off:end - 1].decode("latin-1")))
                off = end
        if cobj.methods and cobj.methods[-1].end < cobj.size:
            emit(cobj.methods[-1].end, data[cobj.methods[-1].end:cobj.size], "padding")
        out.append("")
    return "\n".join(out)
