"""The Spin1 bytecode set as data: one table for compiler, interpreter and disassembler.

Encodings (checked against the images OpenSpin 1.00.81 writes):

``$00-$3F`` one opcode each; operands, if any, follow in the formats below.

``$40-$7F`` fast long access to VAR or local longs 0..7::

    0 1 L o o o a a     L: 0 = VAR (vbase), 1 = local (dbase)
                        ooo: long index (byte offset = 4 * ooo)
                        aa: access (00 push, 01 pop, 10 using, 11 push address)

``$80-$DF`` memory access::

    1 s s i b b a a     ss: 00 byte, 01 word, 10 long
                        i: 1 = indexed (index popped, scaled by the size)
                        bb: 00 MEM (address popped), 01 OBJ (pbase), 10 VAR (vbase), 11 LOC (dbase)
                        aa: access as above
    bb != 00 is followed by an unsigned offset (format OFFSET).

``$E0-$FF`` math operators (binary pop 2 push 1; unary pop 1 push 1).

Operand formats:

* ``JUMP``: signed offset from the end of the instruction. One byte
  ``0sssssss`` (-64..63) or two bytes ``1sssssss ssssssss`` (15-bit signed).
* ``OFFSET``: unsigned; one byte ``0ooooooo`` (0..127) or two bytes
  ``1ooooooo oooooooo`` (15-bit).
* ``METHOD``: one byte, 1-based method index.  ``OBJ_METHOD``: object index
  byte (1-based child slot) then method index byte.
* ``MASK``: one byte ``0 n d mmmmm`` meaning ``2 << m``, minus 1 if ``d``,
  bitwise-inverted if ``n``.
* ``IMM1..IMM4``: a constant, big-endian, in 1 to 4 bytes.
* ``REG``: one byte ``1 aa rrrrr``: register ``$1E0 + r`` with access ``aa``.

Every access of kind USING (``aa = 10``, and SPR/REG variants) is followed by
an *assignment operator* byte, decoded by :data:`ASSIGN_OPS`::

    p 0 0 0 0 0 0 0   WRITE             x := (value below target)
    p 0 0 0 0 0 1 0   REPEAT            repeat x from a to b  (+JUMP back)
    p 0 0 0 0 1 1 0   REPEAT_STEP       repeat x from a to b step s (+JUMP back)
    p 0 0 0 1 0 0 0   RANDOM_FWD        ?x
    p 0 0 0 1 1 0 0   RANDOM_REV        x?
    p 0 0 1 0 0 0 0   SIGNX_BYTE        ~x
    p 0 0 1 0 1 0 0   SIGNX_WORD        ~~x
    p 0 0 1 1 0 0 0   POST_CLEAR        x~
    p 0 0 1 1 1 0 0   POST_SET          x~~
    p 0 1 0 0 s s 0   PRE_INC           ++x     ss: 00 bits, 01 byte, 10 word, 11 long
    p 0 1 0 1 s s 0   POST_INC          x++
    p 0 1 1 0 s s 0   PRE_DEC           --x
    p 0 1 1 1 s s 0   POST_DEC          x--
    p 1 0 m m m m m   MATH              x := x OP y  (OP = math opcode $E0 + m)

``p`` set: the result is also pushed.

Source: Propeller Manual v1.2 for semantics; the Spin bytecode notes
collected on the Parallax forum (Cluso99, 2008) for the layout; every
encoding here was confirmed by compiling probes with OpenSpin.

This module is a shared leaf: it imports nothing from the project.
"""
from __future__ import annotations


from .records import FrozenRecord

__all__ = [
    "Opcode", "TABLE", "BY_MNEMONIC", "MathOp", "MATH_OPS", "MATH_BY_SYMBOL",
    "AssignOp", "ASSIGN_OPS", "decode_assign", "REGISTER_NAMES", "register_name",
    "MEM_SIZES", "MEM_BASES", "ACCESS",
    "encode_signed", "decode_signed", "encode_unsigned", "decode_unsigned",
    "mask_value", "mask_code", "instruction_length",
]

# Operand formats
NONE, JUMP, OFFSET, METHOD, OBJ_METHOD, MASK, IMM1, IMM2, IMM3, IMM4, REG = (
    "", "jump", "offset", "method", "obj_method", "mask", "imm1", "imm2", "imm3", "imm4", "reg")

