"""PASM cogs: Propeller 1 assembly run instruction by instruction, to the cycle.

A cog started on code other than the ROM's Spin interpreter (``cognew(@entry,
par)`` from Spin, ``COGINIT`` from PASM) loads 496 longs from hub RAM into its
cog RAM and runs them (Propeller Manual v1.2, "Assembly Language Reference").
:class:`PasmEngine` is the cog's engine: the chip's scheduler
(:mod:`.scheduler`) calls :meth:`PasmEngine.run` and :meth:`PasmEngine.key`
for it, as for any engine object, so Spin and PASM cogs share one clock, one
hub, one set of pins, the locks and each other's COGINIT/COGSTOP.

**Instructions are data.**  :mod:`spinemu.pasm` is the instruction table (the
assembler and disassembler read it too); :data:`ALU` gives every ALU
instruction's result, C and Z as Python expressions over ``d``, ``s``, ``c``,
``z`` (checked against the vectors measured on spinsim in
tests/data/pasm/alu_vectors.txt).  From the two, :class:`HandlerBuilder` writes
one small Python function per distinct instruction long (condition, operands,
special registers, effects and timing folded in) and caches it by the long,
so self-modifying code needs no bookkeeping.  A block compiler can read the
same table.

**Cog RAM** is a plain list of 512 ints, plus four slots after it:
``[512]`` the flags ``C << 1 | Z``, ``[513]`` the real PAR, ``[514]`` the
cog's hub phase, ``[515]`` the :class:`~spinemu.chip.cog.Cog`.  ``$1F0-$1FF``
hold the registers' shadow RAM: OUTA, DIRA, CTRx, FRQx, VCFG, VSCL mirror
their registers; PAR, CNT, INA, INB and PHSx as *destination* read this
shadow (what an instruction last wrote there), as *source* the register.

**Timing** (measured on spinsim 0.99 ``-p``, tests/data/chip/pasm): 4 cycles per
instruction; ``djnz``/``tjz``/``tjnz`` 4 when they jump, 8 when not; a false
condition 4; a hub instruction starting at ``t`` ends at the first cycle
``>= t + 8`` on the cog's hub window; ``waitcnt`` ends on the first cycle of
the cog's 4-cycle grid at or after its target (a target up to 3 cycles back
still counts) and the next instruction starts 4 later; ``waitpeq``/``waitpne``
poll INA every 4 cycles.  The instruction after one that writes cog RAM was
fetched before the write (the P1 pipeline): it runs its old value.

**Scheduling.**  Only some instructions touch state other cogs share: hub
instructions (at their hub window), INA reads, OUTA/DIRA writes that change
them, counter writes, PHS reads of a counter in a pin-reading mode,
``waitpeq``/``waitpne``.  A PASM cog runs ahead freely through the others
(its own cog RAM, CNT, ``waitcnt``) and stops only before a shared access at
or past the scheduler's ``until``; its key is that access's cycle.  A cog
whose write reaches the same pins or hub long in the same cycle as another
cog's read goes first when its id is lower (as spinsim steps its cogs).

**Hot paths:** :meth:`PasmEngine.run` (one dict lookup of the instruction
long, one call, no flag checks) and the generated handlers.
:meth:`PasmEngine.run_traced` is its instrumented twin (``--trace-cog``).
"""
from __future__ import annotations

import re
from typing import Callable, NamedTuple, Optional

from .. import pasm as isa
from .blocks import BUSY
from .cog import PIN_WAIT, RUNNING, STOPPED
from .control import RebootRequested

__all__ = ["PasmEngine", "HandlerBuilder", "ALU", "AluOp", "PasmStep", "RAM_SLOTS",
           "FLAGS", "PAR_REAL", "HUB_PHASE", "COG"]

