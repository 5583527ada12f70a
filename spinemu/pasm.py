"""The Propeller 1 assembly (PASM) instruction set as data, with encoder and disassembler.

Every cog instruction is one long::

    iiiiii zcri cccc ddddddddd sssssssss
    31  26 25..22 21..18  17..9    8..0

    iiiiii     instruction (6 bits)
    z c r i    write Z flag, write C flag, write result, source is immediate
    cccc       condition (IF_xxx, see CONDITIONS; 0000 = never, 1111 = always)
    d...       destination register (9 bits, cog long address)
    s...       source register, or a 9-bit constant when i = 1

Several mnemonics share an ``iiiiii`` value and differ only in ``r`` (``test``
is ``and`` with ``nr``, ``cmp`` is ``sub`` with ``nr``, ``wrlong`` is
``rdlong`` with ``nr``), in the source field (the hub operations ``cogid``,
``coginit``... are ``hubop`` with a fixed immediate source) or in both
(``jmp``, ``call``, ``ret`` are forms of ``jmpret``).  :data:`INSTRUCTIONS`
holds one :class:`Instruction` per mnemonic; :func:`decode` picks the
mnemonic a Propeller Tool or OpenSpin user expects.

Sources: Propeller Manual v1.2, "Assembly Language Reference" (master table,
conditions, effects); every encoding, default effect and operand rule here was
checked against OpenSpin 1.00.81 by compiling probe files (tests/data/pasm,
see tests/data/README.md).  OpenSpin facts worth knowing:

* ``nop`` is the long ``$00000000`` and takes no condition and no effects.
* ``rdxxxx``/``wrxxxx`` reject ``wr``/``nr`` ("Memory instructions cannot use
  WR/NR"); every other instruction accepts ``wz``, ``wc``, ``wr``, ``nr`` in
  any order, the last of ``wr``/``nr`` winning.
* ``call #label`` puts the address of ``label_ret`` in the destination field.
* Negative operand values are not range-checked: their 32-bit two's
  complement is OR-ed into the word (``mov 5, #-1`` assembles to
  ``$FFFFFFFF``).  :func:`encode` does the same, so images stay
  byte-identical; values above ``$1FF`` are errors.

This module is a shared leaf: it imports nothing from the project.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable, Mapping, Optional

__all__ = [
    "PasmError", "Instruction", "INSTRUCTIONS", "CONDITIONS", "CONDITION_NAMES",
    "EFFECTS", "Effect", "REGISTERS", "REGISTER_NAMES", "FIELDS",
    "Z_BIT", "C_BIT", "R_BIT", "I_BIT", "ZCRI_BITS",
    "DATA_LONG", "Decoded", "encode", "decode", "disassemble", "assemble_line",
]

# ----------------------------------------------------------------------------- fields
#: name -> (lowest bit, width) of each instruction field
FIELDS = {
    "instr": (26, 6), "zcri": (22, 4), "z": (25, 1), "c": (24, 1), "r": (23, 1),
    "i": (22, 1), "cond": (18, 4), "dest": (9, 9), "src": (0, 9),
}
Z_BIT, C_BIT, R_BIT, I_BIT = 1 << 25, 1 << 24, 1 << 23, 1 << 22
#: bit values of z, c, r, i inside the 4-bit zcri field
ZCRI_BITS = {"z": 8, "c": 4, "r": 2, "i": 1}
_MAX_FIELD = 0x1FF


class PasmError(ValueError):
    """An instruction that cannot be encoded, in the user's words.

    Attributes:
        part: which part of the instruction is wrong: ``"mnemonic"``,
            ``"condition"``, ``"effect"``, ``"dest"``, ``"src"`` or
            ``"operands"`` (so a compiler can put its caret there).
        index: for ``part == "effect"``, the position of the bad effect.
    """

    def __init__(self, message: str, part: str = "operands", index: Optional[int] = None):
        super().__init__(message)
        self.message = message
        self.part = part
        self.index = index


# ----------------------------------------------------------------------------- registers
_REGS = ("PAR", "CNT", "INA", "INB", "OUTA", "OUTB", "DIRA", "DIRB",
         "CTRA", "CTRB", "FRQA", "FRQB", "PHSA", "PHSB", "VCFG", "VSCL")
#: register name (upper case) -> cog address $1F0-$1FF
REGISTERS: dict[str, int] = {name: 0x1F0 + i for i, name in enumerate(_REGS)}
#: cog address -> register name
REGISTER_NAMES: dict[int, str] = {a: n for n, a in REGISTERS.items()}

# ----------------------------------------------------------------------------- conditions
# code: names, the first one is what disassembly shows (Propeller Manual v1.2, "Conditions")
_CONDS = {
    0b0000: ("if_never",),
    0b0001: ("if_nc_and_nz", "if_nz_and_nc", "if_a"),
    0b0010: ("if_nc_and_z", "if_z_and_nc"),
    0b0011: ("if_nc", "if_ae"),
    0b0100: ("if_c_and_nz", "if_nz_and_c"),
    0b0101: ("if_nz", "if_ne"),
    0b0110: ("if_c_ne_z", "if_z_ne_c"),
    0b0111: ("if_nc_or_nz", "if_nz_or_nc"),
    0b1000: ("if_c_and_z", "if_z_and_c"),
    0b1001: ("if_c_eq_z", "if_z_eq_c"),
    0b1010: ("if_z", "if_e"),
    0b1011: ("if_nc_or_z", "if_z_or_nc"),
    0b1100: ("if_c", "if_b"),
    0b1101: ("if_c_or_nz", "if_nz_or_c"),
    0b1110: ("if_c_or_z", "if_z_or_c", "if_be"),
    0b1111: ("if_always",),
}
#: every condition prefix (lower case, all aliases) -> 4-bit cccc code
CONDITIONS: dict[str, int] = {name: code for code, names in _CONDS.items() for name in names}
#: 4-bit code -> the name disassembly uses
CONDITION_NAMES: dict[int, str] = {code: names[0] for code, names in _CONDS.items()}
COND_ALWAYS = 0b1111


@dataclass(frozen=True)
class Effect:
    """An effect suffix: sets (or, for ``nr``, clears) one zcri bit."""

    name: str
    bit: int
    value: bool
    doc: str


#: effect name -> :class:`Effect`
EFFECTS: dict[str, Effect] = {
    "wz": Effect("wz", Z_BIT, True, "write the Z flag"),
    "wc": Effect("wc", C_BIT, True, "write the C flag"),
    "wr": Effect("wr", R_BIT, True, "write the result to the destination register"),
    "nr": Effect("nr", R_BIT, False, "do not write the result"),
}

# ----------------------------------------------------------------------------- instructions
# operand forms
BOTH, DEST, SRC, NONE, CALL = "ds", "d", "s", "", "call"


@dataclass(frozen=True)
class Instruction:
    """One PASM mnemonic.

    Attributes:
        mnemonic: lower-case name.
        opcode: the 6-bit ``iiiiii`` field.
        zcri: the 4-bit ``zcri`` field it assembles with before effects (z and
            c are always 0; r is the default write; i is set when fixed).
        operands: ``"ds"`` destination and source, ``"d"`` destination only,
            ``"s"`` source only, ``""`` none, ``"call"`` (source ``#label``,
            destination the address of ``label_ret``).
        fixed_src: the source field for forms that fix it (hub operations,
            ``ret``); ``None`` otherwise.
        kind: ``"alu"``, ``"jump"`` (immediate source is a cog address),
            ``"hub"`` (hub access or hub operation), ``"wait"`` or ``"nop"``.
        cycles: clock cycles as the Propeller Manual v1.2 gives them
            (``"4/8"``: 4 when it jumps, 8 when not; ``"8..23"``: hub access;
            ``"6+"``: at least).
        doc: result and flags in one line (Z is ``result == 0`` where not
            said; for the ALU instructions checked against the vectors in
            tests/data/pasm/alu_vectors.txt).
    """

    mnemonic: str
    opcode: int
    zcri: int
    operands: str
    kind: str
    cycles: str
    doc: str
    fixed_src: Optional[int] = None

    @property
    def writes(self) -> bool:
        """True if the result is written by default (``wr``), False for ``nr``."""
        return bool(self.zcri & ZCRI_BITS["r"])

    @property
    def default_effect(self) -> str:
        """``"wr"`` or ``"nr"``."""
        return "wr" if self.writes else "nr"

    @property
    def fixed_immediate(self) -> bool:
        """True when the ``i`` bit is part of the instruction (hub ops, call, ret)."""
        return bool(self.zcri & ZCRI_BITS["i"])

    @property
    def allows_wr_nr(self) -> bool:
        """OpenSpin rejects ``wr``/``nr`` on rdxxxx/wrxxxx and ``nop``."""
        return not (self.opcode <= 2 and self.kind == "hub") and self.kind != "nop"

    @property
    def base(self) -> int:
        """The word with condition ``if_always`` and all operands zero (``nop``: 0)."""
        if self.kind == "nop":
            return 0
        return ((self.opcode << 26) | (self.zcri << 22) | (COND_ALWAYS << 18)
                | (self.fixed_src or 0))


# mnemonic, iiiiii, zcri, operands, kind, cycles, doc  (Propeller Manual v1.2 master table)
_TABLE = [
    ("wrbyte", 0b000000, 0b0000, BOTH, "hub", "8..23", "write byte D to hub[S]"),
    ("rdbyte", 0b000000, 0b0010, BOTH, "hub", "8..23", "D = byte hub[S] (zero-extended); Z = result == 0"),
    ("wrword", 0b000001, 0b0000, BOTH, "hub", "8..23", "write word D to hub[S]"),
    ("rdword", 0b000001, 0b0010, BOTH, "hub", "8..23", "D = word hub[S] (zero-extended); Z = result == 0"),
    ("wrlong", 0b000010, 0b0000, BOTH, "hub", "8..23", "write long D to hub[S]"),
    ("rdlong", 0b000010, 0b0010, BOTH, "hub", "8..23", "D = long hub[S]; Z = result == 0"),
    ("hubop", 0b000011, 0b0000, BOTH, "hub", "8..23", "hub operation S[2..0] with D"),
    ("clkset", 0b000011, 0b0001, DEST, "hub", "8..23", "set the CLK register to D[7..0]"),
    ("cogid", 0b000011, 0b0011, DEST, "hub", "8..23", "D = this cog's id"),
    ("coginit", 0b000011, 0b0001, DEST, "hub", "8..23",
     "start a cog: D = PAR[31..18] ADDR[17..4] NEW[3] COG[2..0]; wr: D = cog id; C = no cog free"),
    ("cogstop", 0b000011, 0b0001, DEST, "hub", "8..23", "stop cog D[2..0]"),
    ("locknew", 0b000011, 0b0011, DEST, "hub", "8..23", "D = new lock id; C = no lock free"),
    ("lockret", 0b000011, 0b0001, DEST, "hub", "8..23", "return lock D[2..0]"),
    ("lockset", 0b000011, 0b0001, DEST, "hub", "8..23", "set lock D[2..0]; C = its previous state"),
    ("lockclr", 0b000011, 0b0001, DEST, "hub", "8..23", "clear lock D[2..0]; C = its previous state"),
    ("ror", 0b001000, 0b0010, BOTH, "alu", "4", "D = D rotated right by S[4..0]; C = D[0]"),
    ("rol", 0b001001, 0b0010, BOTH, "alu", "4", "D = D rotated left by S[4..0]; C = D[31]"),
    ("shr", 0b001010, 0b0010, BOTH, "alu", "4", "D = D >> S[4..0] (logical); C = D[0]"),
    ("shl", 0b001011, 0b0010, BOTH, "alu", "4", "D = D << S[4..0]; C = D[31]"),
    ("rcr", 0b001100, 0b0010, BOTH, "alu", "4", "D = D >> S[4..0], vacated bits = C; C = D[0]"),
    ("rcl", 0b001101, 0b0010, BOTH, "alu", "4", "D = D << S[4..0], vacated bits = C; C = D[31]"),
    ("sar", 0b001110, 0b0010, BOTH, "alu", "4", "D = D >> S[4..0] (arithmetic); C = D[0]"),
    ("rev", 0b001111, 0b0010, BOTH, "alu", "4", "D = low 32-S[4..0] bits of D reversed, rest 0; C = D[0]"),
    ("mins", 0b010000, 0b0010, BOTH, "alu", "4", "D = max(D, S) signed; C = D < S signed; Z = S == 0"),
    ("maxs", 0b010001, 0b0010, BOTH, "alu", "4", "D = min(D, S) signed; C = D < S signed; Z = S == 0"),
    ("min", 0b010010, 0b0010, BOTH, "alu", "4", "D = max(D, S) unsigned; C = D < S unsigned; Z = S == 0"),
    ("max", 0b010011, 0b0010, BOTH, "alu", "4", "D = min(D, S) unsigned; C = D < S unsigned; Z = S == 0"),
    ("movs", 0b010100, 0b0010, BOTH, "alu", "4", "D[8..0] = S[8..0]; C = D < S unsigned"),
    ("movd", 0b010101, 0b0010, BOTH, "alu", "4", "D[17..9] = S[8..0]; C = D < S unsigned"),
    ("movi", 0b010110, 0b0010, BOTH, "alu", "4", "D[31..23] = S[8..0]; C = D < S unsigned"),
    ("jmpret", 0b010111, 0b0010, BOTH, "jump", "4", "D[8..0] = return address (PC + 1); jump to S"),
    ("jmp", 0b010111, 0b0000, SRC, "jump", "4", "jump to S"),
    ("call", 0b010111, 0b0011, CALL, "jump", "4", "label_ret[8..0] = return address; jump to label"),
    ("ret", 0b010111, 0b0001, NONE, "jump", "4", "jump to the address a call stored in this ret"),
    ("test", 0b011000, 0b0000, BOTH, "alu", "4", "D & S (not written); Z = result == 0; C = parity"),
    ("and", 0b011000, 0b0010, BOTH, "alu", "4", "D = D & S; Z = result == 0; C = parity of result"),
    ("testn", 0b011001, 0b0000, BOTH, "alu", "4", "D & !S (not written); Z = result == 0; C = parity"),
    ("andn", 0b011001, 0b0010, BOTH, "alu", "4", "D = D & !S; Z = result == 0; C = parity of result"),
    ("or", 0b011010, 0b0010, BOTH, "alu", "4", "D = D | S; Z = result == 0; C = parity of result"),
    ("xor", 0b011011, 0b0010, BOTH, "alu", "4", "D = D ^ S; Z = result == 0; C = parity of result"),
    ("muxc", 0b011100, 0b0010, BOTH, "alu", "4", "D bits in mask S = C; Z = result == 0; C = parity"),
    ("muxnc", 0b011101, 0b0010, BOTH, "alu", "4", "D bits in mask S = !C; Z = result == 0; C = parity"),
    ("muxz", 0b011110, 0b0010, BOTH, "alu", "4", "D bits in mask S = Z; Z = result == 0; C = parity"),
    ("muxnz", 0b011111, 0b0010, BOTH, "alu", "4", "D bits in mask S = !Z; Z = result == 0; C = parity"),
    ("add", 0b100000, 0b0010, BOTH, "alu", "4", "D = D + S; C = unsigned carry"),
    ("cmp", 0b100001, 0b0000, BOTH, "alu", "4", "compare D, S unsigned; Z = D == S; C = D < S"),
    ("sub", 0b100001, 0b0010, BOTH, "alu", "4", "D = D - S; C = unsigned borrow"),
    ("addabs", 0b100010, 0b0010, BOTH, "alu", "4", "D = D + |S|; C = unsigned carry (S < 0: borrow of D - S)"),
    ("subabs", 0b100011, 0b0010, BOTH, "alu", "4", "D = D - |S|; C = unsigned borrow (S < 0: carry of D + S)"),
    ("sumc", 0b100100, 0b0010, BOTH, "alu", "4", "D = D - S if C else D + S; C = signed overflow"),
    ("sumnc", 0b100101, 0b0010, BOTH, "alu", "4", "D = D + S if C else D - S; C = signed overflow"),
    ("sumz", 0b100110, 0b0010, BOTH, "alu", "4", "D = D - S if Z else D + S; C = signed overflow"),
    ("sumnz", 0b100111, 0b0010, BOTH, "alu", "4", "D = D + S if Z else D - S; C = signed overflow"),
    ("mov", 0b101000, 0b0010, BOTH, "alu", "4", "D = S; C = S[31]"),
    ("neg", 0b101001, 0b0010, BOTH, "alu", "4", "D = -S; C = S[31]"),
    ("abs", 0b101010, 0b0010, BOTH, "alu", "4", "D = |S|; C = S[31]"),
    ("absneg", 0b101011, 0b0010, BOTH, "alu", "4", "D = -|S|; C = S[31]"),
    ("negc", 0b101100, 0b0010, BOTH, "alu", "4", "D = -S if C else S; C = S[31]"),
    ("negnc", 0b101101, 0b0010, BOTH, "alu", "4", "D = S if C else -S; C = S[31]"),
    ("negz", 0b101110, 0b0010, BOTH, "alu", "4", "D = -S if Z else S; C = S[31]"),
    ("negnz", 0b101111, 0b0010, BOTH, "alu", "4", "D = S if Z else -S; C = S[31]"),
    ("cmps", 0b110000, 0b0000, BOTH, "alu", "4", "compare D, S signed; Z = D == S; C = D < S"),
    ("cmpsx", 0b110001, 0b0000, BOTH, "alu", "4", "compare D, S+C signed; Z = equal and Z; C = D < S+C"),
    ("addx", 0b110010, 0b0010, BOTH, "alu", "4", "D = D + S + C; Z = result == 0 and Z; C = carry"),
    ("cmpx", 0b110011, 0b0000, BOTH, "alu", "4", "compare D, S+C unsigned; Z = equal and Z; C = D < S+C"),
    ("subx", 0b110011, 0b0010, BOTH, "alu", "4", "D = D - (S + C); Z = result == 0 and Z; C = borrow"),
    ("adds", 0b110100, 0b0010, BOTH, "alu", "4", "D = D + S signed; C = signed overflow"),
    ("subs", 0b110101, 0b0010, BOTH, "alu", "4", "D = D - S signed; C = signed overflow"),
    ("addsx", 0b110110, 0b0010, BOTH, "alu", "4", "D = D + S + C signed; Z = result == 0 and Z; C = overflow"),
    ("subsx", 0b110111, 0b0010, BOTH, "alu", "4", "D = D - (S + C) signed; Z = result == 0 and Z; C = overflow"),
    ("cmpsub", 0b111000, 0b0010, BOTH, "alu", "4", "if D >= S then D = D - S; C = subtracted; Z = D == S"),
    ("djnz", 0b111001, 0b0010, BOTH, "jump", "4/8", "D = D - 1; jump to S if D != 0"),
    ("tjnz", 0b111010, 0b0000, BOTH, "jump", "4/8", "jump to S if D != 0"),
    ("tjz", 0b111011, 0b0000, BOTH, "jump", "4/8", "jump to S if D == 0"),
    ("waitpeq", 0b111100, 0b0000, BOTH, "wait", "6+", "wait until INx & S == D"),
    ("waitpne", 0b111101, 0b0000, BOTH, "wait", "6+", "wait until INx & S != D"),
    ("waitcnt", 0b111110, 0b0010, BOTH, "wait", "6+", "wait until CNT == D; D = D + S"),
    ("waitvid", 0b111111, 0b0000, BOTH, "wait", "4+", "wait for the video generator; hand it colors D, pixels S"),
    ("nop", 0b000000, 0b0000, NONE, "nop", "4", "no operation (the long $00000000)"),
]
_HUB_SRC = {"clkset": 0, "cogid": 1, "coginit": 2, "cogstop": 3,
            "locknew": 4, "lockret": 5, "lockset": 6, "lockclr": 7}


def _build() -> dict[str, Instruction]:
    table = {}
    for mnem, opcode, zcri, operands, kind, cycles, doc in _TABLE:
        fixed = _HUB_SRC.get(mnem)
        if mnem == "ret":
            fixed = 0
        table[mnem] = Instruction(mnem, opcode, zcri, operands, kind, cycles, doc, fixed)
    return table


#: lower-case mnemonic -> :class:`Instruction` (every P1 instruction and alias)
INSTRUCTIONS: dict[str, Instruction] = _build()
_I = INSTRUCTIONS
_HUBOP_BY_SRC = {ins.fixed_src: ins for ins in INSTRUCTIONS.values()
                 if ins.opcode == 0b000011 and ins.fixed_src is not None}
#: what :func:`decode` returns for opcodes $04-$07, which have no mnemonic
#: (the manual lists none; OpenSpin cannot assemble them): shown as ``long $xxxxxxxx``
DATA_LONG = Instruction("long", 0, 0, NONE, "data", "", "a long with no instruction mnemonic")
_FAMILY: dict[tuple[int, bool], Instruction] = {}
for _ins in INSTRUCTIONS.values():
    if _ins.operands == BOTH:
        _FAMILY.setdefault((_ins.opcode, _ins.writes), _ins)


# ----------------------------------------------------------------------------- encode
def _lookup(mnemonic: str) -> Instruction:
    ins = INSTRUCTIONS.get(mnemonic.lower())
    if ins is None:
        raise PasmError(f"unknown instruction '{mnemonic}'", "mnemonic")
    return ins


def _field(value: int, what: str, part: str) -> int:
    if value > _MAX_FIELD:
        raise PasmError(f"{what} operand ${value:X} exceeds $1FF", part)
    return value & 0xFFFFFFFF  # negative: two's complement, OR-ed in whole (as OpenSpin does)


def encode(mnemonic: str, *, condition: Optional[str] = None, effects: Iterable[str] = (),
           dest: Optional[int] = None, src: Optional[int] = None, immediate: bool = False) -> int:
    """Assemble one instruction into its 32-bit word, as OpenSpin 1.00.81 does.

    Args:
        mnemonic: any name in :data:`INSTRUCTIONS` (case-insensitive).
        condition: an ``if_xxx`` prefix (case-insensitive) or ``None`` for always.
        effects: ``wz``, ``wc``, ``wr``, ``nr`` in source order (the last of
            wr/nr wins).
        dest: destination register (0..$1FF). For ``call`` it is the address
            of ``label_ret``.
        src: source register, or constant when ``immediate``.
        immediate: the source was written with ``#``.

    Returns:
        The instruction long.

    Raises:
        PasmError: the message names the problem in PASM terms; ``part``
            says which part of the instruction it is about.

    >>> hex(encode("mov", dest=5, src=3, immediate=True))
    '0xa0fc0a03'
    >>> hex(encode("djnz", condition="if_nz", effects=["wz"], dest=5, src=2, immediate=True))
    '0xe6d40a02'
    >>> encode("jmp", dest=1, src=2)
    Traceback (most recent call last):
    ...
    spinemu.pasm.PasmError: instruction 'jmp' takes no destination operand
    """
    ins = _lookup(mnemonic)
    name = ins.mnemonic
    word = ins.base
    if condition is not None:
        code = CONDITIONS.get(condition.lower())
        if code is None:
            raise PasmError(f"unknown condition '{condition}'", "condition")
        if ins.kind == "nop":
            raise PasmError("'nop' cannot have a condition", "condition")
        word = (word & ~(0xF << 18)) | (code << 18)
    for index, eff_name in enumerate(effects):
        eff = EFFECTS.get(eff_name.lower())
        if eff is None:
            raise PasmError(f"unknown effect '{eff_name}' (expected wz, wc, wr or nr)", "effect", index)
        if ins.kind == "nop":
            raise PasmError("'nop' cannot have effects", "effect", index)
        if eff.bit == R_BIT and not ins.allows_wr_nr:
            raise PasmError(f"'{name}' cannot use wr or nr (hub memory instruction)", "effect", index)
        word = (word | eff.bit) if eff.value else (word & ~eff.bit)
    form = ins.operands
    if dest is not None and DEST not in form and form != CALL:
        raise PasmError(f"instruction '{name}' takes no destination operand", "dest")
    if src is not None and SRC not in form and form != CALL:
        raise PasmError(f"instruction '{name}' takes no source operand", "src")
    if immediate and src is None:
        raise PasmError(f"instruction '{name}' has no source operand to make immediate", "src")
    if dest is None and (DEST in form or form == CALL):
        raise PasmError(f"instruction '{name}' needs a destination operand", "dest")
    if src is None and (SRC in form or form == CALL):
        raise PasmError(f"instruction '{name}' needs a source operand", "src")
    if form == CALL and not immediate:
        raise PasmError("'call' needs '#' before its label", "src")
    if dest is not None:
        word |= (_field(dest, "destination", "dest") << 9) & 0xFFFFFFFF
    if src is not None:
        word |= _field(src, "source", "src")
        if immediate:
            word |= I_BIT
    return word


# ----------------------------------------------------------------------------- decode
@dataclass(frozen=True)
class Decoded:
    """A decoded instruction long (see :func:`decode`).

    Attributes:
        word: the long.
        instr: the :class:`Instruction` disassembly shows (aliases resolved).
        zcri: the 4-bit zcri field as stored.
        cond: the 4-bit condition code.
        dest, src: the 9-bit fields.
        immediate: the ``i`` bit.
        effects: the effect suffixes that reproduce ``zcri`` for ``instr``
            (``wz``/``wc`` when set, ``wr``/``nr`` when ``r`` differs from
            the default), in the order ``wz, wc, wr|nr``.
    """

    word: int
    instr: Instruction
    zcri: int
    cond: int
    dest: int
    src: int
    immediate: bool
    effects: tuple

    @property
    def mnemonic(self) -> str:
        return self.instr.mnemonic

    @property
    def opcode(self) -> int:
        """The 6-bit ``iiiiii`` field as stored."""
        return self.word >> 26

    @property
    def condition(self) -> Optional[str]:
        """The condition's disassembly name, ``None`` for ``if_always``."""
        return None if self.cond == COND_ALWAYS else CONDITION_NAMES[self.cond]

    @property
    def writes(self) -> bool:
        """True if the result is written (the ``r`` bit)."""
        return bool(self.zcri & ZCRI_BITS["r"])

    @property
    def jump_target(self) -> Optional[int]:
        """The cog address a jump goes to when it is immediate (``None`` otherwise)."""
        if self.instr.kind == "jump" and self.immediate and self.instr.mnemonic != "ret":
            return self.src
        return None