ACCESS = ("PUSH", "POP", "USING", "ADDR")
MEM_SIZES = (1, 2, 4)
MEM_BASES = ("MEM", "OBJ", "VAR", "LOC")
_SIZE_NAMES = {1: "BYTE", 2: "WORD", 4: "LONG"}


class Opcode(FrozenRecord):
    """One bytecode value.

    Attributes:
        code: the byte.
        mnemonic: the uppercase name used by listings, disassembly and handlers.
        fmt: operand format (see module docstring); ``"+using"`` is appended
            when an assignment-operator byte follows.
        pops, pushes: stack effect in longs (``None``: depends on operands).
        handler: name of the interpreter method (``op_`` + lowercase family).
        doc: one line for listings and docs.
        size, base, indexed, access: decoded fields of memory/variable opcodes.
    """

    _fields = ("code", "mnemonic", "fmt", "pops", "pushes", "handler", "doc", "size", "base", "indexed",
               "access", "var_offset")

    def __init__(self, code: int, mnemonic: str, fmt: str, pops: int | None, pushes: int | None,
                 handler: str, doc: str, size: int = 0, base: str = "", indexed: bool = False,
                 access: str = "", var_offset: int = -1):
        self.code, self.mnemonic, self.fmt, self.pops, self.pushes = code, mnemonic, fmt, pops, pushes
        self.handler, self.doc, self.size, self.base, self.indexed = handler, doc, size, base, indexed
        self.access, self.var_offset = access, var_offset


class MathOp(FrozenRecord):
    """A math operator ``$E0-$FF``; ``assign_code`` is its low 5 bits for MATH assignments."""

    _fields = ("code", "mnemonic", "symbol", "unary", "doc")

    def __init__(self, code: int, mnemonic: str, symbol: str, unary: bool, doc: str):
        self.code, self.mnemonic, self.symbol, self.unary, self.doc = code, mnemonic, symbol, unary, doc

    @property
    def assign_code(self) -> int:
        return self.code & 0x1F


# ----------------------------------------------------------------------------- math
_MATH = [
    (0xE0, "ROR", "->", False, "rotate right"),
    (0xE1, "ROL", "<-", False, "rotate left"),
    (0xE2, "SHR", ">>", False, "shift right (logical)"),
    (0xE3, "SHL", "<<", False, "shift left"),
    (0xE4, "LIMIT_MIN", "#>", False, "limit minimum (signed)"),
    (0xE5, "LIMIT_MAX", "<#", False, "limit maximum (signed)"),
    (0xE6, "NEG", "-", True, "negate"),
    (0xE7, "BIT_NOT", "!", True, "bitwise not"),
    (0xE8, "BIT_AND", "&", False, "bitwise and"),
    (0xE9, "ABS", "||", True, "absolute value"),
    (0xEA, "BIT_OR", "|", False, "bitwise or"),
    (0xEB, "BIT_XOR", "^", False, "bitwise xor"),
    (0xEC, "ADD", "+", False, "add"),
    (0xED, "SUB", "-", False, "subtract"),
    (0xEE, "SAR", "~>", False, "shift arithmetic right"),
    (0xEF, "REV", "><", False, "reverse the low bits"),
    (0xF0, "LOG_AND", "AND", False, "boolean and"),
    (0xF1, "ENCODE", ">|", True, "encode: bit number + 1 of highest set bit"),
    (0xF2, "LOG_OR", "OR", False, "boolean or"),
    (0xF3, "DECODE", "|<", True, "decode: 1 << value"),
    (0xF4, "MUL", "*", False, "multiply, low 32 bits"),
    (0xF5, "MUL_HIGH", "**", False, "multiply, high 32 bits"),
    (0xF6, "DIV", "/", False, "divide (signed)"),
    (0xF7, "MOD", "//", False, "modulus (signed)"),
    (0xF8, "SQRT", "^^", True, "square root"),
    (0xF9, "CMP_LT", "<", False, "less than (signed)"),
    (0xFA, "CMP_GT", ">", False, "greater than (signed)"),
    (0xFB, "CMP_NE", "<>", False, "not equal"),
    (0xFC, "CMP_EQ", "==", False, "equal"),
    (0xFD, "CMP_LE", "=<", False, "equal or less (signed)"),
    (0xFE, "CMP_GE", "=>", False, "equal or greater (signed)"),
    (0xFF, "LOG_NOT", "NOT", True, "boolean not"),
]
MATH_OPS: dict[int, MathOp] = {c: MathOp(c, m, s, u, d) for c, m, s, u, d in _MATH}
#: binary operators by their Spin symbol (upper case for the word operators)
MATH_BY_SYMBOL: dict[tuple[str, bool], MathOp] = {(op.symbol, op.unary): op for op in MATH_OPS.values()}


