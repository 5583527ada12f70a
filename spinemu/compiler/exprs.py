"""Spin expressions to bytecode (the opcode values come from spinemu.bytecode).

What OpenSpin 1.00.81 does, and this module copies (observed with probes):

* no constant folding of operators: ``3 + 4`` pushes 3, pushes 4, adds; only
  a literal, a constant name, ``obj#NAME``, a character, ``constant()``,
  ``float()``, ``round()``, ``trunc()`` and ``-`` written directly before a
  literal or a name (``-5``, ``-K``, but not ``-(5)``, ``-constant(5)`` or
  ``-obj#K``, which negate at run time) become one constant;
* constants: -1, 0, 1 have their own opcodes; values of the form
  ``2 << n`` (optionally minus 1, optionally inverted) use PUSH_MASK; other
  values use PUSH_IMM1..4, or the inverted value followed by BIT_NOT when
  that is shorter (-255 is ``38 FE E7``);
* a long VAR or local variable below offset 32 that is not indexed uses the
  one-byte forms $40-$7F; everything else the $80-$DF memory forms;
* an assignment used as a value ends with the "push" bit set.
"""
from __future__ import annotations

from contextlib import nullcontext

from ..bytecode import BY_MNEMONIC, MATH_BY_SYMBOL, REGISTER_NAMES, encode_unsigned, mask_code
from .. import messages as msg
from ..frontend.ast import (
    walk,
    Assign, Builtin, Call, Float, KConst, MemberRef, MemRef, NameRef, Number, ObjCall, ObjConst, Paren,
    Range, RegRef, ResultRef, SprRef, Str, Unary, key,
)
from ..frontend.constants import Const, ConstError, NotConstant, evaluate
from .code import Label
from .dat import DatSymbol
from .symbols import LocalSymbol, MethodSymbol, ObjSymbol, VarSymbol

__all__ = ["ExprCompiler", "push_const_bytes", "CompileFailure"]

PUSH, POP, USING, ADDR = 0, 1, 2, 3
_SIZE_BITS = {1: 0, 2: 1, 4: 2}
_BASE_BITS = {"MEM": 0, "OBJ": 1, "VAR": 2, "LOC": 3}
_REG_INDEX = {name.lower(): addr - 0x1E0 for addr, name in REGISTER_NAMES.items()}
_OP = {name: op.code for name, op in BY_MNEMONIC.items()}

# assignment-operator bytes (see spinemu.bytecode ASSIGN_OPS)
_PRE_POST = {("pre", "++"): 0x20, ("post", "++"): 0x28, ("pre", "--"): 0x30, ("post", "--"): 0x38,
             ("pre", "~"): 0x10, ("pre", "~~"): 0x14, ("post", "~"): 0x18, ("post", "~~"): 0x1C,
             ("pre", "?"): 0x08, ("post", "?"): 0x0C}
_INCDEC_SIZE = {0: 0, 1: 1, 2: 2, 4: 3}
_WRITE = 0x00
_PUSH_BIT = 0x80
_MATH_BIT = 0x40

_SIMPLE_BUILTINS = {
    # name: (argument count, opcode as a statement, opcode as a value)
    "bytemove": (3, "BYTEMOVE", None), "wordmove": (3, "WORDMOVE", None),
    "longmove": (3, "LONGMOVE", None), "bytefill": (3, "BYTEFILL", None),
    "wordfill": (3, "WORDFILL", None), "longfill": (3, "LONGFILL", None),
    "waitcnt": (1, "WAITCNT", None), "waitpeq": (3, "WAITPEQ", None),
    "waitpne": (3, "WAITPNE", None), "waitvid": (2, "WAITVID", None),
    "clkset": (2, "CLKSET", None), "cogstop": (1, "COGSTOP", None),
    "lockret": (1, "LOCKRET", None), "strsize": (1, None, "STRSIZE"),
    "strcomp": (2, None, "STRCOMP"), "lockset": (1, "LOCKSET", "LOCKSET_RESULT"),
    "lockclr": (1, "LOCKCLR", "LOCKCLR_RESULT"), "locknew": (0, "LOCKNEW", "LOCKNEW_RESULT"),
}
_FOLDED_BUILTINS = ("constant", "float", "round", "trunc")


