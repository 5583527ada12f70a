"""PASM instructions as data and as code: the ALU table and the handler generator.

The PASM cog (:mod:`.pasm_cog`) runs a cog by calling, for each instruction
long, a small Python function that does exactly what that long does.  This
module makes those functions:

* :data:`ALU` is every ALU instruction as Python expressions over ``d``,
  ``s``, ``c``, ``z`` (result, C, Z), checked against the vectors measured on
  spinsim in tests/data/pasm/alu_vectors.txt;
* :data:`FAMILIES` maps each 6-bit opcode to what runs it, derived from
  :data:`spinemu.pasm.INSTRUCTIONS` (the table the assembler and the
  disassembler read);
* :class:`HandlerBuilder` writes the handler of one long from them: the
  condition, the operands and special registers, the effects (``wz wc wr
  nr``) and the timing folded in, compiled once per *shape* and bound to
  the long's D and S fields.

A block compiler can read the same table and the same operand rules.

The handler protocol (cog RAM layout, return values, the exceptions) is
described on :class:`HandlerBuilder`; the timing facts on
:mod:`.pasm_cog`.
"""
from __future__ import annotations

import re
from typing import Callable, NamedTuple, Optional

from .. import pasm as isa
from .blocks import BUSY, PROGRAM, WATCHPOINT

__all__ = ["ALU", "AluOp", "JUMPS", "JumpOp", "CONDITION_EXPRS", "FAMILIES", "HandlerBuilder", "Handlers", "Yield", "Leave", "Fetched",
           "RAM_SLOTS", "FLAGS", "PAR_REAL", "HUB_PHASE", "COG", "AUX", "PIN_MODES", "never"]

M = 0xFFFFFFFF
#: cog RAM slots after the 512 longs (see the module docstring)
FLAGS, PAR_REAL, HUB_PHASE, COG, AUX = 512, 513, 514, 515, 516
RAM_SLOTS = 517
#: distinct instruction longs kept compiled before the cache starts over (code that runs data)
MAX_HANDLERS = 1 << 16
#: counter modes whose PHS depends on the pins (POS/NEG detectors, edge counters, logic modes)
PIN_MODES = frozenset(range(0b01000, 0b11111))
_REG = {name: addr for name, addr in isa.REGISTERS.items()}
_PAR, _CNT, _INA, _INB, _OUTA, _OUTB, _DIRA, _DIRB = (_REG[n] for n in
                                                      ("PAR", "CNT", "INA", "INB", "OUTA", "OUTB", "DIRA", "DIRB"))
_PHSA, _PHSB = _REG["PHSA"], _REG["PHSB"]


class AluOp(NamedTuple):
    """One ALU instruction as Python text over ``d``, ``s``, ``c``, ``z`` (longs and flags).

    ``prelude`` runs first (may be empty), ``result`` is the long written to
    D, ``carry`` and ``zero`` the new C and Z (``zero`` ``None``: ``r == 0``,
    with ``r`` the result).  ``M`` is ``$FFFFFFFF``, ``SB`` ``$80000000``,
    ``REV(x)`` reverses 32 bits, ``r.bit_count() & 1`` is the parity.
    """

    prelude: str
    result: str
    carry: str
    zero: Optional[str] = None


_PARITY = "r.bit_count() & 1"
_ADD_V = "((d ^ r) & (s ^ r)) >> 31"          # signed overflow of d + s (+ c)
_SUB_V = "((d ^ s) & (d ^ r)) >> 31"          # signed overflow of d - s (- c)
_SUM_V = "((d ^ r) & ((d ^ s) if {sub} else (s ^ r))) >> 31"
_CHAIN_Z = "z and r == 0"                      # extended instructions: Z stays set only if it was

