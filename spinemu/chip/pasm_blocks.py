"""PASM blocks: hot straight-line runs of cog RAM compiled to one Python function each.

The PASM cog (:mod:`.pasm_cog`) calls one small function per instruction
(:mod:`.pasm_ops`); its run loop's fetch, dispatch and packing of the next
state cost more than most instructions' own work.  A *block* is a run of
cog RAM from a hot address, compiled once into one function that does the
same work with every register address, constant, condition and cycle offset
folded into its text, the flags kept in two locals:

* **Only private instructions.**  A block holds ALU instructions whose source
  and destination are cog RAM, constants, CNT, PAR or the shadow registers,
  and jumps; it stops *before* anything that touches shared state (hub
  instructions, INA, PHSx, OUTA/DIRA/counter writes, waits, hub
  operations), which the run loop then runs through its handler, with the
  same hand-over rules as before.  So a PASM cog hands over at exactly the
  same points with or without blocks.
* **Same semantics table.**  Results and flags come from
  :data:`.pasm_ops.ALU` and :data:`.pasm_ops.JUMPS`, operands from
  :meth:`.pasm_ops.HandlerBuilder._source`; conditions from
  :data:`.pasm_ops.CONDITION_EXPRS`.
* **Timing is static.**  Every instruction takes 4 cycles (a false
  condition too), ``djnz``/``tjz``/``tjnz`` 8 when they do not jump; a
  conditional one of those adds its 4 cycles at run time.  A block runs only
  when its last instruction, on its slowest path, starts before the run
  loop's bound, so it stops where the loop would have stopped.
* **Conditional jumps are side exits**; an unconditional ``jmp``/``jmpret``
  ends the block.  The block's last jump reads its target from cog RAM when
  it runs (``call`` rewrites the ``ret`` of its subroutine on every call).
* **Self-modifying code.**  A block compares its code with cog RAM when it
  starts (and its first long with the long the pipeline fetched), and does
  nothing if they differ; the run loop then interprets and recompiles when
  hot again.  Inside a block, an instruction that writes a later long of the
  same block ends it before that long (the loop fetches the new value, as the
  chip does two instructions on); one that writes the long right after it
  (which the pipeline fetched already) or its own jump target is left to the
  interpreter, as is a register jump that writes its own target (checked when
  it runs).

A block function is called as ``f(R, t, w, limit)`` (cog RAM, the first
instruction's cycle, the long the pipeline fetched for it, the run's cycle
limit: a block may run past the loop's hand-over bound, as its instructions
touch nothing another cog sees, but never past the limit) and returns ``-1`` when it did nothing, else the packed
``(t_next << 17) | (instructions << 9) | pc_next``.
"""
from __future__ import annotations

import functools
import re
from typing import Callable, Optional

from .. import pasm as isa
from .pasm_ops import ALU, CONDITION_EXPRS, FAMILIES, JUMPS, HandlerBuilder, _rev32

__all__ = ["PasmBlockCompiler", "MAX_INSTRUCTIONS", "HOT", "RECOMPILE_LIMIT"]

#: instructions in one block at most (the count must fit 8 bits of the packed result)
MAX_INSTRUCTIONS = 200
#: times an address is interpreted before a block is compiled from it
HOT = 16
#: compilations of one address (its code keeps changing) after which it stays interpreted
RECOMPILE_LIMIT = 8
_TOP = 0x1F0                        # blocks stay below the special registers
_INB = isa.REGISTERS["INB"]
#: operand texts of HandlerBuilder._source that a block can fold (the rest touch shared state)
_PRIVATE_SOURCES = {"S", "R[S]", "R[513]", "t & M", "0"}


@functools.lru_cache(maxsize=None)
def _uses(expr: str, name: str) -> bool:
    return re.search(rf"\b{name}\b", expr) is not None


def _literal(expr: str, **names) -> str:
    for name, value in names.items():
        expr = re.sub(rf"\b{name}\b", str(value), expr)
    return expr


assert not any(_uses(op.zero or "", "c") for op in list(ALU.values()) + list(JUMPS.values()))


_C1, _C0, _Z1, _Z0 = 0b1100, 0b0011, 0b1010, 0b0101      # conditions' truth tables: bit (C << 1) | Z
_LITERALS = ((_C1, "c", "c"), (_C0, "not c", "c"), (_Z1, "z", "z"), (_Z0, "not z", "z"))