# ----------------------------------------------------------------------------- assignment ops
class AssignOp(FrozenRecord):
    """A decoded assignment-operator byte (the byte after a USING access)."""

    _fields = ("code", "mnemonic", "push", "size", "math", "has_jump")

    def __init__(self, code: int, mnemonic: str, push: bool, size: int = 0, math: MathOp | None = None,
                 has_jump: bool = False):
        self.code, self.mnemonic, self.push = code, mnemonic, push
        self.size = size            # inc/dec: 0 = bit field, 1/2/4 bytes
        self.math, self.has_jump = math, has_jump

    @property
    def text(self) -> str:
        base = self.mnemonic if self.math is None else f"{self.mnemonic}_{self.math.mnemonic}"
        if self.size and self.mnemonic.endswith(("INC", "DEC")):
            base += "_" + _SIZE_NAMES[self.size]
        return base + ("_PUSH" if self.push else "")


_INCDEC = {0x20: "PRE_INC", 0x28: "POST_INC", 0x30: "PRE_DEC", 0x38: "POST_DEC"}
_SIMPLE_ASSIGN = {0x00: "WRITE", 0x02: "REPEAT", 0x06: "REPEAT_STEP", 0x08: "RANDOM_FWD",
                  0x0C: "RANDOM_REV", 0x10: "SIGNX_BYTE", 0x14: "SIGNX_WORD",
                  0x18: "POST_CLEAR", 0x1C: "POST_SET"}
_INCDEC_SIZE = {0: 0, 1: 1, 2: 2, 3: 4}


def decode_assign(byte: int) -> AssignOp | None:
    """Decode an assignment-operator byte; ``None`` for unused values.

    >>> decode_assign(0x2E).text
    'POST_INC_LONG'
    >>> decode_assign(0xCC).text
    'MATH_ADD_PUSH'
    """
    push = bool(byte & 0x80)
    b = byte & 0x7F
    if b & 0x40:
        if b & 0x20:
            return None
        return AssignOp(byte, "MATH", push, math=MATH_OPS[0xE0 | (b & 0x1F)])
    if b in _SIMPLE_ASSIGN:
        return AssignOp(byte, _SIMPLE_ASSIGN[b], push, has_jump=b in (0x02, 0x06))
    if 0x20 <= b < 0x40 and not (b & 1):
        return AssignOp(byte, _INCDEC[b & 0x38], push, size=_INCDEC_SIZE[(b >> 1) & 3])
    return None


ASSIGN_OPS: dict[int, AssignOp] = {b: op for b in range(256) if (op := decode_assign(b)) is not None}


# ----------------------------------------------------------------------------- registers
_REG_NAMES = ["PAR", "CNT", "INA", "INB", "OUTA", "OUTB", "DIRA", "DIRB",
              "CTRA", "CTRB", "FRQA", "FRQB", "PHSA", "PHSB", "VCFG", "VSCL"]
#: cog register address -> Propeller Manual name ($1F0-$1FF)
REGISTER_NAMES = {0x1F0 + i: n for i, n in enumerate(_REG_NAMES)}


def register_name(reg: int) -> str:
    """Name of a cog register ``$1E0-$1FF`` as a REG operand reaches it.

    >>> register_name(0x1F4), register_name(0x1E9)
    ('OUTA', '$1E9')
    """
    return REGISTER_NAMES.get(reg, f"${reg:03X}")


