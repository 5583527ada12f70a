"""Every bytecode of spinemu.bytecode.TABLE and every assignment operator: emit -> decode -> emit.

The disassembler's structured form (opcode, operands with their widths,
assignment operator, jump) must give back the exact bytes, agree with
``instruction_length`` and show the table's mnemonic and the jump target.
"""
from __future__ import annotations

import pytest

from spinemu import bytecode as bc
from spinemu.analysis.disasm import decode_bytecode

BASE = 0x1000
USING_OPS = [op for op in bc.TABLE if op.fmt.endswith("+using")]


def operand_variants(op: bc.Opcode) -> list[bytes]:
    """Operand bytes (before any assignment byte) in every width the format allows."""
    main = op.fmt.split("+")[0]
    if main == bc.JUMP:
        return [bc.encode_signed(v, force_long=f) for v, f in
                [(5, False), (-7, False), (63, False), (-64, False), (5, True), (300, False), (-16384, False)]]
    if main == bc.OFFSET:
        return [bc.encode_unsigned(v, force_long=f) for v, f in [(0, False), (127, False), (8, True), (0x7FFF, False)]]
    if main == bc.METHOD:
        return [bytes([1]), bytes([200])]
    if main == bc.OBJ_METHOD:
        return [bytes([3, 1]), bytes([17, 9])]
    if main == bc.MASK:
        return [bytes([c]) for c in range(0x80)]
    if main.startswith("imm"):
        n = int(main[3:])
        return [bytes(n), bytes([0xFF] * n), bytes(range(0x11, 0x11 + n))]
    if main == bc.REG:
        return [bytes([0x80 | (a << 5) | r]) for a in (0, 1, 3) for r in (0, 0x11, 0x1F)]
    return [b""]


def check(data: bytes, op: bc.Opcode) -> None:
    insn = decode_bytecode(data + b"\xEE\xEE", 0, BASE)     # trailing bytes must not be taken
    assert insn.data == data
    assert len(data) == bc.instruction_length(data, 0)
    assert insn.op is op
    assert insn.encode() == data
    assert insn.text().startswith(op.mnemonic)
    if insn.target is not None:
        assert f"${insn.target:04X}" in insn.text()


@pytest.mark.parametrize("op", bc.TABLE, ids=lambda op: f"{op.code:02X}_{op.mnemonic}")
def test_every_table_entry_round_trips(op):
    assigns = [bytes([0x00])] if op.fmt.endswith("+using") else [b""]
    for operands in operand_variants(op):
        for tail in assigns:
            check(bytes([op.code]) + operands + tail, op)


@pytest.mark.parametrize("code", sorted(bc.ASSIGN_OPS), ids=lambda c: f"{c:02X}_{bc.ASSIGN_OPS[c].text}")
def test_every_assignment_operator_round_trips(code):
    aop = bc.ASSIGN_OPS[code]
    jumps = [bc.encode_signed(-9), bc.encode_signed(-200), bc.encode_signed(4, force_long=True)] \
        if aop.has_jump else [b""]
    for op in USING_OPS[:4] + [bc.TABLE[0xCA], bc.TABLE[0x26]]:
        for jump in jumps:
            data = bytes([op.code]) + operand_variants(op)[0] + bytes([code]) + jump
            check(data, op)
            insn = decode_bytecode(data, 0, BASE)
            assert insn.assign == aop and aop.text in insn.text()
            if aop.has_jump:
                assert insn.target == BASE + len(data) + bc.decode_signed(jump, 0)[0]


def test_reg_using_carries_its_assignment_operator():
    data = bytes([0x3D, 0x80 | (2 << 5) | 0x14, 0x1C])       # outa[x]~~
    insn = decode_bytecode(data, 0, BASE)
    assert insn.encode() == data
    assert insn.text().split() == ["REG_BIT_USING", "OUTA", "POST_SET"]


def test_truncated_bytecode_is_an_image_error():
    from spinemu.diagnostics import ImageError
    with pytest.raises(ImageError, match=r"\$1000"):
        decode_bytecode(bytes([0x3B, 1, 2]), 0, BASE)