#: mnemonic -> :class:`AluOp` for every ALU instruction (aliases with ``nr``
#: such as ``test``/``cmp`` share their ``and``/``sub`` entry by opcode)
ALU: dict[str, AluOp] = {
    "ror": AluOp("n = s & 31", "((d >> n) | (d << (32 - n))) & M", "d & 1"),
    "rol": AluOp("n = s & 31", "((d << n) | (d >> (32 - n))) & M", "d >> 31"),
    "shr": AluOp("", "d >> (s & 31)", "d & 1"),
    "shl": AluOp("", "(d << (s & 31)) & M", "d >> 31"),
    "rcr": AluOp("n = s & 31", "(d >> n) | ((M << (32 - n)) & M if c else 0)", "d & 1"),
    "rcl": AluOp("n = s & 31", "((d << n) & M) | ((1 << n) - 1 if c else 0)", "d >> 31"),
    "sar": AluOp("", "((d - ((d & SB) << 1)) >> (s & 31)) & M", "d & 1"),
    "rev": AluOp("", "REV(d) >> (s & 31)", "d & 1"),
    "mins": AluOp("", "s if (d ^ SB) < (s ^ SB) else d", "(d ^ SB) < (s ^ SB)", "s == 0"),
    "maxs": AluOp("", "s if (d ^ SB) > (s ^ SB) else d", "(d ^ SB) < (s ^ SB)", "s == 0"),
    "min": AluOp("", "s if d < s else d", "d < s", "s == 0"),
    "max": AluOp("", "s if d > s else d", "d < s", "s == 0"),
    "movs": AluOp("", "(d & 0xFFFFFE00) | (s & 0x1FF)", "d < s"),
    "movd": AluOp("", "(d & 0xFFFC01FF) | ((s & 0x1FF) << 9)", "d < s"),
    "movi": AluOp("", "(d & 0x007FFFFF) | ((s & 0x1FF) << 23)", "d < s"),
    "and": AluOp("", "d & s", _PARITY),
    "andn": AluOp("", "d & (s ^ M)", _PARITY),
    "or": AluOp("", "d | s", _PARITY),
    "xor": AluOp("", "d ^ s", _PARITY),
    "muxc": AluOp("", "(d & (s ^ M)) | (s if c else 0)", _PARITY),
    "muxnc": AluOp("", "(d & (s ^ M)) | (0 if c else s)", _PARITY),
    "muxz": AluOp("", "(d & (s ^ M)) | (s if z else 0)", _PARITY),
    "muxnz": AluOp("", "(d & (s ^ M)) | (0 if z else s)", _PARITY),
    "add": AluOp("x = d + s", "x & M", "x >> 32"),
    "sub": AluOp("", "(d - s) & M", "d < s"),
    # D + |S| is done as D - S when S is negative, so C is then that borrow (and the other way round)
    "addabs": AluOp("x = d - s if s >> 31 else d + s", "x & M", "x < 0 or x > M"),
    "subabs": AluOp("x = d + s if s >> 31 else d - s", "x & M", "x < 0 or x > M"),
    "sumc": AluOp("", "(d - s if c else d + s) & M", _SUM_V.format(sub="c")),
    "sumnc": AluOp("", "(d + s if c else d - s) & M", _SUM_V.format(sub="not c")),
    "sumz": AluOp("", "(d - s if z else d + s) & M", _SUM_V.format(sub="z")),
    "sumnz": AluOp("", "(d + s if z else d - s) & M", _SUM_V.format(sub="not z")),
    "mov": AluOp("", "s", "s >> 31"),
    "neg": AluOp("", "(-s) & M", "s >> 31"),
    "abs": AluOp("", "(-s) & M if s >> 31 else s", "s >> 31"),
    "absneg": AluOp("", "s if s >> 31 else (-s) & M", "s >> 31"),
    "negc": AluOp("", "(-s) & M if c else s", "s >> 31"),
    "negnc": AluOp("", "s if c else (-s) & M", "s >> 31"),
    "negz": AluOp("", "(-s) & M if z else s", "s >> 31"),
    "negnz": AluOp("", "s if z else (-s) & M", "s >> 31"),
    "cmps": AluOp("", "(d - s) & M", "(d ^ SB) < (s ^ SB)"),
    "cmpsx": AluOp("", "(d - s - c) & M", "(d ^ SB) < (s ^ SB) + c", _CHAIN_Z),
    "addx": AluOp("x = d + s + c", "x & M", "x >> 32", _CHAIN_Z),
    "subx": AluOp("", "(d - s - c) & M", "d < s + c", _CHAIN_Z),
    "adds": AluOp("", "(d + s) & M", _ADD_V),
    "subs": AluOp("", "(d - s) & M", _SUB_V),
    "addsx": AluOp("", "(d + s + c) & M", _ADD_V, _CHAIN_Z),
    "subsx": AluOp("", "(d - s - c) & M", _SUB_V, _CHAIN_Z),
    "cmpsub": AluOp("ok = d >= s", "d - s if ok else d", "ok", "d == s"),
}


