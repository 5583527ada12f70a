"""The bytecode families of compiled blocks that compute and touch data (:mod:`.blocks`).

:class:`DataOps` is a mixin of :class:`spinemu.chip.blocks.BlockCompiler`:
math, VAR/LOC longs, memory access and the assignment operators (REPEAT's
loop test included), written as Python text into the block being compiled.
Where each reads or writes hub RAM decides what a block must check:

* local variables (``dbase`` + a constant) lie in the cog's own frame: the
  block checks at entry that they lie clear of its stack slots (whose
  stores are lazy) and, in an exact block, that none is watched;
* hub variables and computed addresses: an exact block leaves before a
  watched long (a parked busy loop reads it, code lies there, a cog ahead
  owns it); a private variant reads only longs that are read-only for now
  (``Chip.watch`` bit ``RO``, checked at entry or before the access) or in
  the cog's window, and writes only its window.
"""
from __future__ import annotations

from .ahead import AHEAD, RO
from .mathops import BINARY, MASK32, UNARY
from .timing import MATH_REF

__all__ = ["DataOps", "BUSY", "CODE"]

#: ``Chip.watch`` bits: a parked busy loop reads the long, compiled code lies in it
BUSY, CODE = 1, 2

# math operators as expressions over operands that are names or literals
_BINARY_EXPR = {
    0x02: "{x} >> ({y} & 31)",
    0x03: "({x} << ({y} & 31)) & 0xFFFFFFFF",
    0x08: "{x} & {y}",
    0x0A: "{x} | {y}",
    0x0B: "{x} ^ {y}",
    0x0C: "({x} + {y}) & 0xFFFFFFFF",
    0x0D: "({x} - {y}) & 0xFFFFFFFF",
    0x10: "0xFFFFFFFF if {x} and {y} else 0",
    0x12: "0xFFFFFFFF if {x} or {y} else 0",
    0x14: "({x} * {y}) & 0xFFFFFFFF",
    0x19: "0xFFFFFFFF if {x} ^ 0x80000000 < {y} ^ 0x80000000 else 0",
    0x1A: "0xFFFFFFFF if {x} ^ 0x80000000 > {y} ^ 0x80000000 else 0",
    0x1B: "0xFFFFFFFF if {x} != {y} else 0",
    0x1C: "0xFFFFFFFF if {x} == {y} else 0",
    0x1D: "0xFFFFFFFF if {x} ^ 0x80000000 <= {y} ^ 0x80000000 else 0",
    0x1E: "0xFFFFFFFF if {x} ^ 0x80000000 >= {y} ^ 0x80000000 else 0",
}
# signed division and modulus, inline for the usual non-negative operands (names or literals)
_DIVMOD = {0x16: "//", 0x17: "%"}


def _binary_expr(f: int, x: str, y: str) -> str:
    """Python text for binary math operator ``f`` on operands ``x``, ``y`` (names or literals)."""
    if f in _BINARY_EXPR:
        return _BINARY_EXPR[f].format(x=x, y=y)
    o = _DIVMOD.get(f)
    if o is not None and (x.isidentifier() or x.isdigit()) and (y.isidentifier() or y.isdigit()):
        if y.isdigit() and 0 < int(y) < 0x80000000:     # the sign of the result follows x's
            return f"({x} {o} {y} if {x} < 0x80000000 else -((0x100000000 - {x}) {o} {y}) & 0xFFFFFFFF)"
        if not y.isdigit():
            return f"({x} {o} {y} if {x} < 0x80000000 and 0 < {y} < 0x80000000 else B{f:02X}({x}, {y}))"
    return f"B{f:02X}({x}, {y})"


_UNARY_EXPR = {
    0x06: "-{x} & 0xFFFFFFFF",
    0x07: "{x} ^ 0xFFFFFFFF",
    0x11: "{x}.bit_length()",
    0x13: "1 << ({x} & 31)",
    0x1F: "0 if {x} else 0xFFFFFFFF",
}
# the loop parameter of the value-dependent math paths (timing.math_param), as expressions
_PARAM_EXPR = {
    0x16: "(-{y} & 0xFFFFFFFF if {y} & 0x80000000 else {y}).bit_length()",
    0x17: "(-{y} & 0xFFFFFFFF if {y} & 0x80000000 else {y}).bit_length()",
    0x11: "32 - {x}.bit_length()",
}