# ----------------------------------------------------------------------------- the table
_SPECIAL = [
    # code, mnemonic, fmt, pops, pushes, doc
    (0x00, "FRAME_RESULT", NONE, 0, 4, "start a call frame; the call's result is kept"),
    (0x01, "FRAME", NONE, 0, 4, "start a call frame; the result is dropped"),
    (0x02, "FRAME_RESULT_TRAP", NONE, 0, 4, "start a frame that traps aborts; result kept"),
    (0x03, "FRAME_TRAP", NONE, 0, 4, "start a frame that traps aborts; result dropped"),
    (0x04, "JMP", JUMP, 0, 0, "jump"),
    (0x05, "CALL", METHOD, None, None, "call a method of this object"),
    (0x06, "CALL_OBJ", OBJ_METHOD, None, None, "call a method of a child object"),
    (0x07, "CALL_OBJ_X", OBJ_METHOD, None, None, "call a method of an indexed child object"),
    (0x08, "TJZ", JUMP, 1, None, "repeat n: jump (and pop) if zero, else keep the count"),
    (0x09, "DJNZ", JUMP, 1, None, "repeat n: decrement, jump if not zero (pop when done)"),
    (0x0A, "JZ", JUMP, 1, 0, "pop, jump if zero"),
    (0x0B, "JNZ", JUMP, 1, 0, "pop, jump if not zero"),
    (0x0C, "CASE_DONE", NONE, 2, 0, "end of a case branch: pop value and end address, jump there"),
    (0x0D, "CASE_VALUE", JUMP, 1, 0, "pop a value, jump if it equals the case value"),
    (0x0E, "CASE_RANGE", JUMP, 2, 0, "pop a range, jump if the case value lies in it"),
    (0x0F, "LOOK_DONE", NONE, 3, 1, "lookup/lookdown found nothing: result 0"),
    (0x10, "LOOKUP_VALUE", NONE, 1, None, "lookup: one value"),
    (0x11, "LOOKDOWN_VALUE", NONE, 1, None, "lookdown: one value"),
    (0x12, "LOOKUP_RANGE", NONE, 2, None, "lookup: a range"),
    (0x13, "LOOKDOWN_RANGE", NONE, 2, None, "lookdown: a range"),
    (0x14, "POP", NONE, None, 0, "pop n bytes (n popped first)"),
    (0x15, "RUN", NONE, 2, 3, "prepare a Spin method for COGINIT in a new cog"),
    (0x16, "STRSIZE", NONE, 1, 1, "length of a zero-terminated string"),
    (0x17, "STRCOMP", NONE, 2, 1, "compare two strings (TRUE if equal)"),
    (0x18, "BYTEFILL", NONE, 3, 0, "fill bytes"),
    (0x19, "WORDFILL", NONE, 3, 0, "fill words"),
    (0x1A, "LONGFILL", NONE, 3, 0, "fill longs"),
    (0x1B, "WAITPEQ", NONE, 3, 0, "wait until (INA & mask) == state"),
    (0x1C, "BYTEMOVE", NONE, 3, 0, "copy bytes"),
    (0x1D, "WORDMOVE", NONE, 3, 0, "copy words"),
    (0x1E, "LONGMOVE", NONE, 3, 0, "copy longs"),
    (0x1F, "WAITPNE", NONE, 3, 0, "wait until (INA & mask) != state"),
    (0x20, "CLKSET", NONE, 2, 0, "set clock mode and frequency (reboot for mode $80)"),
    (0x21, "COGSTOP", NONE, 1, 0, "stop a cog"),
    (0x22, "LOCKRET", NONE, 1, 0, "return a lock"),
    (0x23, "WAITCNT", NONE, 1, 0, "wait until CNT equals the value"),
    (0x24, "PUSH_SPR", NONE, 1, 1, "push special register $1F0 + index"),
    (0x25, "POP_SPR", NONE, 2, 0, "pop into special register $1F0 + index"),
    (0x26, "USING_SPR", NONE + "+using", None, None, "assignment operator on SPR[index]"),
    (0x27, "WAITVID", NONE, 2, 0, "wait for the video generator, hand it colors and pixels"),
    (0x28, "COGINIT_RESULT", NONE, 3, 1, "start a cog, push its id (or -1)"),
    (0x29, "LOCKNEW_RESULT", NONE, 0, 1, "check out a lock, push its id (or -1)"),
    (0x2A, "LOCKSET_RESULT", NONE, 1, 1, "set a lock, push its previous state"),
    (0x2B, "LOCKCLR_RESULT", NONE, 1, 1, "clear a lock, push its previous state"),
    (0x2C, "COGINIT", NONE, 3, 0, "start a cog"),
    (0x2D, "LOCKNEW", NONE, 0, 0, "check out a lock"),
    (0x2E, "LOCKSET", NONE, 1, 0, "set a lock"),
    (0x2F, "LOCKCLR", NONE, 1, 0, "clear a lock"),
    (0x30, "ABORT", NONE, 0, 0, "abort with the current result"),
    (0x31, "ABORT_VALUE", NONE, 1, 0, "abort with a value"),
    (0x32, "RETURN", NONE, 0, 0, "return with the current result"),
    (0x33, "RETURN_VALUE", NONE, 1, 0, "return a value"),
    (0x34, "PUSH_NEG1", NONE, 0, 1, "push -1"),
    (0x35, "PUSH_0", NONE, 0, 1, "push 0"),
    (0x36, "PUSH_1", NONE, 0, 1, "push 1"),
    (0x37, "PUSH_MASK", MASK, 0, 1, "push a mask constant"),
    (0x38, "PUSH_IMM1", IMM1, 0, 1, "push a 1-byte constant"),
    (0x39, "PUSH_IMM2", IMM2, 0, 1, "push a 2-byte constant"),
    (0x3A, "PUSH_IMM3", IMM3, 0, 1, "push a 3-byte constant"),
    (0x3B, "PUSH_IMM4", IMM4, 0, 1, "push a 4-byte constant"),
    (0x3C, "UNKNOWN_3C", NONE, 0, 0, "unused"),
    (0x3D, "REG_BIT", REG, None, None, "register bit: reg[bit]"),
    (0x3E, "REG_RANGE", REG, None, None, "register bit range: reg[hi..lo]"),
    (0x3F, "REG", REG, None, None, "whole register"),
]