class CompileFailure(Exception):
    """Stops compiling the current statement after an error was reported."""


def push_const_bytes(bits: int) -> bytes:
    """The shortest push of a 32-bit constant, chosen as OpenSpin chooses.

    >>> push_const_bytes(0xFFFFFFFF).hex(), push_const_bytes(3).hex(), push_const_bytes(-255 & 0xFFFFFFFF).hex()
    ('34', '3721', '38fee7')
    >>> push_const_bytes(1000).hex(), push_const_bytes(0xFF123456).hex()
    ('3903e8', '3bff123456')
    """
    bits &= 0xFFFFFFFF
    if bits == 0xFFFFFFFF:
        return b"\x34"
    if bits in (0, 1):
        return bytes((0x35 + bits,))
    m = mask_code(bits)
    if m is not None:
        return bytes((0x37, m))
    direct = _imm(bits)
    inverted = _imm(bits ^ 0xFFFFFFFF)
    if len(inverted) + 1 < len(direct):
        return inverted + b"\xE7"
    return direct


def _has_string(node) -> bool:
    """Whether ``string(...)`` appears anywhere in ``node``."""
    return any(type(n) is Builtin and n.name == "string" for n in walk(node))


def _imm(v: int) -> bytes:
    n = 1 if v < 0x100 else 2 if v < 0x10000 else 3 if v < 0x1000000 else 4
    return bytes((0x37 + n,)) + v.to_bytes(n, "big")


def _mem_op(access: int, size: int, base: str, indexed: bool) -> int:
    return 0x80 | (_SIZE_BITS[size] << 5) | (0x10 if indexed else 0) | (_BASE_BITS[base] << 2) | access


def _table_index(index: int) -> int:
    """A method or object table index for a CALL byte; past 255 the object has more methods and
    object instances than a table holds, which is reported already: stop compiling this expression."""
    if index > 0xFF:
        raise CompileFailure()
    return index