class _Stop(Exception):
    """The bytecode cannot be compiled: the block ends before it."""


def _is_literal(expr: str) -> bool:
    return expr.isdigit()


class DataOps:
    """Math, variables, memory and assignment operators of :class:`~.blocks.BlockCompiler` (mixin)."""

    def _math(self, b, op: int) -> None:
        f = op & 0x1F
        table = self.T._math[f]
        if UNARY[f] is not None:
            x = b.pop()
            y = "0"
            if _is_literal(x):
                new = str(UNARY[f](int(x)))
            elif f in _UNARY_EXPR:
                new = _UNARY_EXPR[f].format(x=x)
            else:
                new = f"U{f:02X}({x})"
        else:
            y = b.pop()
            x = b.pop()
            if _is_literal(x) and _is_literal(y):
                new = str(BINARY[f](int(x), int(y)))
            else:
                new = _binary_expr(f, x, y)
        b.push(new)
        self._account(b, op, *self._math_rest(f, table, x, y, 0))

    def _math_rest(self, f: int, table, x: str, y: str, base: int):
        """The cycles of math operator ``f`` on operands ``x``, ``y``: ``(rest,)`` or ``(expr, worst)``."""
        if len(set(table)) == 1:
            return (base + table[0],)
        if (_is_literal(x) or f != 0x11) and (_is_literal(y) or f == 0x11):
            from .timing import math_param
            return (base + table[math_param(0xE0 | f, int(x) if _is_literal(x) else 0,
                                             int(y) if _is_literal(y) else 0)],)
        return (f"{base} + MT{f:02X}[{_PARAM_EXPR[f].format(x=x, y=y)}]", base + max(table))

    # -- VAR / LOC longs ($40-$7F)
    def _var(self, b, op: int) -> None:
        off = op & 0x1C
        local = bool(op & 0x20)
        access = op & 3
        if not local and access in (1, 2):
            if b.private:
                raise _Stop                     # a write to a hub variable: shared
            b.shared = True
        base = b.base("dbase" if local else "vbase")
        T = self.T
        addr = f"({base} + {off}) & 0xFFFF"
        if access == 3:
            b.push(addr)
            return self._account(b, op, T.var[op])
        if local:                               # (checked at entry: clear of the stack slots, not watched)
            b.loc(off)
            if access:
                b.loc_writes.add(off)
        elif b.private:                         # read-only for now (checked at entry)
            b.ro.add(("vb", off))
        else:
            b.flush()                           # (a stack may lie among the hub variables)
        if access == 0:
            if not local and not b.private:
                b.var_reads.add(off)
            b.push(f"L[(({base} + {off}) & 0xFFFF) >> 2]")
            return self._account(b, op, T.var[op])
        a = b.let(addr)
        if not local:
            b.deopt(f"{a} >= 0x8000 or WATCH[{a} >> 2]")     # (ROM: the interpreter, and its check)
        if access == 1:
            v = b.pop()
            b.emit(f"if {a} < 0x8000: L[{a} >> 2] = {v}")
            if not local:
                b.forget()
            return self._account(b, op, T.var[op])
        old = b.let(f"L[{a} >> 2]")
        aop = self._byte(b)
        res = self._assign(b, aop, old, op, T.var_using[local])
        new = res[0]
        if not local:
            b.flush()                           # the stack slots the operator wrote come first
        b.emit(f"if {a} < 0x8000: L[{a} >> 2] = {new}")
        if not local:
            b.forget()
        self._assign_close(b, op, res)

    # -- memory ($80-$DF)
    def _mem(self, b, op: int) -> None:
        size = (op >> 5) & 3
        base = (op >> 2) & 3
        indexed = op & 0x10
        access = op & 3
        T = self.T
        reg = None
        if base:
            x = self._byte(b)
            long_ = bool(x & 0x80)
            off = ((x & 0x7F) << 8) | self._byte(b) if long_ else x
            reg = b.base(("pbase", "vbase", "dbase")[base - 1])
            expr = f"{off} + {reg}"
            if indexed:
                k = b.pop()
                expr = f"{expr} + ({k} << {size})" if size else f"{expr} + {k}"
        else:
            long_ = False
            if indexed:
                k = b.pop()
                p = b.pop()
                expr = f"{p} + ({k} << {size})" if size else f"{p} + {k}"
            else:
                expr = b.pop()
        rest = (T.mem_using if access == 2 else T.mem)[(op, long_)]
        a = b.let(f"({expr}) & 0xFFFFFFFF") if (indexed or base) else expr
        if access == 3:
            b.push(a)
            return self._account(b, op, rest)
        local = base == 3 and not indexed       # a local variable: the frame, checked at entry
        if access and not local:
            b.shared = True                     # (a private variant checks that it is in the window)
        fixed = (base and not indexed) or (not base and not indexed and _is_literal(expr))
        if local:
            b.loc(off & ~3)
            if access:
                b.loc_writes.add(off & ~3)
            w = b.let(f"{a} & 0xFFFF")
        elif b.private:
            if access == 0 and fixed:           # read-only for now (checked at entry)
                b.ro.add((reg, off) if base else (None, int(expr) & 0xFFFF))
                w = None
            else:                               # the window (stores first: it may be a stack slot), or read-only
                b.flush()
                w = b.let(f"{a} & 0xFFFF")
                if access:
                    b.deopt(f"not wl <= {w} < wh")
                else:
                    b.deopt(f"not (wl <= {w} < wh or WATCH[{w} >> 2] & {RO})", want=w)
        else:
            b.flush()
            w = b.let(f"{a} & 0xFFFF")
            if access == 0:                     # not in the window of a cog ahead
                b.deopt(f"AH and WATCH[{w} >> 2] & {AHEAD}")
            else:                               # writes: leave the block first if the long is watched
                b.deopt(f"{w} >= 0x8000 or WATCH[{w} >> 2]")
        if access == 0:
            b.push(self._sized_read(size, a))
            return self._account(b, op, rest)
        if access == 1:
            v = b.pop()
            b.emit(f"if {w} < 0x8000: {self._sized_store(size, w, v)}")
            if not local:
                b.forget()
            return self._account(b, op, rest)
        old = b.let(self._sized_read(size, a))
        aop = self._byte(b)
        res = self._assign(b, aop, old, op, rest)
        if not local:
            b.flush()                           # the stack slots the operator wrote come first
        b.emit(f"if {w} < 0x8000: {self._sized_store(size, w, res[0])}")
        if not local:
            b.forget()
        self._assign_close(b, op, res)

    @staticmethod
    def _sized_read(size: int, a: str) -> str:
        if size == 0:
            return f"mem[{a} & 0xFFFF]"
        if size == 1:
            return f"W[({a} & 0xFFFE) >> 1]"
        return f"L[({a} & 0xFFFC) >> 2]"

    @staticmethod
    def _sized_store(size: int, w: str, v: str) -> str:
        if size == 0:
            return f"mem[{w}] = {v} & 0xFF"
        if size == 1:
            return f"W[{w} >> 1] = {v} & 0xFFFF"
        return f"L[{w} >> 2] = {v} & 0xFFFFFFFF"

    # -- assignment operators (the interpreter's spin._assign, for hub targets)
    def _assign(self, b, a: int, v: str, op: int, base_rest: int):
        """Generate assignment operator ``a`` on target value ``v``.

        Returns ``(new, rest...)``: the expression to store, then either
        ``(rest,)``, ``(expr, worst)`` or, for REPEAT, the loop's exits.
        """
        T = self.T
        tab = T.assign_mem
        push_it = a & 0x80
        c = a & 0x7F
        if c == 0:                                      # WRITE: the value is on the stack
            new = b.peek()
            if not push_it:
                b.off -= 4
            return new, base_rest + tab[a]
        b.write(b.off, v)
        if c & 0x40:
            if c & 0x20:
                raise _Stop
            f = c & 0x1F
            table = T._math[f]
            ref = table[MATH_REF.get(0xE0 | f, 0)]
            fixed = T._math_assign[(False, f, push_it != 0)] - ref + base_rest
            if UNARY[f] is not None:
                expr = _UNARY_EXPR[f].format(x=v) if f in _UNARY_EXPR else f"U{f:02X}({v})"
                new = b.write(b.off, expr)
                if push_it:
                    b.off += 4
                return (new,) + self._math_rest(f, table, v, "0", fixed)
            y = b.read(b.off - 4)
            expr = _binary_expr(f, v, y)
            new = b.write(b.off - 4, expr)
            if not push_it:
                b.off -= 4
            return (new,) + self._math_rest(f, table, v, y, fixed)
        if c == 0x02 or c == 0x06:
            return self._repeat(b, a, v, op, base_rest)
        if c == 0x08:
            new = f"RF({v})"
        elif c == 0x0C:
            new = f"RR({v})"
        elif c == 0x10:
            new = f"(({v} & 0xFF) - (({v} & 0x80) << 1)) & 0xFFFFFFFF"
        elif c == 0x14:
            new = f"(({v} & 0xFFFF) - (({v} & 0x8000) << 1)) & 0xFFFFFFFF"
        elif c == 0x18:
            new = None
        elif c == 0x1C:
            new = None
        elif 0x20 <= c < 0x40 and not c & 1:
            m = (MASK32, 0xFF, 0xFFFF, MASK32)[(c >> 1) & 3]
            new = b.let(f"({v} {'+' if c < 0x30 else '-'} 1) & {m:#x}")
            if c & 0x08:                                # post: the old value stays on the stack
                if push_it:
                    b.off += 4
                return new, base_rest + tab[a]
        else:
            raise _Stop
        if new is None:                                 # x~ / x~~: old value stays on the stack
            new = "0" if c == 0x18 else "4294967295"
        else:
            new = b.write(b.off, new)
        if push_it:
            b.off += 4
        return new, base_rest + tab[a]

    def _assign_close(self, b, op: int, res) -> None:
        if len(res) == 4:                               # REPEAT: a conditional jump
            if 0x40 <= op < 0xE0:                       # ... whose write-back is its last instruction
                b.reach = max(b.reach, b.worst + max(res[2][1], res[3][1]) - 4)
            return self._branch(b, op, res[1], res[2], res[3])
        self._account(b, op, *res[1:])

    def _repeat(self, b, a: int, v: str, op: int, base_rest: int):
        step_ = (a & 0x7F) == 0x06
        to = b.read(b.off - 4)
        frm = b.read(b.off - 8)
        if step_:
            step = b.read(b.off - 12)
            b.off -= 12
        else:
            step = "1"
            b.off -= 8
        target, long_ = self._jump_target(b, wrap=True)
        s = lambda e: e if _is_literal(e) and int(e) < 0x80000000 else f"({e} ^ 0x80000000) - 0x80000000"
        x = b.name()
        f_, t_ = s(frm), s(to)
        b.emit(f"{x} = {s(v)}")
        inside = b.name("ins")
        b.emit(f"if {f_} <= {t_}:")
        b.emit(f"{x} += {s(step)}", 1)
        b.emit(f"{inside} = {f_} <= {x} <= {t_}", 1)
        b.emit("else:")
        b.emit(f"{x} -= {s(step)}", 1)
        b.emit(f"{inside} = {t_} <= {x} <= {f_}", 1)
        new = b.let(f"{x} & 0xFFFFFFFF")
        T = self.T
        taken = base_rest + T.repeat[(False, step_, True, long_)]
        not_taken = base_rest + T.repeat[(False, step_, False, long_)]
        return new, inside, (target, taken), (b.pc, not_taken)