M = 0xFFFFFFFF
#: cog RAM slots after the 512 longs (see the module docstring)
FLAGS, PAR_REAL, HUB_PHASE, COG = 512, 513, 514, 515
RAM_SLOTS = 516
#: longs a started cog loads from hub RAM ($000-$1EF)
LOAD_LONGS = 496
#: cycles a PASM cog may run past the scheduler's ``until`` through instructions only it sees
RUN_AHEAD = 1 << 16
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


class PasmStep(NamedTuple):
    """One executed instruction, as :meth:`PasmEngine.run_traced` reports it.

    ``cycle`` its first cycle, ``pc`` its cog address, ``word`` the long,
    ``executed`` False when its condition was false, ``z``/``c`` the flags
    after it, ``result`` the value it wrote to D (``None``: it wrote none).
    """

    cycle: int
    cog: int
    pc: int
    word: int
    executed: bool
    z: int
    c: int
    result: Optional[int]

    def text(self) -> str:
        """One log line: cycle, cog, address, disassembly, flags, written value."""
        dis = " ".join(isa.disassemble(self.word).split())
        tail = f"Z={self.z} C={self.c}"
        if not self.executed:
            tail = "(condition false) " + tail
        elif self.result is not None:
            tail += f" -> ${self.result:08X}"
        return f"{self.cycle:>12} cog {self.cog} ${self.pc:03X}  {dis:<36} {tail}"


class _Yield(Exception):
    """Raised by a handler before a shared access at or past ``until``: the instruction did not run."""

    def __init__(self, key: int):
        self.key = key


class _Leave(Exception):
    """Raised by a handler after it ran: the scheduler must look again.

    ``x`` is the packed next state ``(t << 9) | pc``, or ``None`` when the
    handler already left the cog as it should be (stopped, waiting, restarted).
    """

    def __init__(self, x):
        self.x = x


class _Fetched(Exception):
    """A jump wrote the long it jumps to: the old long runs next (the pipeline fetched it first)."""

    def __init__(self, x: int, word: int):
        self.x = x
        self.word = word