class JumpOp(NamedTuple):
    """One jump instruction as Python text over ``d``, ``s``, ``pc`` (the jump's own address).

    ``result`` is the long written to D (with ``wr``), ``carry`` and ``zero``
    the new C and Z (``r`` is the result), ``taken`` whether it jumps to
    ``S[8..0]``: 4 cycles when it does, 8 when not (``jmpret`` always jumps).
    """

    result: str
    carry: str
    zero: str
    taken: str


#: the jump families: ``jmpret`` (``jmp``, ``call``, ``ret``), ``djnz``, ``tjnz``, ``tjz``
JUMPS: dict[str, JumpOp] = {
    "jmpret": JumpOp("(d & 0xFFFFFE00) | ((pc + 1) & 511)", "d < s", "r == 0", "True"),
    "djnz": JumpOp("(d - 1) & M", "d == 0", "r == 0", "r"),
    "tjnz": JumpOp("d", "0", "d == 0", "d"),
    "tjz": JumpOp("d", "0", "d == 0", "not d"),
}


def _condition_exprs() -> list:
    """Per 4-bit condition field, a Python expression over flags ``c`` and ``z`` (0/1 or bools).

    The field is a truth table: bit ``(C << 1) | Z`` says whether the instruction runs.
    """
    shapes = ["False", "not c and not z", "not c and z", "not c", "c and not z", "not z", "c != z",
              "not c or not z", "c and z", "c == z", "z", "not c or z", "c", "c or not z", "c or z", "True"]
    out = []
    for cond in range(16):
        for e in shapes:
            if all(bool(eval(e, {}, {"c": cc, "z": zz})) == bool((cond >> ((cc << 1) | zz)) & 1)
                   for cc in (0, 1) for zz in (0, 1)):
                out.append(e)
                break
    return out


#: condition field -> Python expression over ``c`` and ``z`` (``"True"``: always, ``"False"``: never)
CONDITION_EXPRS = _condition_exprs()
assert len(CONDITION_EXPRS) == 16


def _rev32(x: int) -> int:
    """The 32 bits of ``x`` in reverse order (REV's first step)."""
    return int(f"{x:032b}"[::-1], 2)


def _family_table() -> list:
    """Per 6-bit opcode, what runs it, derived from :data:`spinemu.pasm.INSTRUCTIONS`."""
    fam: list = [("undefined", None)] * 64
    for ins in isa.INSTRUCTIONS.values():
        op = ins.opcode
        if ins.kind == "alu":
            if fam[op][0] != "alu" or ins.writes:
                fam[op] = ("alu", ins.mnemonic)
        elif ins.kind == "jump":
            fam[op] = ("jump", "jmpret" if op == isa.INSTRUCTIONS["jmpret"].opcode else ins.mnemonic)
        elif ins.kind == "hub":
            fam[op] = ("hubop", None) if op == isa.INSTRUCTIONS["hubop"].opcode else ("mem", op)
        elif ins.kind == "wait":
            fam[op] = ("wait", ins.mnemonic)
    return fam


#: opcode -> ``(family, detail)``: ``alu`` (mnemonic), ``jump`` (jmpret/djnz/tjnz/tjz), ``mem``
#: (0 byte, 1 word, 2 long), ``hubop``, ``wait`` (mnemonic), ``undefined`` (opcodes 4-7)
FAMILIES = _family_table()
_MISSING_ALU = {m for f, m in FAMILIES if f == "alu"} - set(ALU)
assert not _MISSING_ALU, f"ALU table lacks {_MISSING_ALU}"



class Yield(Exception):
    """Raised by a hub operation before its shared access at or past ``until``: it did not run."""

    def __init__(self, key: int):
        self.key = key


class Leave(Exception):
    """Raised by a handler after it ran: the scheduler must look again.

    ``x`` is the packed next state ``(t << 9) | pc``, or ``None`` when the
    handler already left the cog as it should be (stopped, waiting, restarted).
    """

    def __init__(self, x):
        self.x = x


class Fetched(Exception):
    """A jump wrote the long it jumps to: the old long runs next (the pipeline fetched it first)."""

    def __init__(self, x: int, word: int):
        self.x = x
        self.word = word


class Handlers(dict):
    """Instruction long -> handler; a missing long is compiled on first use."""

    def __init__(self, build: Callable[[int], Callable]):
        super().__init__()
        self.build = build

    def __missing__(self, word: int):
        if len(self) >= MAX_HANDLERS:
            self.clear()
        h = self[word] = self.build(word)
        return h