_ACCESS_EFFECT = {"PUSH": (0, 1), "POP": (1, 0), "USING": (None, None), "ADDR": (0, 1)}
_ACCESS_DOC = {"PUSH": "push", "POP": "pop into", "USING": "assignment operator on", "ADDR": "push the address of"}


def _build() -> list[Opcode]:
    table: list[Opcode | None] = [None] * 256
    for code, mnem, fmt, pops, pushes, doc in _SPECIAL:
        handler = "op_unknown" if mnem.startswith("UNKNOWN") else "op_" + mnem.lower()
        table[code] = Opcode(code, mnem, fmt, pops, pushes, handler, doc)
    for code in range(0x40, 0x80):
        loc = bool(code & 0x20)
        slot = (code >> 2) & 7
        acc = ACCESS[code & 3]
        base = "LOC" if loc else "VAR"
        pops, pushes = _ACCESS_EFFECT[acc]
        fmt = "+using" if acc == "USING" else NONE
        table[code] = Opcode(
            code, f"{acc}_{base}_{slot * 4}", fmt, pops, pushes, "op_var_long",
            f"{_ACCESS_DOC[acc]} {'local' if loc else 'VAR'} long at +{slot * 4}",
            size=4, base=base, access=acc, var_offset=slot * 4)
    for code in range(0x80, 0xE0):
        size = MEM_SIZES[(code >> 5) & 3]
        indexed = bool(code & 0x10)
        base = MEM_BASES[(code >> 2) & 3]
        acc = ACCESS[code & 3]
        pops, pushes = _ACCESS_EFFECT[acc]
        if pops is not None:
            pops += (base == "MEM") + indexed
        fmt = (OFFSET if base != "MEM" else NONE) + ("+using" if acc == "USING" else "")
        name = f"{acc}_{_SIZE_NAMES[size]}_{base}" + ("_X" if indexed else "")
        table[code] = Opcode(
            code, name, fmt, pops, pushes, "op_mem",
            f"{_ACCESS_DOC[acc]} {_SIZE_NAMES[size].lower()} at {base}" + ("[index]" if indexed else ""),
            size=size, base=base, indexed=indexed, access=acc)
    for code, op in MATH_OPS.items():
        table[code] = Opcode(code, op.mnemonic, NONE, 1 if op.unary else 2, 1,
                             "op_math", f"{op.doc} ({op.symbol})")
    assert all(t is not None for t in table)
    return table  # type: ignore[return-value]