def decode(word: int) -> Decoded:
    """Split a long into its fields and choose the mnemonic users expect.

    The choice is exact: writing the disassembly back through OpenSpin gives
    the same long for every 32-bit value.  ``$00000000`` is ``nop``; a
    ``jmpret`` with ``nr`` and destination 0 is ``jmp`` (``ret`` when also
    ``#0``); ``and``/``andn``/``sub``/``subx`` with ``nr`` are
    ``test``/``testn``/``cmp``/``cmpx``; ``hubop`` with ``#0..#7`` is
    ``clkset``...``lockclr``.  ``call`` needs symbols (see :func:`disassemble`).

    >>> d = decode(0xE6D40A02)
    >>> d.mnemonic, d.condition, d.dest, d.src, d.immediate, d.effects
    ('djnz', 'if_nz', 5, 2, True, ('wz',))
    >>> decode(0x603C0604).mnemonic, decode(0x5C7C0000).mnemonic
    ('test', 'ret')
    """
    word &= 0xFFFFFFFF
    opcode = word >> 26
    zcri = (word >> 22) & 0xF
    cond = (word >> 18) & 0xF
    dest = (word >> 9) & 0x1FF
    src = word & 0x1FF
    r = bool(zcri & ZCRI_BITS["r"])
    imm = bool(zcri & ZCRI_BITS["i"])
    if word == 0:
        ins = _I["nop"]
    elif opcode == 0b000011 and imm and src in _HUBOP_BY_SRC:
        ins = _HUBOP_BY_SRC[src]
    elif opcode == 0b010111 and not r and dest == 0:
        ins = _I["ret"] if imm and src == 0 else _I["jmp"]
    else:
        ins = _FAMILY.get((opcode, r)) or _FAMILY.get((opcode, not r), DATA_LONG)
    effects = []
    if ins.kind not in ("nop", "data"):
        if zcri & ZCRI_BITS["z"]:
            effects.append("wz")
        if zcri & ZCRI_BITS["c"]:
            effects.append("wc")
        if r != ins.writes:
            effects.append("wr" if r else "nr")
    return Decoded(word, ins, zcri, cond, dest, src, imm, tuple(effects))