def _condition_text(cond: int, known: int) -> str:
    """The shortest condition expression that is ``cond`` wherever the flags can be ``known``."""
    return min((CONDITION_EXPRS[x] for x in range(16) if x & known == cond & known), key=len)


class _Writer:
    """The text of one block: one item per instruction (its condition, the flags it writes, its lines),
    and the exits' flag write-back.  :meth:`render` nests the items' conditions: a run of
    instructions that all need C (``if_c``, ``if_c_and_z`` ...) tests C once."""

    def __init__(self):
        self.items: list = []
        self.flags_dirty = False
        self.flags_used = False

    def begin(self, cond: int, writes: set) -> None:
        self.items.append((cond, writes, []))

    def emit(self, line: str, depth: int = 0) -> None:
        self.items[-1][2].append((depth, line))

    def exit(self, when: str, n: int, pc: str, depth: int) -> None:
        """Return the packed next state (flags written back first)."""
        for line in self.exit_lines(when, n, pc, self.flags_dirty):
            self.emit(line, depth)

    @staticmethod
    def exit_lines(when: str, n: int, pc: str, dirty: bool) -> list:
        return (["R[512] = (c << 1) | z"] if dirty else []) + [f"return (({when}) << 17) | ({n} << 9) | ({pc})"]

    def render(self) -> list:
        out: list = []
        self._render(self.items, 15, 2, out)
        return out

    def _render(self, items: list, known: int, depth: int, out: list) -> None:
        pad = "    "
        i = 0
        while i < len(items):
            cond, writes, lines = items[i]
            here = cond & known
            if here == 0 or not lines:              # cannot run where the flags are known to be, or no code
                i += 1
                continue
            if here == known:
                out += [pad * (depth + d) + x for d, x in lines]
                i += 1
                continue
            lit = next((x for x in _LITERALS if not here & ~x[0] and known & ~x[0]), None)
            if lit is None:
                out.append(pad * depth + f"if {_condition_text(cond, known)}:")
                out += [pad * (depth + 1 + d) + x for d, x in lines]
                i += 1
                continue
            mask, text, flag = lit
            j = self._group(items, i, known, mask, flag)
            out.append(pad * depth + f"if {text}:")
            self._render_body(items[i:j], known & mask, depth + 1, out)
            if not any(flag in w for _, w, _ in items[i:j]):
                k = self._group(items, j, known, mask ^ 15, flag)
                if k > j:
                    out.append(pad * depth + "else:")
                    self._render_body(items[j:k], known & (mask ^ 15), depth + 1, out)
                    j = k
            i = j

    def _render_body(self, items: list, known: int, depth: int, out: list) -> None:
        size = len(out)
        self._render(items, known, depth, out)
        if len(out) == size:
            out.append("    " * depth + "pass")

    @staticmethod
    def _group(items: list, i: int, known: int, mask: int, flag: str) -> int:
        """One past the run of items from ``i`` that only run where ``mask`` holds (ending at a write of ``flag``)."""
        j = i
        while j < len(items) and items[j][0] & known and not items[j][0] & known & ~mask:
            j += 1
            if flag in items[j - 1][1]:
                break
        return j