class _Handlers(dict):
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
    address, its first cycle) and returns ``None`` for "the next instruction
    follows 4 cycles later", else the packed next state ``(t_next << 9) |
    pc_next``.  Handlers are made per *shape* (opcode, effects, condition,
    which special registers it touches) from source text compiled once, and
    per long by binding the D and S fields.

    Args:
        engine: the :class:`PasmEngine` whose chip the handlers act on.
    """

    def __init__(self, engine: "PasmEngine"):
        chip = engine.chip
        self.engine = engine
        self.spinsim = chip.spinsim
        self.factories: dict = {}
        self.env = {
            "M": M, "SB": 0x80000000, "REV": _rev32, "U": engine.until, "Y": _Yield, "LEAVE": _Leave,
            "FETCHED": _Fetched, "CH": chip, "WREG": chip.registers.write, "INA": chip.ina,
            "PHS": chip.counters.phs, "PIN_MODES": PIN_MODES, "MEM": chip.mem, "W": chip.mem_words,
            "L": chip.mem_longs, "WATCH": chip.watch, "BUSY": BUSY, "ENG": engine,
        }

    # ------------------------------------------------------------------ per long
    def build(self, word: int) -> Callable:
        """The handler for instruction long ``word``."""
        opcode = word >> 26
        fam, detail = FAMILIES[opcode]
        cond = (word >> 18) & 15
        if cond == 0:
            return _never
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
            checks.append("if t >= U[0]: raise Y(t)")
            return "INA(t)"
        if src == _INB:
            return "R[S]" if self.spinsim else "0"            # no port B on the P8X32A
        if src in (_PHSA, _PHSB):
            ab = src - _PHSA
            checks.append(f"if (R[{0x1F8 + ab}] >> 26) & 31 in PIN_MODES and t >= U[0]: raise Y(t)")
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
            checks.append(f"if {value} != R[D] and t >= U[0]: raise Y(t)")
            commit += [f"if {value} != R[D]:",
                       f"    R[D] = {value}",
                       f"    WREG(R[515], D, {value}, {when})",
                       f"    if CH._preempt: CH._end_preemption(); raise LEAVE({after})"]
            return
        if 0x1F8 <= dest <= 0x1FD:                 # counters: their pins and PHS
            checks.append("if t >= U[0]: raise Y(t)")
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
        checks: list = []
        s_expr = self._source(word, checks)
        body = checks + ["d = R[D]"]
        nxt = "((t + 8) << 9) | ((pc + 1) & 511)"       # not taken: 8 cycles
        if kind == "jmpret":
            body += [f"s = {s_expr}", "r = (d & 0xFFFFFE00) | ((pc + 1) & 511)"]
            carry, zero, taken = "d < s", "r == 0", "True"
        elif kind == "djnz":
            body += ["r = (d - 1) & M"]
            carry, zero, taken = "d == 0", "r == 0", "r"
        else:
            body += ["r = d"]
            carry, zero, taken = "0", "d == 0", "d" if kind == "tjnz" else "not d"
        if kind != "jmpret":
            body.append("s = S" if imm else f"s = {s_expr}")
        go = "((t + 4) << 9) | (s & 511)"
        checks2: list = []
        commit: list = []
        if wr:
            after = go if kind == "jmpret" else f"({go}) if {taken} else {nxt}"
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
                         "if key >= U[0]: raise Y(key)", f"a = {s_expr}"]
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
                 "    if WATCH[a >> 2] & BUSY:",
                 "        CH.watch_hit_at(R[515], a, key)",
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
        body = ["if t >= U[0]: raise Y(t)"] + body
        body += self._flags(word, "0", "1" if equal else "0")
        test = "==" if equal else "!="
        body.append("x = INA(t) & s")
        commit = []
        if wr:
            self._dest_write(word, "(d - x) & M", "t + 4", f"((t + 4) << 9) | {nxt}", [], commit)
        body += [f"if x {test} d:"] + ["    " + c for c in commit] + [f"    return ((t + 4) << 9) | {nxt}"]
        body.append(f"ENG.wait_pins(R, pc, t, s, d, {equal}, {(word >> 9) & 0x1FF if wr else -1})")
        return body


def _never(R, pc, t):
    """Handler of an instruction whose condition is ``if_never`` (4 cycles, nothing happens)."""
    return None


_NEXT = [(k + 1) & 511 for k in range(512)]
_LEFT = "left"


def x_pc(x: int) -> int:
    """The cog address in a packed next state ``(t << 9) | pc``."""
    return x & 511


class PasmEngine:
    """Runs the chip's PASM cogs (one engine per chip, any number of cogs).

    The scheduler calls :meth:`run` and :meth:`key`; the chip calls
    :meth:`start` from its COGINIT.

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip`.
    """

    def __init__(self, chip):
        self.chip = chip
        #: the scheduler's ``until`` for the running cog (handlers read ``until[0]``)
        self.until = [0]
        self.builder = HandlerBuilder(self)
        self.handlers = _Handlers(self.builder.build)
        #: cog id -> callback(PasmStep), for cogs whose instructions are traced
        self.tracers: dict = {}
        self.instructions = 0
        #: cog id -> register a waiting WAITPEQ/WAITPNE with ``wr`` writes when it ends
        self.wait_results: dict = {}

    def __repr__(self) -> str:  # the scheduler's engine name in debugging output
        return "<PasmEngine>"

    # ------------------------------------------------------------------ starting
    def start(self, c, code: int, par: int, t_first: int, by) -> None:
        """COGINIT of PASM: cog ``c`` loads 496 longs from hub ``code`` and runs them.

        ``t_first`` is the cog's start cycle (its pipeline's first slot); its
        first instruction runs 4 cycles later.  PAR is ``par & $FFFC``.
        """
        chip = self.chip
        keep = (c.dira, c.outa) if chip.spinsim else (0, 0)
        if c.ctra or c.ctrb:                    # a restarted cog's counters start off
            for which in (0, 1):
                chip.counters.write(c, which, 0, t_first)
        c.reset_registers()
        c.dira, c.outa = keep
        par &= 0xFFFC
        code &= 0xFFFC
        L = chip.mem_longs
        base = code >> 2
        R = [L[(base + k) & 0x3FFF] for k in range(LOAD_LONGS)] + [0] * (RAM_SLOTS - LOAD_LONGS)
        R[_OUTA], R[_DIRA] = c.outa, c.dira
        if chip.spinsim:
            R[_PAR] = par
        R[PAR_REAL], R[HUB_PHASE], R[COG], R[FLAGS] = par, c.hub_phase, c, 0
        c.ram = R
        c.par = par
        c.pc = 0
        c.ir = None
        c.engine = self
        c.state = RUNNING
        c.code_addr = code
        c.instructions = 0
        chip._cogs_changed = True
        c.started_at = t_first
        c.t = c.key = t_first + 4
        label = chip.code_label(code)
        chip.cog_events.append((t_first, c.id, "start", f"PASM at ${code:04X}" + (f" {label}" if label else "")
                                + (f" (started by cog {by.id})" if by else "")))
        if keep != (0, 0):
            chip.note_pins(c, t_first)

    # ------------------------------------------------------------------ scheduler side
    def key(self, c) -> int:
        """The cycle of cog ``c``'s next access to shared state (a lower bound after it ran ahead)."""
        k = c.key
        return k if k > c.t else c.t

    def run(self, c, until: int) -> None:
        """Run cog ``c`` until its next shared access at or past ``until``. (Hot loop.)

        Instructions that only touch the cog's own RAM run on past ``until``
        (up to :data:`RUN_AHEAD` cycles and never past the run's limit).
        """
        if c.id in self.tracers:
            return self.run_traced(c, until)
        chip = self.chip
        self.until[0] = until
        R = c.ram
        H = self.handlers
        NEXT = _NEXT
        pc = c.pc
        t = c.t
        w = c.ir
        if w is None:
            w = R[pc]
        bound = (until if until > t else t) + RUN_AHEAD
        if bound > chip.run_limit:
            bound = chip.run_limit
        n = 0
        key = None
        while key is None:
            try:
                while t < bound:
                    pc1 = NEXT[pc]
                    w1 = R[pc1]
                    x = H[w](R, pc, t)
                    n += 1
                    if x is None:
                        pc = pc1
                        w = w1
                        t += 4
                    else:
                        t = x >> 9
                        pc = x & 511
                        w = w1 if pc == pc1 else R[pc]
                key = t
            except _Yield as e:
                key = e.key
            except _Fetched as e:
                n += 1
                t = e.x >> 9
                pc = e.x & 511
                w = e.word
            except _Leave as e:
                n += 1
                if e.x is None:             # the handler left the cog as it must be
                    c.instructions += n
                    self.instructions += n
                    return
                t = e.x >> 9
                pc = e.x & 511
                w = w1 if pc == pc1 else R[pc]
                key = t
        c.instructions += n
        self.instructions += n
        c.pc = pc
        c.t = t
        c.ir = w
        c.key = key

    def run_traced(self, c, until: int) -> None:
        """:meth:`run` one instruction at a time, reporting each to the cog's tracer (no running ahead)."""
        report = self.tracers[c.id]
        while c.state == RUNNING and c.engine is self and c.t < until:
            R = c.ram
            pc, t = c.pc, c.t
            w = c.ir if c.ir is not None else R[pc]
            executed = bool((((w >> 18) & 15) >> R[FLAGS]) & 1)
            done = self._step(c, until)
            if not done:
                return                      # its shared access comes after another cog's
            writes = executed and w & isa.R_BIT
            F = R[FLAGS]
            report(PasmStep(t, c.id, pc, w, executed, F & 1, F >> 1, R[(w >> 9) & 0x1FF] if writes else None))
            if done is _LEFT:
                return                      # the scheduler must look again

    def _step(self, c, until: int):
        """Execute one instruction of cog ``c`` unless its shared access comes at or after ``until``.

        Returns False (it did not run), True, or ``_LEFT`` (it ran and the
        scheduler must look again).
        """
        R = c.ram
        pc, t = c.pc, c.t
        w = c.ir if c.ir is not None else R[pc]
        pc1 = _NEXT[pc]
        w1 = R[pc1]
        self.until[0] = until
        try:
            x = self.handlers[w](R, pc, t)
        except _Yield as e:
            c.key = e.key
            return False
        except _Fetched as e:
            x, w1, pc1 = e.x, e.word, x_pc(e.x)
        except _Leave as e:
            x = e.x
            c.instructions += 1
            self.instructions += 1
            if x is None:                   # the handler left the cog as it must be
                return _LEFT
            self._advance(c, R, x, pc1, w1)
            return _LEFT
        c.instructions += 1
        self.instructions += 1
        if x is None:
            c.pc, c.t, c.ir = pc1, t + 4, w1
            c.key = c.t
        else:
            self._advance(c, R, x, pc1, w1)
        return True

    @staticmethod
    def _advance(c, R, x: int, pc1: int, w1: int) -> None:
        c.t, c.pc = x >> 9, x & 511
        c.ir = w1 if c.pc == pc1 else R[c.pc]
        c.key = c.t

    # ------------------------------------------------------------------ what handlers call
    def wait_pins(self, R, pc: int, t: int, mask: int, state: int, equal: bool, dest: int = -1) -> None:
        """WAITPEQ/WAITPNE whose condition does not hold at ``t``: wait until the pins change.

        ``dest`` (with ``wr``): the register that gets ``D - (INA & S)`` when the wait ends.
        """
        chip = self.chip
        c = R[COG]
        if dest >= 0:
            self.wait_results[c.id] = dest
        c.pin_wait = (mask, state, equal, None)
        c.state = PIN_WAIT
        chip._cogs_changed = True
        chip._pin_waiters.append(c)
        if chip._ext_seen < t:
            chip._ext_seen = t
        c.pc = (pc + 1) & 511
        c.t = t
        c.ir = None
        c.key = 0
        raise _Leave(None)

    def wake_time(self, c, t: int, writer) -> int:
        """The first cycle of the instruction after a WAITPEQ/WAITPNE that the pins at ``t`` satisfy.

        ``t`` is when the pins changed: a cog's write (``writer``) shows at its
        instruction's cycle + 4, which a poll in that cycle sees when the
        writer's id is lower; an input or counter edge (``writer`` None) is
        seen by the first poll at or after it.  Polls fall on the waiting
        cog's 4-cycle grid.
        """
        grid = c.t & 3
        base = t - 4 if writer is not None else t
        poll = base + ((grid - base) & 3)
        if writer is not None and poll == base and writer.id > c.id:
            poll += 4
        dest = self.wait_results.pop(c.id, None)
        if dest is not None:
            mask, state, _equal, _after = c.pin_wait
            value = (state - (self.chip.ina(t) & mask)) & M
            c.ram[dest] = value
            if dest >= 0x1F4:
                self.chip.registers.write(c, dest, value, poll + 4)
        return poll + 4

    def waitvid(self, R, pc: int, t: int) -> int:
        """WAITVID in chip mode: wait for the video generator to take the next frame (VSCL[11:0] clocks)."""
        chip = self.chip
        c = R[COG]
        frame = (R[0x1FF] & 0xFFF) or 4096
        start = max(t, chip._video_ready[c.id])
        chip._video_ready[c.id] = start + frame
        return ((start + 4) << 9) | ((pc + 1) & 511)

    def make_hubop(self, word: int) -> Callable:
        """The handler of a HUBOP long (CLKSET ... LOCKCLR) or of an undefined hub opcode ($04-$07)."""
        cond = (word >> 18) & 15
        op = self.hubop

        def h(R, pc, t):
            if not (cond >> R[FLAGS]) & 1:
                return None
            return op(R, pc, t, word)
        return h

    def hubop(self, R, pc: int, t: int, word: int) -> int:
        """Run a hub operation; results and flags as measured on spinsim 0.99 (docs/pasm.md)."""
        chip = self.chip
        c = R[COG]
        key = t + 8
        key += (R[HUB_PHASE] - key) & 15
        nxt = (key << 9) | ((pc + 1) & 511)
        dest = (word >> 9) & 0x1FF
        wz, wc, wr = word & isa.Z_BIT, word & isa.C_BIT, word & isa.R_BIT
        if word >> 26 != 3:                             # opcodes $04-$07: no operation, D := 0
            if wr:
                self._write_hub_result(R, c, dest, 0, key, nxt)
            return nxt
        src = word & 0x1FF
        op = (src if word & isa.I_BIT else R[src]) & 7
        if op == 1:                                     # COGID: no shared state, flags kept
            if wr:
                self._write_hub_result(R, c, dest, c.id, key, nxt)
            return nxt
        done = key - 4 if op in (2, 3) else key         # a cog op acts in its last cycle
        if done >= self.until[0]:
            raise _Yield(done)
        d = R[dest]
        zero = carry = None
        leave = False
        if op == 0:                                     # CLKSET
            result = 0
            mode = d & 0xFF
            if mode & 0x80:
                c.t = key
                raise RebootRequested(0)
            chip.set_clock_mode(mode)
        elif op == 2:                                   # COGINIT
            free = any(k.state == STOPPED for k in chip.cogs)
            cog_id = 8 if d & 8 else d & 7
            got = chip.start_cog(c, cog_id, (d >> 2) & 0xFFFC, (d >> 16) & 0xFFFC, key)
            result = 7 if got == M else got
            carry, zero = not free, result == 0
            leave = True
        elif op == 3:                                   # COGSTOP
            free = any(k.state == STOPPED for k in chip.cogs)
            result = d & 7
            carry, zero = not free, result == 0
            target = chip.cogs[result]
            if target is c:
                self._flags(R, wz, wc, carry, zero)
                chip.stop_cog(c, key, "COGSTOP of itself")
                raise _Leave(None)
            if target.state != STOPPED:
                chip.stop_cog(target, key, f"stopped by cog {c.id}")
                leave = True
        elif op == 4:                                   # LOCKNEW
            got = chip.locknew()
            result = 7 if got == M else got
            carry, zero = got == M, result == 0
        elif op == 5:                                   # LOCKRET: C = no lock was free
            result = d & 7
            carry, zero = all(chip.lock_used), result == 0
            chip.lockret(result)
        else:                                           # LOCKSET, LOCKCLR
            result = d & 7
            carry, zero = chip.lockset(result, op == 6), result == 0
        if c.state != RUNNING or c.ram is not R or c.engine is not self:    # it restarted itself
            raise _Leave(None)
        if zero is not None:
            self._flags(R, wz, wc, carry, zero)
        if wr:
            self._write_hub_result(R, c, dest, result, key, nxt)
        if leave:
            raise _Leave(nxt)
        return nxt

    @staticmethod
    def _flags(R, wz, wc, carry, zero) -> None:
        F = R[FLAGS]
        if wz:
            F = (F & 2) | int(zero)
        if wc:
            F = (F & 1) | (int(carry) << 1)
        R[FLAGS] = F

    def _write_hub_result(self, R, c, dest: int, value: int, key: int, nxt: int) -> None:
        R[dest] = value
        if dest >= 0x1F4:
            self.chip.registers.write(c, dest, value, key)
            if self.chip._preempt:
                self.chip._end_preemption()
                raise _Leave(nxt)