# ----------------------------------------------------------------------------- disassemble
def _reg_text(addr: int, symbols: Mapping[int, str]) -> str:
    name = symbols.get(addr)
    if name:
        return name
    return REGISTER_NAMES.get(addr) or f"${addr:03X}"


def disassemble(word: int, address: Optional[int] = None,
                symbols: Optional[Mapping[int, str]] = None, *, ret_as_jmp: bool = False) -> str:
    """One instruction long as PASM text, in columns.

    Columns: label (only when ``address`` is given: the symbol at that
    address, padded to 12), condition (12, blank for ``if_always``), mnemonic
    (7), operands, effects.  Registers ``$1F0-$1FF`` show as ``PAR``..``VSCL``,
    other registers and constants as ``$xxx``.  The text reassembles to the
    same long (OpenSpin accepts it as is).

    Args:
        word: the instruction long.
        address: its cog address, to show its label; ``None`` for no label column.
        symbols: cog address -> name, used for register operands, for the
            immediate targets of jumps, and to show ``call #name`` when the
            destination is ``name_ret`` (otherwise ``jmpret name_ret, #name``).
        ret_as_jmp: show the ``ret`` long (``$5C7C0000`` and its conditional
            forms) as ``jmp #$000``, the same long; for callers that know it is
            no subroutine return.

    >>> disassemble(0xE6D40A02)
    'if_nz        djnz    $005, #$002 wz'
    >>> disassemble(0xA0BFE9F1)
    '             mov     OUTA, CNT'
    >>> disassemble(0x5CFC1007, 5, {5: "start", 7: "blink", 8: "blink_ret"})
    'start                     call    #blink'
    >>> disassemble(0)
    '             nop'
    """
    symbols = symbols or {}
    d = decode(word)
    ins = d.instr
    mnem = ins.mnemonic
    if ins.kind == "data":
        text = f"{'':<12} long    ${d.word:08X}"
        return text if address is None else f"{symbols.get(address, ''):<12} {text}"
    if ins.kind == "jump" and d.immediate:
        src = symbols.get(d.src) or f"${d.src:03X}"
    else:
        src = f"${d.src:03X}" if d.immediate else _reg_text(d.src, symbols)
    src = ("#" if d.immediate else "") + src
    dst = _reg_text(d.dest, symbols)
    form = ins.operands
    if mnem == "ret" and ret_as_jmp:
        mnem, form, src = "jmp", SRC, "#" + (symbols.get(0) or "$000")
    if mnem == "jmpret" and d.immediate and d.writes and d.src in symbols \
            and symbols.get(d.dest, "").lower() == symbols[d.src].lower() + "_ret":
        mnem, form = "call", SRC
    operands = {BOTH: f"{dst}, {src}", DEST: dst, SRC: src, NONE: "", CALL: src}[form]
    cond = "" if d.cond == COND_ALWAYS or ins.kind == "nop" else CONDITION_NAMES[d.cond]
    text = f"{cond:<12} {mnem:<7} {operands}"
    if d.effects:
        text = text.rstrip() + " " + ", ".join(d.effects)
    if address is not None:
        text = f"{symbols.get(address, ''):<12} {text}"
    return text.rstrip()