class PasmBlockCompiler:
    """Compiles blocks of one engine's PASM cogs (see the module docstring).

    Args:
        builder: the engine's :class:`~.pasm_ops.HandlerBuilder` (its operand
            rules and compatibility mode).
    """

    def __init__(self, builder: HandlerBuilder):
        self.builder = builder
        self.count = 0
        self.env = {"REV": _rev32}

    def compile(self, R: list, start: int) -> Optional[Callable]:
        """The block starting at cog address ``start`` with cog RAM ``R`` as it is, or ``None``."""
        if start >= _TOP:
            return None
        head: list = []
        body = _Writer()
        off = 0                 # cycles from t (after dynamic extras) to the current instruction
        worst = 0               # the same on the slowest path
        last_start = 0          # the last instruction's start on the slowest path
        n = 0
        pc = start
        forbidden: set = set()
        ends = dynamic_last = False
        while n < MAX_INSTRUCTIONS and pc < _TOP and pc not in forbidden:
            step = self._instruction(body, R[pc], pc, off, n, start, forbidden)
            if step is None:
                break
            cycles, extra, ends, dynamic_last = step
            n += 1
            last_start = worst
            off += cycles
            worst += cycles + extra
            pc += 1
            if ends:
                break
        if n == 0:
            return None
        if not ends:
            body.begin(15, set())
            body.exit(f"t + {off}", n, str(pc), 0)
        end = pc                    # one past the last instruction
        last = end - 1
        # validation: the first long as fetched, the others as in cog RAM (the last jump's S is read live)
        checked_end = last if dynamic_last else end
        if dynamic_last and last == start:
            head.append(f"if (w ^ {R[last]}) >> 9: return -1")
        else:
            head.append(f"if w != {R[start]}: return -1")
            if checked_end > start + 1:
                head.append(f"if R[{start + 1}:{checked_end}] != WORDS: return -1")
            if dynamic_last:
                head.append(f"if (R[{last}] ^ {R[last]}) >> 9: return -1")
        head.append(f"if t + {last_start} >= bound: return -2")
        if body.flags_used or body.flags_dirty:
            head.append("F = R[512]")
            head.append("c = F >> 1")
            head.append("z = F & 1")
        src = "def make(WORDS):\n    def block(R, t, w, bound):\n"
        src += "\n".join(["    " * 2 + x for x in head] + body.render()) + "\n    return block\n"
        src = _literal(src, M=0xFFFFFFFF, SB=0x80000000)
        ns: dict = {}
        exec(compile(src, f"<pasm block ${start:03X}-${last:03X}>", "exec"), dict(self.env), ns)
        fn = ns["make"](list(R[start + 1:checked_end]))
        fn.source = src
        fn.span = (start, end)
        code = list(R[start:end])
        if dynamic_last:            # as the block checks it: the last jump's S may change
            fn.matches = lambda R: R[start:last] == code[:-1] and not (R[last] ^ code[-1]) >> 9
        else:
            fn.matches = lambda R: R[start:end] == code
        self.count += 1
        return fn

    # ------------------------------------------------------------------ one instruction
    def _instruction(self, out: _Writer, word: int, pc: int, off: int, n: int, start: int, forbidden: set):
        """Emit ``word`` at ``pc``; returns ``(cycles, extra, ends, dynamic_target)`` or ``None`` (not here)."""
        cond = (word >> 18) & 15
        if cond == 0:
            return 4, 0, False, False               # never: 4 cycles, nothing
        fam, detail = FAMILIES[word >> 26]
        if fam not in ("alu", "jump"):
            return None
        dest, src = (word >> 9) & 0x1FF, word & 0x1FF
        wr = bool(word & isa.R_BIT)
        s_expr = self._source(word, off)
        if s_expr is None:
            return None
        if wr and dest >= _TOP and dest > _INB:
            return None                             # OUTA, DIRA, counters, video: shared
        ce = CONDITION_EXPRS[cond]
        if ce != "True":
            out.flags_used = True
        if fam == "alu":
            if wr and dest < _TOP:
                if dest == pc + 1:
                    return None                     # the pipeline fetched it already: interpreter
                if dest > pc:
                    forbidden.add(dest)             # end the block before it: the loop fetches the new long
            self._alu(out, word, detail, s_expr, ce)
            return 4, 0, False, False
        return self._jump(out, word, detail, pc, off, n, start, s_expr, ce, forbidden)

    def _source(self, word: int, off: int) -> Optional[str]:
        checks: list = []
        e = self.builder._source(word, checks)
        if checks or e not in _PRIVATE_SOURCES:
            return None
        src = word & 0x1FF
        return {"S": str(src), "R[S]": f"R[{src}]", "t & M": f"(t + {off}) & M"}.get(e, e)

    @staticmethod
    def _flag_lines(word: int, carry: str, zero: str) -> list:
        wz, wc = bool(word & isa.Z_BIT), bool(word & isa.C_BIT)
        if wz and wc:
            if not _uses(carry, "z"):
                return [f"c = {carry}", f"z = {zero}"]     # Z never reads C (checked below)
            return [f"nc = {carry}", f"z = {zero}", "c = nc"]
        if wc:
            return [f"c = {carry}"]
        if wz:
            return [f"z = {zero}"]
        return []

    def _alu(self, out: _Writer, word: int, mnemonic: str, s_expr: str, ce: str) -> None:
        op = ALU[mnemonic]
        dest = (word >> 9) & 0x1FF
        wr = bool(word & isa.R_BIT)
        wz, wc = bool(word & isa.Z_BIT), bool(word & isa.C_BIT)
        zero = op.zero or "r == 0"
        carry = op.carry
        flag_exprs = ([carry] if wc else []) + ([zero] if wz else [])
        need_r = wr or any(_uses(e, "r") for e in flag_exprs)
        used = [op.prelude] + ([op.result] if need_r else []) + flag_exprs
        if any(_uses(e, "c") or _uses(e, "z") for e in used):
            out.flags_used = True
        lines = []
        # operands used once are read where they are used (constants always)
        d_uses = sum(len(re.findall(r"\bd\b", e)) for e in used)
        s_uses = sum(len(re.findall(r"\bs\b", e)) for e in used)
        d_text, s_text = f"R[{dest}]", s_expr if s_expr.startswith("R[") or s_expr.isdigit() else f"({s_expr})"
        if d_uses > 1:
            lines.append(f"d = {d_text}")
            d_text = "d"
        if s_uses > 1 and not s_expr.isdigit():
            lines.append(f"s = {s_text}")
            s_text = "s"

        def fold(e: str) -> str:
            return _literal(e, d=d_text, s=s_text)
        if op.prelude:
            lines.append(fold(op.prelude))
        result = fold(op.result)
        flags = [fold(x) for x in self._flag_lines(word, carry, zero)]
        written = ({"c"} if wc else set()) | ({"z"} if wz else set())
        if need_r and (any(_uses(e, "r") for e in flag_exprs) or any(_uses(result, f) for f in written)):
            lines.append(f"r = {result}")
            lines += flags
            if wr:
                lines.append(f"R[{dest}] = r")
        else:
            lines += flags                  # they read the operands before the write
            if wr:
                lines.append(f"R[{dest}] = {result}")
        out.begin((word >> 18) & 15, written)
        for x in lines:
            out.emit(x)
        if wz or wc:
            out.flags_dirty = True

    def _jump(self, out: _Writer, word: int, kind: str, pc: int, off: int, n: int, start: int,
              s_expr: str, ce: str, forbidden: set):
        op = JUMPS[kind]
        dest, src = (word >> 9) & 0x1FF, word & 0x1FF
        wr = bool(word & isa.R_BIT)
        imm = bool(word & isa.I_BIT)
        always = ce == "True"
        ends = always and op.taken == "True"        # an unconditional jmp/jmpret: the block's last
        if wr and dest < _TOP:
            if imm and dest == src:
                return None                         # writes its own target (pipeline): interpreter
            if dest == pc + 1 and op.taken != "True":
                return None                         # may fall through to the long it wrote
            if dest > pc + 1 or (dest == pc + 1 and not ends):
                forbidden.add(dest)
        dynamic = imm and ends
        if dynamic:                                 # the last jump: its S field is read when it runs
            s_expr = "w" if pc == start else f"R[{pc}]"
            s_expr += " & 511"
        result = _literal(op.result, pc=pc)
        lines = []
        if not imm and wr and dest < _TOP and kind in ("jmpret", "djnz"):
            # a register jump to the long it writes: the pipeline runs the old long (interpreter)
            lines.append(f"s = {s_expr}")
            lines.append(f"if (s & 511) == {dest}:")
            lines += ["    " + x for x in _Writer.exit_lines(f"t + {off}", n, str(pc), out.flags_dirty)]
            have_s = True
        else:
            have_s = False
        wz, wc = bool(word & isa.Z_BIT), bool(word & isa.C_BIT)
        exprs = [result, op.taken] + ([op.carry] if wc else []) + ([op.zero] if wz else [])
        if not have_s:
            lines.append(f"s = {s_expr}")
        if any(_uses(e, "d") for e in exprs):
            lines.append(f"d = R[{dest}]")
        if wr or any(_uses(e, "r") for e in [op.taken] + ([op.carry] if wc else []) + ([op.zero] if wz else [])):
            lines.append(f"r = {result}")
        lines += self._flag_lines(word, op.carry, op.zero)
        if wr:
            lines.append(f"R[{dest}] = r")
        out.begin((word >> 18) & 15, ({"c"} if wc else set()) | ({"z"} if wz else set()))
        if wz or wc:
            out.flags_dirty = True
        depth = 0
        for x in lines:
            out.emit(x)
        if op.taken == "True":
            out.exit(f"t + {off + 4}", n + 1, "s & 511", depth)
            return 4, 0, ends, dynamic
        out.emit(f"if {op.taken}:", depth)
        out.exit(f"t + {off + 4}", n + 1, "s & 511", depth + 1)
        if always:
            return 8, 0, False, False               # not taken: 8 cycles, static
        out.emit("t += 4", depth)                   # executed but not taken: 4 more cycles
        return 4, 4, False, False