def _uses(expr: str, name: str) -> bool:
    return re.search(rf"\b{name}\b", expr) is not None


class HandlerBuilder:
    """Writes the Python handler of one instruction long.

    A handler is called as ``h(R, pc, t)`` (cog RAM, the instruction's cog
    address, its first cycle) and returns

    * ``None``: the next instruction follows 4 cycles later;
    * the packed next state ``(t_next << 9) | pc_next``;
    * ``-1 - key`` when its access to shared state at cycle ``key`` comes at
      or after the scheduler's ``until`` (``U[0]``): it did *not* run.

    Rare outcomes are exceptions: :class:`Leave` (it ran, and the scheduler
    must look again), :class:`Fetched` (a jump wrote its own target),
    :class:`Yield` (a hub operation's turn has not come).  Handlers are made
    per *shape* (opcode, effects, condition, which special registers it
    touches) from source text compiled once, and per long by binding the D
    and S fields.

    Args:
        engine: the :class:`PasmEngine` whose chip the handlers act on.
    """

    def __init__(self, engine: "PasmEngine"):
        chip = engine.chip
        self.engine = engine
        self.spinsim = chip.spinsim
        self.factories: dict = {}
        self.env = {
            "M": M, "SB": 0x80000000, "REV": _rev32, "U": engine.until, "LEAVE": Leave,
            "FETCHED": Fetched, "CH": chip, "WREG": chip.registers.write, "INA": chip.ina,
            "PHS": chip.counters.phs, "PIN_MODES": PIN_MODES, "MEM": chip.mem, "W": chip.mem_words,
            "L": chip.mem_longs, "WATCH": chip.watch, "SEEN": BUSY | PROGRAM | WATCHPOINT, "ENG": engine,
        }

    # ------------------------------------------------------------------ per long
    def build(self, word: int) -> Callable:
        """The handler for instruction long ``word``."""
        opcode = word >> 26
        fam, detail = FAMILIES[opcode]
        cond = (word >> 18) & 15
        if cond == 0:
            return never
        dest, src = (word >> 9) & 0x1FF, word & 0x1FF
        imm = bool(word & isa.I_BIT)
        if fam in ("hubop", "undefined"):
            return self.engine.make_hubop(word)
        extra = None
        if fam == "jump" and imm:
            extra = dest == src
        shape = (word >> 18, dest if dest >= 0x1F0 else -1, src if not imm and src >= 0x1F0 else -1, extra)
        factory = self.factories.get(shape)
        if factory is None:
            factory = self.factories[shape] = self._factory(word, fam, detail)
        return factory(dest, src)

    def _factory(self, word: int, fam: str, detail) -> Callable:
        body = getattr(self, "_body_" + fam)(word, detail)
        lines = ["def make(D, S):", "    def h(R, pc, t):"]
        cond = (word >> 18) & 15
        if cond != 15:
            lines.append("        F = R[512]")
            lines.append(f"        if not ({cond} >> F) & 1: return None")
        elif any(_uses(x, "F") for x in body):
            lines.append("        F = R[512]")
        lines += ["        " + x for x in body]
        lines.append("        return None")
        lines.append("    return h")
        src = "\n".join(lines) + "\n"
        src = re.sub(r"\bM\b", "0xFFFFFFFF", re.sub(r"\bSB\b", "0x80000000", src))   # constants, not globals
        ns: dict = {}
        exec(compile(src, f"<pasm {fam} {detail} ${word >> 18:04X}>", "exec"), self.env, ns)
        make = ns["make"]
        make.source = src
        return make

    # ------------------------------------------------------------------ operands
    def _source(self, word: int, checks: list) -> str:
        """The expression for S (register, special register or constant); shared reads add a check."""
        src = word & 0x1FF
        if word & isa.I_BIT:
            return "S"
        if src < 0x1F0:
            return "R[S]"
        if src == _PAR:
            return "R[S]" if self.spinsim else "R[513]"       # spinsim: PAR is a plain register
        if src == _CNT:
            return "t & M"
        if src == _INA:
            checks.append("if t >= U[0]: return -1 - t")
            return "INA(t)"
        if src == _INB:
            return "R[S]" if self.spinsim else "0"            # no port B on the P8X32A
        if src in (_PHSA, _PHSB):
            ab = src - _PHSA
            checks.append(f"if (R[{0x1F8 + ab}] >> 26) & 31 in PIN_MODES and t >= U[0]: return -1 - t")
            return f"PHS(R[515], {ab}, t)"
        return "R[S]"                                          # mirrored registers

    @staticmethod
    def _dest_write(word: int, value: str, when: str, after: str, checks: list, commit: list) -> None:
        """Write ``value`` to D: plain RAM, shadow RAM, or a register others see (checked first).

        ``when`` is the cycle the register changes, ``after`` the packed next
        state (for leaving when the write woke another cog).
        """
        dest = (word >> 9) & 0x1FF
        if dest < 0x1F0 or dest <= _INB:
            commit.append(f"R[D] = {value}")
            return
        if dest in (_OUTA, _DIRA):
            checks.append(f"if {value} != R[D] and t >= U[0]: return -1 - t")
            commit += [f"if {value} != R[D]:",
                       f"    R[D] = {value}",
                       f"    WREG(R[515], D, {value}, {when})",
                       f"    if CH._preempt: CH._end_preemption(); raise LEAVE({after})"]
            return
        if 0x1F8 <= dest <= 0x1FD:                 # counters: their pins and PHS
            checks.append("if t >= U[0]: return -1 - t")
            commit += [f"R[D] = {value}", f"WREG(R[515], D, {value}, {when})",
                       f"if CH._preempt: CH._end_preemption(); raise LEAVE({after})"]
            return
        commit += [f"R[D] = {value}", f"WREG(R[515], D, {value}, {when})"]   # OUTB, DIRB, VCFG, VSCL

    @staticmethod
    def _flags(word: int, carry: Optional[str], zero: Optional[str]) -> list:
        wz, wc = bool(word & isa.Z_BIT), bool(word & isa.C_BIT)
        if wz and wc:
            return [f"R[512] = (({carry}) << 1) | ({zero})"]
        if wc:
            return [f"R[512] = (F & 1) | (({carry}) << 1)"]
        if wz:
            return [f"R[512] = (F & 2) | ({zero})"]
        return []

    @staticmethod
    def _flag_reads(exprs) -> list:
        out = []
        if any(_uses(e, "c") for e in exprs):
            out.append("c = F >> 1")
        if any(_uses(e, "z") for e in exprs):
            out.append("z = F & 1")
        return out

    # ------------------------------------------------------------------ families
    def _body_alu(self, word: int, mnemonic: str) -> list:
        op = ALU[mnemonic]
        wr = bool(word & isa.R_BIT)
        zero = op.zero or "r == 0"
        wz, wc = bool(word & isa.Z_BIT), bool(word & isa.C_BIT)
        used = [op.prelude, op.result] + ([op.carry] if wc else []) + ([zero] if wz else [])
        checks: list = []
        body: list = []
        s_expr = self._source(word, checks)
        if any(_uses(e, "d") for e in used):
            body.append("d = R[D]")
        if any(_uses(e, "s") for e in used):
            body.append(f"s = {s_expr}")
        elif checks:
            body.append(s_expr)                     # a shared read still happens
        body = checks + body                        # shared reads are checked before any work
        body += self._flag_reads(used)
        if op.prelude:
            body.append(op.prelude)
        if wr or wz or (wc and _uses(op.carry, "r")):
            body.append(f"r = {op.result}")
        checks2: list = []
        commit: list = []
        if wr:
            self._dest_write(word, "r", "t + 4", "((t + 4) << 9) | ((pc + 1) & 511)", checks2, commit)
        return body + checks2 + self._flags(word, op.carry, zero) + commit

    def _body_jump(self, word: int, kind: str) -> list:
        wr = bool(word & isa.R_BIT)
        imm = bool(word & isa.I_BIT)
        dest, src = (word >> 9) & 0x1FF, word & 0x1FF
        op = JUMPS[kind]
        checks: list = []
        s_expr = self._source(word, checks)
        body = checks + ["d = R[D]"]
        nxt = "((t + 8) << 9) | ((pc + 1) & 511)"       # not taken: 8 cycles
        if kind == "jmpret":                            # C compares with S: read it first
            body += [f"s = {s_expr}", f"r = {op.result}"]
        else:
            body += [f"r = {op.result}", "s = S" if imm else f"s = {s_expr}"]
        carry, zero, taken = op.carry, op.zero, op.taken
        go = "((t + 4) << 9) | (s & 511)"
        checks2: list = []
        commit: list = []
        if wr:
            after = go if taken == "True" else f"({go}) if {taken} else {nxt}"
            self._dest_write(word, "r", "t + 4", after, checks2, commit)
        body += checks2 + self._flags(word, carry, zero) + commit
        # the pipeline fetched the target before this instruction wrote it: the old long runs
        if wr and kind in ("jmpret", "djnz") and dest < 0x1F0 and (not imm or dest == src):
            fetched = f"raise FETCHED({go}, d)"
            if not imm:
                fetched = f"if (s & 511) == D: {fetched}"
            pre = [fetched]
        else:
            pre = []
        if taken == "True":
            return body + pre + [f"return {go}"]
        return body + [f"if {taken}:"] + ["    " + x for x in pre] + [f"    return {go}", f"return {nxt}"]

    def _body_mem(self, word: int, size: int) -> list:
        read = bool(word & isa.R_BIT)
        checks: list = []
        s_expr = self._source(word, checks)
        body = checks + ["key = t + 8", "key += (R[514] - key) & 15",
                         "if key >= U[0]: return -1 - key", f"a = {s_expr}"]
        nxt = "(key << 9) | ((pc + 1) & 511)"
        if read:
            body.append(("r = MEM[a & 0xFFFF]", "r = W[(a & 0xFFFE) >> 1]", "r = L[(a & 0xFFFC) >> 2]")[size])
            commit: list = []
            self._dest_write(word, "r", "key", nxt, [], commit)
            return body + self._flags(word, "0", "r == 0") + commit + [f"return {nxt}"]
        store = ("MEM[a] = d & 0xFF", "W[a >> 1] = d & 0xFFFF", "L[a >> 2] = d")[size]
        mask = (0xFFFF, 0xFFFE, 0xFFFC)[size]
        body += ["d = R[D]", f"a &= {mask}"]
        body += self._flags(word, "0", "F & 1")             # C cleared, Z kept (as spinsim)
        body += ["if a < 0x8000:",
                 "    if WATCH[a >> 2] & SEEN:",
                 f"        CH.pasm_write_hit(R[515], a, {1 << size}, t, key, pc)",
                 f"        {store}",
                 f"        if CH._preempt: CH._end_preemption(); raise LEAVE({nxt})",
                 f"    {store}",
                 f"return {nxt}"]
        return body

    def _body_wait(self, word: int, kind: str) -> list:
        checks: list = []
        s_expr = self._source(word, checks)
        body = checks + ["d = R[D]", f"s = {s_expr}"]
        nxt = "(pc + 1) & 511"
        if kind == "waitcnt":
            # ends on the first cycle of the cog's 4-cycle grid at or after the target (3 back still count)
            body += ["e = t + (((d - t + 3) & M) & ~3)"]
            if not word & isa.I_BIT and word & 0x1FF == _CNT:
                body.append("s = e & M")                # CNT as S is read when the wait ends
            body += ["x = d + s", "r = x & M"]
            commit: list = []
            if word & isa.R_BIT:
                self._dest_write(word, "r", "e + 4", f"((e + 4) << 9) | {nxt}", body, commit)
            return body + self._flags(word, "x >> 32", "r == 0") + commit + [f"return ((e + 4) << 9) | {nxt}"]
        wr = bool(word & isa.R_BIT)
        if kind == "waitvid":                   # wr writes 0 (as spinsim)
            commit = []
            if wr:
                self._dest_write(word, "0", "t + 4", f"((t + 4) << 9) | {nxt}", body, commit)
            if self.spinsim:                    # spinsim has no video generator: 4 cycles
                return body + commit
            return body + commit + ["return ENG.waitvid(R, pc, t)"]
        # WAITPEQ/WAITPNE: Z as if D - (INA & S) were the result (0 for a met WAITPEQ), C = 0;
        # wr writes that result
        equal = kind == "waitpeq"
        body = ["if t >= U[0]: return -1 - t"] + body
        body += self._flags(word, "0", "1" if equal else "0")
        test = "==" if equal else "!="
        body.append("x = INA(t) & s")
        commit = []
        if wr:
            self._dest_write(word, "(d - x) & M", "t + 4", f"((t + 4) << 9) | {nxt}", [], commit)
        body += [f"if x {test} d:"] + ["    " + c for c in commit] + [f"    return ((t + 4) << 9) | {nxt}"]
        body.append(f"ENG.wait_pins(R, pc, t, s, d, {equal}, {(word >> 9) & 0x1FF if wr else -1})")
        return body


def never(R, pc, t):
    """Handler of an instruction whose condition is ``if_never`` (4 cycles, nothing happens)."""
    return None