class ExprCompiler:
    """Expression code generation; a MethodCompiler (stmts.py) adds statements.

    Needs ``self.code`` (CodeBuffer), ``self.obj`` (object context with
    ``symbols``, ``const``, ``child_method``), ``self.frame`` (local symbols)
    and ``self.error(message, node)``.
    """

    # ------------------------------------------------------------------ lookups
    def lookup(self, name: str):
        k = key(name)
        if k in self.frame:
            return self.frame[k]
        return self.obj.symbols.get(k)

    def constant_of(self, node):
        """The Const a term stands for, or None if it is not a constant term."""
        t = type(node)
        if t is Number or t is Float or t is KConst:
            return self.fold(node)
        if t is Str:
            data = self.obj.char_bytes(node.text)
            return Const(data[0]) if len(data) == 1 else None
        if t is NameRef and node.index is None and key(node.name) not in self.frame:
            return self.obj.const(node.name)
        if t is ObjConst:
            return self.fold(node)
        if t is Builtin and node.name in _FOLDED_BUILTINS:
            starter = getattr(node, "starter", None)
            if starter is not None:
                return self.fold_group(node, starter)
            return self.fold(node)
        if t is Unary and node.op == "-" and not isinstance(node.operand, (Paren, Unary, Builtin, ObjConst)):
            inner = self.constant_of(node.operand)
            if inner is not None:
                return self.fold(node)
        return None

    def fold_group(self, node, starter: str) -> Const:
        """Fold a constant group begun by ``round(``/``trunc(``/``float(`` in code (frontend.builder)."""
        try:
            return evaluate(node, self.obj.resolve_const, self.obj.char_bytes)
        except (NotConstant, ConstError) as exc:
            bad = exc.node
            what = getattr(bad, "name", None)
            known = what is not None and (self.lookup(what) is not None or self.obj.has_method(what))
            if isinstance(exc, NotConstant) or known:
                self.error(msg.CONSTANT_GROUP.format(word=starter, what=f"'{what}'" if what else "this"), bad)
            else:
                self.error(exc.message, bad, getattr(exc, "name", None))
        raise CompileFailure()

    def fold(self, node) -> Const:
        """Fold a constant expression or report why it is not one."""
        try:
            return evaluate(node, self.obj.resolve_const, self.obj.char_bytes)
        except NotConstant as exc:
            self.error(msg.NEEDS_CONSTANT, exc.node)
        except ConstError as exc:
            self.error(exc.message, exc.node, getattr(exc, "name", None))
        raise CompileFailure()

    # ------------------------------------------------------------------ values
    def push_const(self, bits: int, note: str = "") -> None:
        self.code.emit(push_const_bytes(bits), note)

    def expr(self, node) -> None:
        """Compile ``node`` so that its value is pushed."""
        c = self.constant_of(node)
        if c is not None:
            self.push_const(c.bits, "constant")
            return
        getattr(self, "x_" + type(node).__name__)(node)

    def x_Here(self, node) -> None:
        self.error(msg.HERE_OUTSIDE_DAT, node)
        raise CompileFailure()

    def x_LocalLabel(self, node) -> None:
        self.error(msg.LOCAL_LABEL_OUTSIDE_DAT.format(name=node.name), node)
        raise CompileFailure()

    def x_Range(self, node) -> None:
        self.error(msg.RANGE_NOT_ALLOWED, node)
        raise CompileFailure()

    def x_Paren(self, node) -> None:
        self.expr(node.expr)

    def x_Str(self, node) -> None:
        self.error(msg.STRING_TOO_LONG, node)
        raise CompileFailure()

    def x_NameRef(self, node) -> None:
        sym = self.lookup(node.name)
        if isinstance(sym, MethodSymbol) or (sym is None and self.obj.has_method(node.name)):
            self.call(Call(node.pos, node.name, []), want=True)
            return
        self.var(node, PUSH)

    x_MemberRef = x_MemRef = x_RegRef = x_SprRef = x_ResultRef = \
        lambda self, node: self.var(node, PUSH)

    def x_Unary(self, node) -> None:
        self.expr(node.operand)
        if node.op == "+":
            return
        self.code.emit(MATH_BY_SYMBOL[(node.op, True)].code, node.op)

    def x_Binary(self, node) -> None:
        self.expr(node.left)
        self.expr(node.right)
        self.code.emit(MATH_BY_SYMBOL[(node.op, False)].code, node.op)

    def x_Assign(self, node) -> None:
        self.assign(node, push=True)

    def x_PreOp(self, node) -> None:
        self.step(node, "pre", push=True)

    def x_PostOp(self, node) -> None:
        self.step(node, "post", push=True)

    def x_AddrOf(self, node) -> None:
        self.var(node.target, ADDR)

    def x_ObjAddr(self, node) -> None:
        self.expr(node.operand)
        self.code.emit((_mem_op(ADDR, 1, "OBJ", True), 0), "@@")

    def x_Call(self, node) -> None:
        self.call(node, want=True)

    x_ObjCall = x_Call

    def x_AbortTrap(self, node) -> None:
        self.call(node.call, want=True, trap=True)

    def x_Lookup(self, node) -> None:
        with self.code.block():     # OpenSpin compiles it until it settles (code.py)
            self._lookup(node)

    def _lookup(self, node) -> None:
        end = Label("lookup end")
        self.code.emit(0x36 if node.name in ("lookup", "lookdown") else 0x35, node.name)
        self.code.push_address(end)
        self.expr(node.value)
        down = node.name.startswith("lookdown")
        value_op = _OP["LOOKDOWN_VALUE" if down else "LOOKUP_VALUE"]
        range_op = _OP["LOOKDOWN_RANGE" if down else "LOOKUP_RANGE"]
        for item in node.items:
            if isinstance(item, Range):
                self.expr(item.low)
                self.expr(item.high)
                self.code.emit(range_op)
            elif isinstance(item, Str) and len(self.obj.char_bytes(item.text)) > 1:
                for b in self.obj.char_bytes(item.text):
                    self.push_const(b)
                    self.code.emit(value_op)
            else:
                self.expr(item)
                self.code.emit(value_op)
        self.code.emit(_OP["LOOK_DONE"])
        self.code.mark(end)

    def x_Builtin(self, node) -> None:
        self.builtin(node, want=True)

    # ------------------------------------------------------------------ variables
    def var(self, node, access: int) -> None:
        """Compile an access (push/pop/using/address) of a variable-like node."""
        code = self.code
        t = type(node)
        if t is NameRef:
            sym = self.lookup(node.name)
            if sym is None:
                self.undefined(node.name, node)
            self.sym_access(sym, node, node.index, access, None, node)
        elif t is ResultRef:
            self.sym_access(LocalSymbol("result", 0, 1), node, node.index, access, None, node)
        elif t is MemberRef:
            base = node.base
            if isinstance(base, ResultRef):
                sym = LocalSymbol("result", 0, 1)
            else:
                sym = self.lookup(base.name)
                if sym is None:
                    self.undefined(base.name, base)
            self.sym_access(sym, base, node.sub, access, node.size, node)
        elif t is MemRef:
            self.expr(node.base)
            if node.index is not None:
                self.expr(node.index)
            code.emit(_mem_op(access, node.size, "MEM", node.index is not None))
        elif t is RegRef:
            if access == ADDR:
                self.error(msg.NOT_A_VARIABLE.format(name=node.name), node)
                raise CompileFailure()
            reg = 0x80 | (access << 5) | _REG_INDEX[node.name]
            if node.bit is None:
                code.emit((_OP["REG"], reg), node.name)
            elif node.bit2 is None:
                self.expr(node.bit)
                code.emit((_OP["REG_BIT"], reg), node.name + "[bit]")
            else:
                self.expr(node.bit)
                self.expr(node.bit2)
                code.emit((_OP["REG_RANGE"], reg), node.name + "[range]")
        elif t is SprRef:
            if access == ADDR:
                self.error(msg.NOT_A_VARIABLE.format(name="spr"), node)
                raise CompileFailure()
            self.expr(node.index)
            code.emit(_OP[("PUSH_SPR", "POP_SPR", "USING_SPR")[access]], "spr")
        elif t is Paren:
            self.var(node.expr, access)
        else:
            self.error(msg.NOT_ASSIGNABLE if access != PUSH else msg.NEEDS_VALUE.format(name="?"), node)
            raise CompileFailure()

    def sym_access(self, sym, name_node, index, access, size_override, node) -> None:
        if isinstance(sym, LocalSymbol):
            base, offset, size = "LOC", sym.offset, 4
        elif isinstance(sym, VarSymbol):
            base, offset, size = "VAR", sym.offset, sym.size
        elif isinstance(sym, DatSymbol) and not sym.reserved:
            base, offset, size = "OBJ", sym.offset, sym.size
        else:
            what = getattr(name_node, "name", "?")
            self.error(msg.NOT_A_VARIABLE.format(name=what), name_node)
            raise CompileFailure()
        if size_override is not None:
            if size_override > size:
                self.error(msg.DATA_SIZE_OVERRIDE, node)
                raise CompileFailure()
            size = size_override
        if index is not None:
            self.expr(index)
        if base != "OBJ" and size == 4 and index is None and offset < 32 and (offset & 3) == 0:
            self.code.emit((0x40 | (0x20 if base == "LOC" else 0) | offset | access),
                           getattr(name_node, "name", "result"))
            return
        # Past $7FFF only a local at exactly $8000 (OpenSpin writes it as $80 $00, offset 0 on the chip)
        # or an object already reported too big (VAR or DAT over 32 KB): keep 15 bits, as OpenSpin does.
        operand = encode_unsigned(offset & 0x7FFF, force_long=offset > 0x7F)
        self.code.emit(bytes((_mem_op(access, size, base, index is not None),)) + operand,
                       getattr(name_node, "name", "result"))

    def undefined(self, name: str, node) -> None:
        self.error(msg.UNDEFINED.format(name=name), node, undefined=name)
        raise CompileFailure()

    def step_size(self, target) -> int:
        """The size field of ++/-- for ``target`` (0: a register bit field)."""
        t = type(target)
        if t is RegRef:
            return 0 if target.bit is not None else 4
        if t is MemRef:
            return target.size
        if t is MemberRef:
            return target.size
        if t is NameRef:
            sym = self.lookup(target.name)
            if isinstance(sym, VarSymbol):
                return sym.size
            if isinstance(sym, DatSymbol):
                return sym.size
        return 4

    # ------------------------------------------------------------------ assignments
    def assign(self, node: Assign, push: bool) -> None:
        # when the target holds a string, its strings and the value's share the pool as
        # OpenSpin allocates them (CodeBuffer.part)
        context = self.code.new_context() if _has_string(node.target) else None
        with self.string_part(context, "value"):
            self.expr(node.value)
        with self.string_part(context, "target"):
            if node.op == ":=":
                if push:
                    self.var(node.target, USING)
                    self.code.emit(_WRITE | _PUSH_BIT, ":=")
                else:
                    self.var(node.target, POP)
                return
            self.var(node.target, USING)
        op = MATH_BY_SYMBOL[(node.op, False)]
        self.code.emit(_MATH_BIT | (op.code & 0x1F) | (_PUSH_BIT if push else 0), node.op + "=")

    def string_part(self, context, role: str):
        """The strings compiled in the block are ``context``'s ``role`` (no context: nothing special)."""
        return self.code.part(context, role) if context is not None else nullcontext()

    def step(self, node, where: str, push: bool) -> None:
        op = _PRE_POST[(where, node.op)]
        if node.op in ("++", "--"):
            op |= _INCDEC_SIZE[self.step_size(node.target)] << 1
        self.var(node.target, USING)
        self.code.emit(op | (_PUSH_BIT if push else 0), node.op)

    # ------------------------------------------------------------------ calls
    def call(self, node, want: bool, trap: bool = False) -> None:
        frame = (0x02 if trap else 0x00) | (0x00 if want else 0x01)
        if isinstance(node, NameRef):
            node = Call(node.pos, node.name, [])
        if isinstance(node, Call):
            sym = self.obj.symbols.get(key(node.name))
            if not isinstance(sym, MethodSymbol):
                if sym is None:
                    self.undefined(node.name, node)
                self.error(msg.NOT_A_METHOD.format(name=node.name), node)
                raise CompileFailure()
            self.check_args(node.name, sym.nparams, node.args, node)
            self.code.emit(frame, "frame")
            for a in node.args:
                self.expr(a)
            self.code.emit((_OP["CALL"], _table_index(sym.index)), f"call {node.name}")
            return
        if isinstance(node, ObjCall):
            sym = self.obj.symbols.get(key(node.obj))
            if not isinstance(sym, ObjSymbol):
                if sym is None:
                    self.undefined(node.obj, node)
                self.error(msg.NOT_AN_OBJECT.format(name=node.obj), node)
                raise CompileFailure()
            target = self.obj.child_method(sym, node.method)
            if target is None:
                self.error(msg.UNKNOWN_METHOD_IN_OBJECT.format(obj=node.obj, name=node.method), node)
                raise CompileFailure()
            index, nparams = target
            self.check_args(node.method, nparams, node.args, node)
            self.code.emit(frame, "frame")
            # the index is compiled after the arguments: when it holds a string, the
            # arguments' strings share the pool as in an assignment
            context = self.code.new_context() if node.index is not None and _has_string(node.index) else None
            with self.string_part(context, "value"):
                for a in node.args:
                    self.expr(a)
            if node.index is None:
                self.code.emit((_OP["CALL_OBJ"], _table_index(sym.index), _table_index(index)),
                               f"call {node.obj}.{node.method}")
            else:
                with self.string_part(context, "target"):
                    self.expr(node.index)
                self.code.emit((_OP["CALL_OBJ_X"], _table_index(sym.index), _table_index(index)), f"call {node.obj}[].{node.method}")
            return
        self.error(msg.NOT_A_METHOD.format(name="?"), node)
        raise CompileFailure()

    def check_args(self, name, nparams, args, node) -> None:
        if len(args) != nparams:
            self.error(msg.WRONG_ARG_COUNT.format(name=name, expected=nparams,
                                                  s="" if nparams == 1 else "s", got=len(args)), node)
            raise CompileFailure()

    # ------------------------------------------------------------------ built-ins
    def builtin(self, node: Builtin, want: bool) -> None:
        name, args = node.name, node.args or []
        code = self.code
        if name in _SIMPLE_BUILTINS:
            count, stmt_op, value_op = _SIMPLE_BUILTINS[name]
            op = value_op if want else stmt_op
            if op is None or len(args) != count or (count and node.args is None):
                self.bad_builtin(node, count)
            for a in args:
                self.expr(a)
            code.emit(_OP[op], name)
            return
        if name in ("cognew", "coginit"):
            self.cog_start(node, want)
            return
        if name == "string":
            if not want or not args:
                self.bad_builtin(node, 1)
            data = bytearray()
            for a in args:
                if isinstance(a, Str):
                    chunk = self.obj.char_bytes(a.text)
                else:
                    value = self.fold(a).bits
                    chunk = bytes((value & 0xFF,)) if 0 < value < 256 else b""
                if not chunk or 0 in chunk:
                    self.error(msg.STRING_CHARACTER_RANGE, a)
                    raise CompileFailure()
                data += chunk
            code.push_string(bytes(data), "string", node.pos)
            return
        if name in _FOLDED_BUILTINS:
            if not want or len(args) != 1:
                self.bad_builtin(node, 1)
            self.push_const(self.fold(node).bits, name)
            return
        if node.args is not None:
            self.bad_builtin(node, 0)
        if name == "reboot" and not want:
            code.emit(push_const_bytes(0x80) + b"\x35" + bytes((_OP["CLKSET"],)), "reboot")
        elif name == "cogid" and want:
            code.emit((_OP["REG"], 0x89), "cogid")
        elif name == "chipver" and want:
            code.emit((0x34, _mem_op(PUSH, 1, "MEM", False)), "chipver")
        elif name == "clkfreq" and want:
            code.emit((0x35, _mem_op(PUSH, 4, "MEM", False)), "clkfreq")
        elif name == "clkmode" and want:
            code.emit((0x38, 0x04, _mem_op(PUSH, 1, "MEM", False)), "clkmode")
        else:
            self.bad_builtin(node, 0)

    def bad_builtin(self, node, count) -> None:
        self.error(msg.BAD_BUILTIN_USE.format(name=node.name), node)
        raise CompileFailure()

    def cog_start(self, node: Builtin, want: bool) -> None:
        args = node.args or []
        new = node.name == "cognew"
        if (new and len(args) != 2) or (not new and len(args) != 3) or (want and not new):
            self.bad_builtin(node, 2)
        first = args[0] if new else args[1]
        rest = args[1] if new else args[2]
        target = first.expr if isinstance(first, Paren) else first
        sym = None
        if isinstance(target, (Call, NameRef)):
            sym = self.obj.symbols.get(key(target.name))
        if isinstance(sym, MethodSymbol) and (isinstance(target, Call) or target.index is None):
            call_args = target.args if isinstance(target, Call) else []
            self.check_args(target.name, sym.nparams, call_args, target)
            for a in call_args:
                self.expr(a)
            self.push_const((sym.nparams << 8) | sym.index, "method")
            self.expr(rest)
            self.code.emit(_OP["RUN"], "run")
            if not new:
                self.expr(args[0])
                # the cog id goes into the frame RUN just built (long[dcurr][-4])
                self.code.emit(bytes((_OP["REG"], 0x8F)) + push_const_bytes(0xFFFFFFFC) +
                               bytes((_mem_op(POP, 4, "MEM", True),)), "cog id")
        else:  # an address (PASM); an object's method is called and its result used
            if new:
                self.code.emit(0x34, "next free cog")
            else:
                self.expr(args[0])
            self.expr(first)
            self.expr(rest)
        self.code.emit(_OP["COGINIT_RESULT" if want else "COGINIT"], node.name)
