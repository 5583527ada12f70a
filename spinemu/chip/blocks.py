"""Runs of Spin bytecode compiled to Python functions: the block cache (hot path).

The interpreter (:mod:`.spin`) pays, for every bytecode, a dispatch, the
operand decoding and the stack pointer's round trip through the cog object.
A *block* is a run of bytecodes from one hub address, compiled once into one
Python function that does the same work with the operands, stack offsets and
cycle counts folded into its text:

* **Timing is static inside a block.**  Every bytecode's fetch completes on
  the cog's hub window, and the rest of its path is a fixed count from there
  (docs/timing.md), so the fetch of bytecode ``j+1`` completes
  ``ceil16(rest_j + 12)`` cycles after the fetch of bytecode ``j``, whatever
  the window.  Only value-dependent paths (division, ENCODE, taken jumps,
  WAITCNT) add a term computed at run time.
* **Scheduling is unchanged.**  The interpreter starts a bytecode only while
  its hub access comes before the next access of any other cog
  (:meth:`Scheduler._run_spin`).  A block first checks that its *last*
  access, with the slowest value-dependent paths, is still before that
  limit; if not, it does nothing and the run loop interprets bytecodes one by
  one as before.
* **Rare things are left to the interpreter** ("deoptimisation"): a write to
  a hub long that a parked busy loop reads or that holds compiled code, an
  unusual stack pointer, a call that would overflow the stack.  The block
  then stops *before* that bytecode, with the cog in exactly the state the
  interpreter would have it in, and the run loop interprets the bytecode.
* **Code may change.**  A block compares its code bytes with hub RAM when it
  starts (any writer, even a stack push, can change them) and is recompiled
  if they differ; writes that go through the checked paths to a long holding
  compiled code leave the block first (``Chip.watch`` bit ``CODE``), so a
  block never runs bytes that its own earlier bytecodes changed.

Compiled: constants, VAR/LOC longs, memory access with every assignment
operator but the undefined ones, math, FRAME, CALL, CALL_OBJ, RETURN,
jumps, REPEAT, CASE tests and WAITCNT.  Everything touching registers, pins,
cogs, locks or the clock is interpreted.

A block function is called as ``f(cog, tf, limit)`` with ``tf`` the cycle its
first fetch completes; it returns the start cycle of the cog's next bytecode,
``-1`` when it did nothing, or ``-2 - t`` when it stopped early before a
bytecode starting at ``t`` that the interpreter must run.
"""
from __future__ import annotations

from .mathops import BINARY, MASK32, UNARY
from .spin import random_forward, random_reverse
from .timing import MATH_REF

__all__ = ["BlockCompiler", "MAX_OPS", "HOT", "CODE", "BUSY", "PROGRAM", "WATCHPOINT"]

#: bytecodes in one block at most
MAX_OPS = 48
#: times a block start is reached before it is compiled (cold code stays interpreted)
HOT = 8
#: ``Chip.watch`` bits: a parked busy loop reads the long, compiled code lies in it
BUSY, CODE = 1, 2
#: ``Chip.watch`` bits: the program's own code (runtime check), a debugger watchpoint
PROGRAM, WATCHPOINT = 4, 8

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


_BASE_LOCALS = {"vbase": "vb", "dbase": "db", "pbase": "pb"}


class _Stop(Exception):
    """The bytecode cannot be compiled: the block ends before it."""


def _ceil16(x: int) -> int:
    return x + (-x & 15)


def _is_literal(expr: str) -> bool:
    return expr.isdigit()


