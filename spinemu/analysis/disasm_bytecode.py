"""One Spin bytecode instruction, decoded into a structured form and emitted again.

:func:`decode_bytecode` turns the bytes at an address into a
:class:`BytecodeInsn` (opcode, operands with their widths, assignment
operator, jump); :meth:`BytecodeInsn.encode` gives the same bytes back and
:meth:`BytecodeInsn.text` the listing text.  Everything comes from
:mod:`spinemu.bytecode` (``TABLE``, ``decode_assign``, the operand codecs,
``mask_value``, ``register_name``); ``instruction_length`` checks the result.
Used by :mod:`spinemu.analysis.disasm`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from .. import bytecode as bc
from ..diagnostics import ImageError

__all__ = ["Operand", "BytecodeInsn", "decode_bytecode"]


# ----------------------------------------------------------------------------- one bytecode
@dataclass
class Operand:
    """One operand of a bytecode instruction.

    Attributes:
        kind: ``jump`` (signed offset), ``offset`` (unsigned), ``method``,
            ``object``, ``mask``, ``imm``, ``reg``.
        value: the decoded number (``reg``: the byte itself).
        width: bytes it takes (1 or 2 for jump/offset: OpenSpin sometimes
            writes small values in the 2-byte form, and the listing keeps it).
    """

    kind: str
    value: int
    width: int

    def encode(self) -> bytes:
        if self.kind == "jump":
            return bc.encode_signed(self.value, force_long=self.width == 2)
        if self.kind == "offset":
            return bc.encode_unsigned(self.value, force_long=self.width == 2)
        if self.kind == "mask":
            return bytes([self.value])
        return (self.value & ((1 << 8 * self.width) - 1)).to_bytes(self.width, "big")


@dataclass
class BytecodeInsn:
    """A decoded bytecode instruction at a hub address.

    Attributes:
        addr: hub address of the opcode byte.
        data: all its bytes.
        op: the :class:`spinemu.bytecode.Opcode`.
        operands: the operands before the assignment byte, in order.
        assign: the assignment operator (USING accesses), else ``None``.
        assign_jump: the jump operand after REPEAT-type assignment ops.
    """

    addr: int
    data: bytes
    op: bc.Opcode
    operands: list = field(default_factory=list)
    assign: Optional[bc.AssignOp] = None
    assign_jump: Optional[Operand] = None

    @property
    def end(self) -> int:
        return self.addr + len(self.data)

    @property
    def target(self) -> Optional[int]:
        """Hub address a jump operand leads to (relative to the instruction's end)."""
        jump = self.assign_jump or next((o for o in self.operands if o.kind == "jump"), None)
        return None if jump is None else self.end + jump.value

    @property
    def reg_access(self) -> Optional[str]:
        reg = next((o for o in self.operands if o.kind == "reg"), None)
        return None if reg is None else bc.ACCESS[(reg.value >> 5) & 3]

    @property
    def mnemonic(self) -> str:
        """The table mnemonic; REG forms add their access (``REG_POP``)."""
        access = self.reg_access
        return self.op.mnemonic + (f"_{access}" if access else "")

    def encode(self) -> bytes:
        """The bytes again, from the decoded fields (round trip of :func:`decode_bytecode`)."""
        out = bytearray([self.op.code])
        for o in self.operands:
            out += o.encode()
        if self.assign is not None:
            out.append(self.assign.code)
        if self.assign_jump is not None:
            out += self.assign_jump.encode()
        return bytes(out)

    def operand_text(self) -> str:
        parts = []
        for o in self.operands:
            if o.kind == "jump":
                parts.append(f"${self.target:04X}" if self.assign_jump is None else f"{o.value:+d}")
            elif o.kind == "offset":
                parts.append(f"+${o.value:04X}" if self.op.base == "OBJ" else f"+{o.value}")
            elif o.kind == "mask":
                parts.append(f"${bc.mask_value(o.value):X}")
            elif o.kind == "imm":
                parts.append(f"{_signed32(o.value) if o.width == 4 else o.value}")
            elif o.kind == "reg":
                parts.append(bc.register_name(0x1E0 + (o.value & 0x1F)))
            else:
                parts.append(str(o.value))
        if self.assign is not None:
            parts.append(self.assign.text)
        if self.assign_jump is not None:
            parts.append(f"${self.target:04X}")
        return " ".join(parts)

    def text(self) -> str:
        ops = self.operand_text()
        return f"{self.mnemonic:<20} {ops}".rstrip()


def _signed32(v: int) -> int:
    return v - (1 << 32) if v & 0x80000000 else v


def decode_bytecode(code, pos: int, base_addr: int = 0) -> BytecodeInsn:
    """Decode the instruction at ``code[pos]``; ``base_addr`` is the hub address of ``code[0]``.

    Raises:
        ImageError: when the instruction runs past the end of ``code``.

    >>> decode_bytecode(bytes([0x0A, 0x05]), 0, 0x100).text()
    'JZ                   $0107'
    >>> decode_bytecode(bytes([0x87, 0x80, 0x47]), 0).text()
    'ADDR_BYTE_OBJ        +$0047'
    """
    try:
        return _decode(code, pos, base_addr)
    except IndexError:
        raise ImageError(f"bytecode at ${base_addr + pos:04X} runs past the end of its method") from None


def _decode(code, pos, base_addr):
    op = bc.TABLE[code[pos]]
    p = pos + 1
    main = op.fmt.split("+")[0]
    operands = []
    if main == bc.JUMP:
        value, q = bc.decode_signed(code, p)
        operands.append(Operand("jump", value, q - p))
    elif main == bc.OFFSET:
        value, q = bc.decode_unsigned(code, p)
        operands.append(Operand("offset", value, q - p))
    elif main in (bc.METHOD, bc.MASK, bc.REG):
        operands.append(Operand({bc.METHOD: "method", bc.MASK: "mask", bc.REG: "reg"}[main], code[p], 1))
    elif main == bc.OBJ_METHOD:
        operands += [Operand("object", code[p], 1), Operand("method", code[p + 1], 1)]
    elif main.startswith("imm"):
        n = int(main[3:])
        operands.append(Operand("imm", int.from_bytes(bytes(code[p:p + n]), "big"), n))
        if len(code) < p + n:
            raise IndexError
    q = p + sum(o.width for o in operands)
    insn = BytecodeInsn(base_addr + pos, b"", op, operands)
    using = op.fmt.endswith("+using") or (main == bc.REG and (code[p] >> 5) & 3 == 2)
    if using:
        aop = bc.decode_assign(code[q])
        insn.assign = aop if aop is not None else bc.AssignOp(code[q], f"UNKNOWN_{code[q]:02X}", False)
        q += 1
        if aop is not None and aop.has_jump:
            value, r = bc.decode_signed(code, q)
            insn.assign_jump = Operand("jump", value, r - q)
            q = r
    insn.data = bytes(code[pos:q])
    assert len(insn.data) == bc.instruction_length(code, pos)
    return insn