#: 256 entries, indexed by byte value
TABLE: list[Opcode] = _build()
BY_MNEMONIC: dict[str, Opcode] = {op.mnemonic: op for op in TABLE}


# ----------------------------------------------------------------------------- operand codecs
def encode_signed(offset: int, force_long: bool = False) -> bytes:
    """A JUMP operand: 1 byte for -64..63 (unless ``force_long``), else 2 bytes.

    >>> encode_signed(-8).hex(), encode_signed(100).hex(), encode_signed(-200).hex()
    ('78', '8064', 'ff38')
    """
    if -64 <= offset <= 63 and not force_long:
        return bytes([offset & 0x7F])
    if not -16384 <= offset <= 16383:
        raise ValueError(f"jump offset {offset} does not fit in 15 bits")
    v = offset & 0x7FFF
    return bytes([0x80 | (v >> 8), v & 0xFF])


def decode_signed(data, pos: int) -> tuple[int, int]:
    """Decode a JUMP operand at ``pos``; returns ``(offset, new_pos)``."""
    b = data[pos]
    if b & 0x80:
        v = ((b & 0x7F) << 8) | data[pos + 1]
        return (v - 0x8000 if v & 0x4000 else v), pos + 2
    return (b - 0x80 if b & 0x40 else b), pos + 1


def encode_unsigned(value: int, force_long: bool = False) -> bytes:
    """An OFFSET operand: 1 byte for 0..127 (unless ``force_long``), else 2 bytes.

    >>> encode_unsigned(8).hex(), encode_unsigned(0xD2).hex()
    ('08', '80d2')
    """
    if 0 <= value <= 0x7F and not force_long:
        return bytes([value])
    if not 0 <= value <= 0x7FFF:
        raise ValueError(f"offset {value} does not fit in 15 bits")
    return bytes([0x80 | (value >> 8), value & 0xFF])


def decode_unsigned(data, pos: int) -> tuple[int, int]:
    """Decode an OFFSET operand at ``pos``; returns ``(value, new_pos)``."""
    b = data[pos]
    if b & 0x80:
        return ((b & 0x7F) << 8) | data[pos + 1], pos + 2
    return b, pos + 1


def mask_value(code: int) -> int:
    """The constant a PUSH_MASK operand stands for.

    >>> hex(mask_value(0x21)), hex(mask_value(0x63)), hex(mask_value(0x07))
    ('0x3', '0xfffffff0', '0x100')
    """
    v = (2 << (code & 0x1F)) & 0xFFFFFFFF
    if code & 0x20:
        v = (v - 1) & 0xFFFFFFFF
    if code & 0x40:
        v ^= 0xFFFFFFFF
    return v


#: value -> smallest PUSH_MASK operand code producing it
_MASKS: dict[int, int] = {}
for _c in range(0x80):
    _MASKS.setdefault(mask_value(_c), _c)


def mask_code(value: int) -> int | None:
    """The PUSH_MASK operand for ``value`` (32-bit), or ``None``.

    >>> mask_code(4), mask_code(256), mask_code(5)
    (1, 7, None)
    """
    return _MASKS.get(value & 0xFFFFFFFF)


def instruction_length(code_bytes, pos: int) -> int:
    """Length in bytes of the instruction at ``pos`` (operands and assignment byte included)."""
    op = TABLE[code_bytes[pos]]
    p = pos + 1
    fmt = op.fmt
    main = fmt.split("+")[0]
    if main == JUMP:
        _, p = decode_signed(code_bytes, p)
    elif main == OFFSET:
        _, p = decode_unsigned(code_bytes, p)
    elif main in (METHOD, MASK, IMM1, REG):
        p += 1
    elif main == OBJ_METHOD or main == IMM2:
        p += 2
    elif main == IMM3:
        p += 3
    elif main == IMM4:
        p += 4
    using = fmt.endswith("+using") or (main == REG and (code_bytes[pos + 1] >> 5) & 3 == 2)
    if using:
        aop = decode_assign(code_bytes[p])
        p += 1
        if aop is not None and aop.has_jump:
            _, p = decode_signed(code_bytes, p)
    return p - pos