# ----------------------------------------------------------------------------- assemble one line
_TOKEN = re.compile(r"#|,|[^\s,#]+")


def _value(token: str, symbols: Mapping[str, int]) -> int:
    neg = token.startswith("-")
    t = token[1:] if neg else token
    t = t.replace("_", "") if t[:1] in "$%0123456789" else t
    if t.startswith("$"):
        v = int(t[1:], 16)
    elif t.startswith("%%"):
        v = int(t[2:], 4)
    elif t.startswith("%"):
        v = int(t[1:], 2)
    elif t.isdigit():
        v = int(t)
    elif t.upper() in REGISTERS:
        v = REGISTERS[t.upper()]
    elif t.lower() in {k.lower(): k for k in symbols}:
        v = {k.lower(): a for k, a in symbols.items()}[t.lower()]
    else:
        raise PasmError(f"unknown symbol '{t}'", "operands")
    return -v if neg else v


def assemble_line(text: str, symbols: Optional[Mapping[str, int]] = None) -> int:
    """Assemble one line of PASM (no label) with simple operands, e.g. disassembly output.

    ``long <value>`` (what :func:`disassemble` shows for longs that are no
    instruction) gives the value itself.

    Operands are numbers (``$hex``, ``%bin``, ``%%quaternary``, decimal,
    optionally negative), register names, or names from ``symbols``; no
    expressions.  ``call #name`` takes its destination from ``name_ret``.

    Args:
        text: ``[condition] mnemonic [dest][, [#]src] [effect[, effect]...]``.
        symbols: name -> cog address.

    Raises:
        PasmError: as :func:`encode`, or for text it cannot split.

    >>> hex(assemble_line("if_nz  djnz  $005, #$002 wz"))
    '0xe6d40a02'
    """
    symbols = symbols or {}
    tokens = _TOKEN.findall(text.split("'", 1)[0])
    cond = None
    if tokens and tokens[0].lower() in CONDITIONS:
        cond = tokens.pop(0)
    if not tokens:
        raise PasmError("expected an instruction", "mnemonic")
    mnem = tokens.pop(0)
    if mnem.lower() == "long" and cond is None and len(tokens) == 1:
        return _value(tokens[0], symbols) & 0xFFFFFFFF
    ins = _lookup(mnem)
    effects = []
    first_eff = next((k for k, t in enumerate(tokens) if t.lower() in EFFECTS
                      and (k == 0 or tokens[k - 1] != "#")), len(tokens))
    effects = [t for t in tokens[first_eff:] if t != ","]
    operands: list[list[str]] = [[]]
    for t in tokens[:first_eff]:
        if t == ",":
            operands.append([])
        else:
            operands[-1].append(t)
    operands = [op for op in operands if op]
    kw: dict = {}
    for op, role in zip(operands, _roles(ins, len(operands))):
        if op[0] == "#":
            kw["immediate"] = True
            op = op[1:]
        if len(op) != 1:
            raise PasmError(f"cannot read operand {' '.join(op)!r}", role)
        kw[role] = _value(op[0], symbols)
        if ins.operands == CALL:
            kw["dest"] = _value(op[0] + "_ret", symbols)
    return encode(mnem, condition=cond, effects=effects, **kw)


def _roles(ins: Instruction, count: int) -> list[str]:
    form = ins.operands
    if form == BOTH or count == 2:
        return ["dest", "src"]
    if form == DEST:
        return ["dest"]
    return ["src"]