class _Block:
    """Compile-time state of one block being generated."""

    def __init__(self, start: int):
        self.start = start
        self.lines: list = []           # the body, indented one level
        self.off = 0                    # stack offset (bytes) from the stack pointer at entry
        self.lo = 0                     # lowest and highest stack byte offsets touched
        self.hi = 0
        self.vals: dict = {}            # stack offset -> expression of the long stored there
        self.names = 0
        self.n = 0                      # bytecodes compiled
        self.d = 0                      # the current fetch is at tf + d ...
        self.tf = "tf"                  # ... where tf is this local
        self.worst = 0                  # latest possible current fetch, from the block's first
        self.reach = 0                  # latest possible hub access, from the first fetch
        self.t_start = None             # expression: start cycle of the current bytecode
        self.pc = start                 # address of the current bytecode
        self.op_pc = start
        self.op_off = 0                 # stack offset when the current bytecode started
        self.bases: set = set()         # cog fields read into locals at entry
        self.end = False

    def snapshot(self) -> dict:
        state = dict(self.__dict__)
        state["lines"] = len(self.lines)
        state["vals"] = dict(self.vals)
        state["bases"] = set(self.bases)
        return state

    def restore(self, state: dict) -> None:
        lines = self.lines
        del lines[state["lines"]:]
        self.__dict__.update(state)
        self.lines = lines
        self.pc = self.op_pc

    def name(self, prefix="v") -> str:
        self.names += 1
        return f"{prefix}{self.names}"

    def emit(self, line: str, indent: int = 0) -> None:
        self.lines.append("    " * (indent + 1) + line)

    def let(self, expr: str) -> str:
        """A name or literal holding ``expr``."""
        if expr.isidentifier() or _is_literal(expr):
            return expr
        v = self.name()
        self.emit(f"{v} = {expr}")
        return v

    @staticmethod
    def slot(off: int) -> str:
        k = off // 4
        return "L[i]" if k == 0 else f"L[i + {k}]" if k > 0 else f"L[i - {-k}]"

    def touch(self, off: int, size: int = 4) -> None:
        self.lo = min(self.lo, off)
        self.hi = max(self.hi, off + size)

    def read(self, off: int) -> str:
        v = self.vals.get(off)
        if v is None:
            self.touch(off)
            v = self.name()
            self.emit(f"{v} = {self.slot(off)}")
            self.vals[off] = v
        return v

    def write(self, off: int, expr: str) -> str:
        v = self.let(expr)
        self.touch(off)
        self.emit(f"{self.slot(off)} = {v}")
        self.vals[off] = v
        return v

    def push(self, expr: str) -> str:
        v = self.write(self.off, expr)
        self.off += 4
        return v

    def pop(self) -> str:
        self.off -= 4
        return self.read(self.off)

    def peek(self) -> str:
        return self.read(self.off - 4)

    def base(self, field: str) -> str:
        """The local holding cog field ``field`` (read once at entry)."""
        self.bases.add(field)
        return _BASE_LOCALS[field]

    def forget(self) -> None:
        """A write to a computed address may have hit a stack slot: reread them."""
        self.vals.clear()

    def sp_expr(self, off: int = None) -> str:
        off = self.off if off is None else off
        return "sp" if off == 0 else f"sp + {off}" if off > 0 else f"sp - {-off}"

    def exit_lines(self, pc_expr: str, indent: int = 0) -> None:
        """Write the cog's pc, sp and bytecode count back (before a return)."""
        self.emit(f"c.pc = {pc_expr}", indent)
        self.emit(f"c.sp = {self.sp_expr()}", indent)
        self.emit(f"c.bytecodes += {self.n + 1}", indent)

    def deopt(self, cond: str) -> None:
        """Leave the block before the current bytecode when ``cond`` holds."""
        if self.n == 0:
            self.emit(f"if {cond}: return -1")
            return
        self.emit(f"if {cond}:")
        self.emit(f"c.pc = {self.op_pc}", 1)
        self.emit(f"c.sp = {self.sp_expr(self.op_off)}", 1)
        self.emit(f"c.bytecodes += {self.n}", 1)
        self.emit(f"return -2 - ({self.t_start})", 1)

    def now(self, extra: int = 0) -> str:
        d = self.d + extra
        return self.tf if d == 0 else f"{self.tf} + {d}"


class BlockCompiler:
    """Compiles blocks for one chip.

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip` (memory views, watch
            flags, timing, access offsets).
        table: the list of block functions by hub address (filled in here).
        stub: what ``table`` holds for an address with no compiled block.
    """

    def __init__(self, chip, table: list, stub):
        self.chip = chip
        self.T = chip.timing
        self.acc = chip.access_at
        self.mem = chip.mem
        self.table = table
        self.boundaries: set = set(chip.interpret_only)   # addresses a block must start at (busy-loop heads)
        self.interpret_only = chip.interpret_only          # ... and ones no block may start at
        self.interpret_calls = chip.interpret_calls        # calls stay interpreted (runtime checks)
        self.checks = chip.checks if chip.checks is not None and chip.checks.wants("waitcnt-passed") else None
        self.compiled: dict = {}          # start -> end of every compiled block
        self.env = {
            "L": chip.mem_longs, "W": chip.mem_words, "mem": chip.mem, "WATCH": chip.watch,
            "B": table, "STUB": stub, "RF": random_forward, "RR": random_reverse,
            "CHECKS": chip.checks,
        }
        for f, fn in enumerate(BINARY):
            if fn is not None:
                self.env[f"B{f:02X}"] = fn
        for f, fn in enumerate(UNARY):
            if fn is not None:
                self.env[f"U{f:02X}"] = fn
        for f, table_f in enumerate(self.T._math):
            self.env[f"MT{f:02X}"] = tuple(table_f)
        self.count = 0

    # ------------------------------------------------------------------ public
    def compile(self, pc: int):
        """The block function for hub address ``pc``, or ``None`` if its first bytecode is not compiled."""
        if pc in self.interpret_only:
            return None
        b = _Block(pc)
        while True:
            if b.pc >= 0xFFF0 or b.n >= MAX_OPS or (b.n and b.pc in self.boundaries):
                break
            b.op_pc, b.op_off = b.pc, b.off
            saved = b.snapshot()
            try:
                self._op(b)
            except _Stop:
                b.restore(saved)
                break
            b.n += 1
            if b.end:
                break
        if b.n == 0:
            return None
        if not b.end:
            b.emit(f"c.pc = {b.pc}")
            b.emit(f"c.sp = {b.sp_expr()}")
            b.emit(f"c.bytecodes += {b.n}")
            b.emit(f"return {b.t_start}")
        return self._finish(b)

    def add_boundary(self, pc: int) -> None:
        """Make ``pc`` a block start: no block runs through it (the fast-forward stops there)."""
        if pc in self.boundaries:
            return
        self.boundaries.add(pc)
        for start, end in list(self.compiled.items()):
            if start < pc < end:
                self.table[start] = self.env["STUB"]
                del self.compiled[start]

    # ------------------------------------------------------------------ assembly
    def _finish(self, b: _Block):
        start, end = b.start, b.pc
        code = bytes(self.mem[start:end])
        head = ["def blk(c, tf, limit):",
                f"    if tf + {b.reach} >= limit: return -1",
                f"    if mem[{start}:{end}] != K: B[{start}] = STUB; return -1",
                "    sp = c.sp"]
        # the stack bytes the block touches must be in hub RAM and away from its own code
        lo, hi = b.lo, b.hi
        head.append(f"    if sp & 3 or sp < {max(-lo, end - lo)} or sp > {0x10000 - hi}:")
        head.append(f"        if sp & 3 or sp < {-lo} or sp > {min(0x10000 - hi, start - hi)}: return -1")
        head.append("    i = sp >> 2")
        for field in sorted(b.bases):
            head.append(f"    {_BASE_LOCALS[field]} = c.{field}")
        src = "\n".join(head + b.lines) + "\n"
        ns: dict = {}
        env = dict(self.env)
        env["K"] = code
        exec(compile(src, f"<spin block ${start:04X}>", "exec"), env, ns)
        fn = ns["blk"]
        fn.source = src
        self.compiled[start] = end
        watch = self.chip.watch
        for k in range(start >> 2, ((end - 1) >> 2) + 1):
            watch[k] |= CODE
        self.count += 1
        return fn

    # ------------------------------------------------------------------ timing
    def _account(self, b: _Block, op: int, rest, worst: int = None) -> None:
        """Close bytecode ``op`` (started at the current fetch) whose path takes ``rest``.

        ``rest`` is an int or an expression (``worst``: its largest value).
        """
        b.reach = max(b.reach, b.worst + self.acc[op])
        if isinstance(rest, int):
            b.t_start = b.now(rest)
            b.d += _ceil16(rest + 12)
            b.worst += _ceil16(rest + 12)
        else:
            x = b.name("x")
            tf = b.name("T")
            b.emit(f"{x} = {rest} + 12")
            b.emit(f"{tf} = {b.now()} + {x} + (-{x} & 15)")
            b.t_start = f"{tf} - 12 - (-{x} & 15)"
            b.tf, b.d = tf, 0
            b.worst += _ceil16(worst + 12)

    def _terminal_rest(self, b: _Block, op: int) -> None:
        b.reach = max(b.reach, b.worst + self.acc[op])

    # ------------------------------------------------------------------ operands
    def _byte(self, b: _Block) -> int:
        v = self.mem[b.pc]
        b.pc += 1
        return v

    def _jump_operand(self, b: _Block):
        x = self._byte(b)
        if x & 0x80:
            v = ((x & 0x7F) << 8) | self._byte(b)
            return (v - 0x8000 if v & 0x4000 else v), True
        return (x - 0x80 if x & 0x40 else x), False

    def _jump_target(self, b: _Block, wrap: bool = False) -> tuple:
        off, long_ = self._jump_operand(b)
        target = b.pc + off
        if wrap:
            target &= 0xFFFF
        if not 0 <= target < 0x10000:
            raise _Stop
        return target, long_

    # ------------------------------------------------------------------ bytecodes
    def _op(self, b: _Block) -> None:
        op = self._byte(b)
        if op >= 0xE0:
            return self._math(b, op)
        if op >= 0x80:
            return self._mem(b, op)
        if op >= 0x40:
            return self._var(b, op)
        T = self.T
        if 0x34 <= op <= 0x36:
            b.push(("4294967295", "0", "1")[op - 0x34])
            return self._account(b, op, T.push_const)
        if op == 0x37:
            m = self._byte(b)
            v = (2 << (m & 0x1F)) & MASK32
            if m & 0x20:
                v = (v - 1) & MASK32
            if m & 0x40:
                v ^= MASK32
            b.push(str(v))
            return self._account(b, op, T.push_mask)
        if 0x38 <= op <= 0x3B:
            n = op - 0x37
            v = int.from_bytes(self.mem[b.pc:b.pc + n], "big")
            b.pc += n
            b.push(str(v))
            return self._account(b, op, T.push_imm[n])
        if op <= 0x03:
            return self._frame(b, op)
        if op in (0x05, 0x06):
            return self._call(b, op)
        if op in (0x32, 0x33):
            return self._return(b, op)
        if op in (0x04, 0x08, 0x09, 0x0A, 0x0B, 0x0D, 0x0E):
            return self._jump(b, op)
        if op == 0x23:
            return self._waitcnt(b, op)
        raise _Stop

    def _math(self, b: _Block, op: int) -> None:
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
            elif f in _BINARY_EXPR:
                new = _BINARY_EXPR[f].format(x=x, y=y)
            else:
                new = f"B{f:02X}({x}, {y})"
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
    def _var(self, b: _Block, op: int) -> None:
        off = op & 0x1C
        base = b.base("dbase" if op & 0x20 else "vbase")
        access = op & 3
        T = self.T
        addr = f"({base} + {off}) & 0xFFFF"
        if access == 0:
            b.push(f"L[(({base} + {off}) & 0xFFFF) >> 2]")
            return self._account(b, op, T.var[op])
        if access == 3:
            b.push(addr)
            return self._account(b, op, T.var[op])
        a = b.let(addr)
        b.deopt(f"{a} >= 0x8000 or WATCH[{a} >> 2]")
        if access == 1:
            v = b.pop()
            b.emit(f"if {a} < 0x8000: L[{a} >> 2] = {v}")
            b.forget()
            return self._account(b, op, T.var[op])
        old = b.let(f"L[{a} >> 2]")
        aop = self._byte(b)
        res = self._assign(b, aop, old, op, T.var_using[bool(op & 0x20)])
        new = res[0]
        b.emit(f"if {a} < 0x8000: L[{a} >> 2] = {new}")
        b.forget()
        self._assign_close(b, op, res)

    # -- memory ($80-$DF)
    def _mem(self, b: _Block, op: int) -> None:
        size = (op >> 5) & 3
        base = (op >> 2) & 3
        indexed = op & 0x10
        access = op & 3
        T = self.T
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
        if access == 0:
            b.push(self._sized_read(size, a))
            return self._account(b, op, rest)
        # writes: leave the block first if the long is watched
        w = b.let(f"{a} & 0xFFFF")
        b.deopt(f"{w} >= 0x8000 or WATCH[{w} >> 2]")
        if access == 1:
            v = b.pop()
            b.emit(f"if {w} < 0x8000: {self._sized_store(size, w, v)}")
            b.forget()
            return self._account(b, op, rest)
        old = b.let(self._sized_read(size, a))
        aop = self._byte(b)
        res = self._assign(b, aop, old, op, rest)
        b.emit(f"if {w} < 0x8000: {self._sized_store(size, w, res[0])}")
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
    def _assign(self, b: _Block, a: int, v: str, op: int, base_rest: int):
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
            expr = _BINARY_EXPR[f].format(x=v, y=y) if f in _BINARY_EXPR else f"B{f:02X}({v}, {y})"
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

    def _assign_close(self, b: _Block, op: int, res) -> None:
        if len(res) == 4:                               # REPEAT: a conditional jump
            return self._branch(b, op, res[1], res[2], res[3])
        self._account(b, op, *res[1:])

    def _repeat(self, b: _Block, a: int, v: str, op: int, base_rest: int):
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

    # -- control flow (the block ends)
    def _branch(self, b: _Block, op: int, cond: str, yes, no) -> None:
        """End the block: go to ``yes = (pc, rest)`` if ``cond`` holds, else to ``no``."""
        self._terminal_rest(b, op)
        b.emit(f"if {cond}:")
        b.exit_lines(str(yes[0]), 1)
        b.emit(f"return {b.now(yes[1])}", 1)
        b.exit_lines(str(no[0]))
        b.emit(f"return {b.now(no[1])}")
        b.end = True

    def _jump(self, b: _Block, op: int) -> None:
        T = self.T
        target, long_ = self._jump_target(b)
        nxt = b.pc
        if op == 0x04:                                  # JMP
            self._terminal_rest(b, op)
            b.exit_lines(str(target))
            b.emit(f"return {b.now(T.jmp[long_])}")
            b.end = True
            return
        if op == 0x08:                                  # TJZ: pop only when jumping
            v = b.peek()
            self._terminal_rest(b, op)
            b.emit(f"if {v} == 0:")
            b.off -= 4
            b.exit_lines(str(target), 1)
            b.off += 4
            b.emit(f"return {b.now(T.tjz[(long_, True)])}", 1)
            b.exit_lines(str(nxt))
            b.emit(f"return {b.now(T.tjz[(long_, False)])}")
            b.end = True
            return
        if op == 0x09:                                  # DJNZ
            v = b.let(f"({b.peek()} - 1) & 0xFFFFFFFF")
            b.touch(b.off - 4)
            self._terminal_rest(b, op)
            b.emit(f"if {v}:")
            b.emit(f"{b.slot(b.off - 4)} = {v}", 1)     # written back only when it loops (0 is not)
            b.exit_lines(str(target), 1)
            b.emit(f"return {b.now(T.djnz[(long_, True)])}", 1)
            b.off -= 4
            b.exit_lines(str(nxt))
            b.emit(f"return {b.now(T.djnz[(long_, False)])}")
            b.end = True
            return
        if op in (0x0A, 0x0B):                          # JZ / JNZ
            v = b.pop()
            table = T.jz if op == 0x0A else T.jnz
            cond = f"{v} == 0" if op == 0x0A else f"{v} != 0"
            return self._branch(b, op, cond, (target, table[(long_, True)]), (nxt, table[(long_, False)]))
        if op == 0x0D:                                  # CASE value
            v = b.pop()
            cur = b.peek()
            return self._branch(b, op, f"{v} == {cur}", (target, T.case_value[(long_, True)]),
                                (nxt, T.case_value[(long_, False)]))
        # CASE range (0x0E)
        hi = b.pop()
        lo = b.pop()
        x = b.peek()
        s = lambda e: f"(({e} ^ 0x80000000) - 0x80000000)"
        lo_, hi_ = b.name(), b.name()
        b.emit(f"{lo_} = {s(lo)}")
        b.emit(f"{hi_} = {s(hi)}")
        b.emit(f"if {lo_} > {hi_}: {lo_}, {hi_} = {hi_}, {lo_}")
        return self._branch(b, op, f"{lo_} <= {s(x)} <= {hi_}", (target, T.case_range[(long_, True)]),
                            (nxt, T.case_range[(long_, False)]))

    def _waitcnt(self, b: _Block, op: int) -> None:
        T = self.T
        target = b.pop()
        self._terminal_rest(b, op)
        issue = T.waitcnt_issue + T.waitcnt_min
        b.exit_lines(str(b.pc))
        if self.checks is None:
            b.emit(f"return {b.now(issue + T.waitcnt_after)} + (({target} - ({b.now(issue)})) & 0xFFFFFFFF)")
        else:                                           # the runtime check for a count already passed
            b.emit(f"w = ({target} - ({b.now(issue)})) & 0xFFFFFFFF")
            b.emit("if w & 0x80000000:")
            b.emit(f"CHECKS.waitcnt(c, {target}, w, {b.now()})", 1)
            b.emit(f"return {b.now(issue + T.waitcnt_after)} + w")
        b.end = True

    def _frame(self, b: _Block, op: int) -> None:
        o = b.off
        b.touch(o, 12)
        sp = b.sp_expr()
        b.emit(f"s = {sp}")
        b.emit(f"W[s >> 1] = (c.pbase | {op}) & 0xFFFF")
        b.emit("W[(s + 2) >> 1] = c.vbase")
        b.emit("W[(s + 4) >> 1] = c.dbase")
        b.emit("W[(s + 6) >> 1] = c.dcall & 0xFFFF")
        b.emit("c.dcall = s + 6")
        b.vals.pop(o, None)
        b.vals.pop(o + 4, None)
        b.write(o + 8, "0")
        b.off = o + 12
        self._account(b, op, self.T.frame)

    def _call(self, b: _Block, op: int) -> None:
        T = self.T
        if self.interpret_calls:
            raise _Stop
        if op == 0x06:
            obj = self._byte(b)
        m = self._byte(b)
        ret = b.pc
        if ret > 0xFFFF:
            raise _Stop
        self._terminal_rest(b, op)
        b.emit("pb = c.pbase")
        b.emit("pbh = c.pbase_hi")
        if op == 0x06:
            b.emit(f"e = L[((pb + {4 * obj}) & 0xFFFF) >> 2]")
            b.emit("full = ((pbh << 16 | pb) + e) & 0xFFFFFFFF")
            b.emit("pb = full & 0xFFFF")
            b.emit("pbh = full >> 16")
            b.emit("vbn = (c.vbase + (e >> 16)) & 0xFFFF")
        b.emit(f"ent = L[((pb + {4 * m}) & 0xFFFF) >> 2]")
        b.emit("f6 = c.dcall")
        b.emit(f"nsp = {b.sp_expr()} + (ent >> 16)")
        b.deopt("nsp > c.stack_end or not 0 <= f6 < 0x10000")
        if op == 0x06:
            b.emit("c.pbase = pb")
            b.emit("c.pbase_hi = pbh")
            b.emit("c.vbase = vbn")
        b.emit("c.dcall = W[f6 >> 1]")
        b.emit(f"W[f6 >> 1] = {ret}")
        b.emit("c.dbase = (f6 + 2) & 0xFFFF")
        b.emit("full = (pbh << 16 | pb) + ent")
        b.emit("c.pc = full & 0xFFFF")
        b.emit("c.pc_hi = (full >> 16) & 0xFFFF")
        b.emit("c.sp = nsp")
        b.emit(f"c.bytecodes += {b.n + 1}")
        b.emit(f"return {b.now(T.call_obj if op == 0x06 else T.call)}")
        b.end = True

    def _return(self, b: _Block, op: int) -> None:
        T = self.T
        self._terminal_rest(b, op)
        b.emit("d = c.dbase")
        b.deopt("not 8 <= d < 0x10000")
        value = b.pop() if op == 0x33 else b.let("L[d >> 2]")
        b.emit("c.pc = W[(d - 2) >> 1]")
        b.emit("c.pc_hi = 0")
        b.emit("c.dbase = W[(d - 4) >> 1]")
        b.emit("c.vbase = W[(d - 6) >> 1]")
        b.emit("flags = W[(d - 8) >> 1]")
        b.emit("c.pbase = flags & 0xFFFC")
        b.emit("c.pbase_hi = 0")
        b.emit(f"c.bytecodes += {b.n + 1}")
        b.emit("if flags & 1:")
        b.emit("c.sp = d - 8", 1)
        b.emit(f"return {b.now(T.returns(op, 1, False))}", 1)
        b.emit(f"L[(d - 8) >> 2] = {value}")
        b.emit("c.sp = d - 4")
        b.emit(f"return {b.now(T.returns(op, 1, True))}")
        b.end = True
