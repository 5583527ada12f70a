"""Spin statements to bytecode: one :class:`MethodCompiler` per method.

Code shapes (observed on OpenSpin 1.00.81; ``J`` is a jump to a label)::

    if c / elseif / else      c  JZ next  body  JMP end  next: ...  end:
                              (ifnot/elseifnot use JNZ)
    repeat                    top: body  JMP top
    repeat n                  n  TJZ end  top: body  next: DJNZ top  end:
    repeat while c            top: c  JZ end  body  JMP top  end:
    repeat ... until c        top: body  next: c  JZ top   (while: JNZ)
    repeat x from a to b      a  POP x  top: body  next: [step] a b  USING x REPEAT[_STEP] J top
    case v                    PUSH end  v  (value CASE_VALUE J | lo hi CASE_RANGE J)...
                              other-body CASE_DONE  (label: body CASE_DONE)...  end:

``quit`` in ``repeat n`` is a JNZ (it drops the count); ``next``/``quit``
inside ``case`` blocks first pop the case's two longs per open case
(``PUSH 8*n``, ``POP``).  Every method ends with RETURN, then its strings.
"""
from __future__ import annotations

from .. import messages as msg
from ..bytecode import BY_MNEMONIC, MATH_BY_SYMBOL
from ..frontend.ast import (
    VARIABLE_NODES, AbortTrap, Assign, Builtin, Call, Case, If, NameRef, ObjCall, PostOp, PreOp, Range,
    RepeatFrom, Str, Unary, key,
)
from ..frontend.source import Pos
from .code import CodeBuffer, Label
from .exprs import USING, CompileFailure, ExprCompiler, push_const_bytes
from .symbols import MethodSymbol, frame_locals

__all__ = ["MethodCompiler"]

_OP = {name: op.code for name, op in BY_MNEMONIC.items()}
_ASSIGNING_UNARY = {"-", "!", "||", "^^", "|<", ">|", "NOT"}
#: statements OpenSpin compiles as blocks, again until they settle (code.py)
_BLOCKS = frozenset(("If", "Case", "RepeatForever", "RepeatCount", "RepeatWhile", "RepeatFrom"))


class _Loop:
    __slots__ = ("next", "quit", "count", "cases")

    def __init__(self, next_label, quit_label, count=False):
        self.next = next_label
        self.quit = quit_label
        self.count = count
        self.cases = 0


class MethodCompiler(ExprCompiler):
    """Compiles one method into a :class:`CodeBuffer`.

    Args:
        obj: the object context (symbols, constants, error reporting).
        method: the ``ast.Method``.
    """

    def __init__(self, obj, method):
        self.obj = obj
        self.method = method
        self.code = CodeBuffer()
        self.frame, self.locals_size = frame_locals(method, obj.count_of, self.check_local)
        self.loops: list[_Loop] = []
        for local in method.locals:     # OpenSpin: no local may reach past offset $8000 of the frame
            sym = self.frame.get(key(local.name))
            if sym is not None and sym.offset + 4 * (sym.count - 1) > 0x8000:
                obj.error(msg.LOCALS_TOO_BIG, local.count if local.count is not None else local)
                break

    def check_local(self, name, pos, frame) -> bool:
        """A parameter or local must not reuse a name of the object or of the method."""
        if key(name) in frame or self.obj.symbols.get(name) is not None or self.obj.const(name) is not None:
            self.obj.error_at(msg.DUPLICATE_SAME_LINE.format(name=name), pos)
            return False
        return True

    def error(self, message, node, undefined=None) -> None:
        self.obj.error(message, node, undefined)

    def compile(self) -> CodeBuffer:
        self.block(self.method.body)
        self.code.pos = None
        self.code.emit(_OP["RETURN"], "end of method")
        return self.code

    def block(self, stmts) -> None:
        for st in stmts:
            self.code.pos = st.pos
            name = type(st).__name__
            try:
                if name in _BLOCKS:
                    with self.code.block():
                        getattr(self, "s_" + name)(st)
                else:
                    getattr(self, "s_" + name)(st)
            except CompileFailure:
                pass

    # ------------------------------------------------------------------ simple statements
    def s_ExprStmt(self, node) -> None:
        e = node.expr
        t = type(e)
        if t is Assign:
            self.assign(e, push=False)
        elif t is PreOp:
            self.step(e, "pre", push=False)
        elif t is PostOp:
            self.step(e, "post", push=False)
        elif t is Unary and e.op in _ASSIGNING_UNARY and isinstance(e.operand, VARIABLE_NODES) \
                and self.constant_of(e.operand) is None and not self.is_method_name(e.operand):
            self.var(e.operand, USING)
            self.code.emit(0x40 | (MATH_BY_SYMBOL[(e.op, True)].code & 0x1F), e.op)
        elif t is Call or t is ObjCall:
            self.call(e, want=False)
        elif t is AbortTrap:
            self.call(e.call, want=False, trap=True)
        elif t is Builtin:
            self.builtin(e, want=False)
        elif t is NameRef and self.is_method_name(e):
            self.call(e, want=False)
        elif t is NameRef and self.lookup(e.name) is None and self.constant_of(e) is None:
            self.undefined(e.name, e)
        else:
            self.error(msg.NOT_A_STATEMENT, e)

    def is_method_name(self, node) -> bool:
        return isinstance(node, NameRef) and node.index is None and key(node.name) not in self.frame \
            and isinstance(self.obj.symbols.get(key(node.name)), MethodSymbol)

    def s_Return(self, node) -> None:
        if node.value is None:
            self.code.emit(_OP["RETURN"], "return")
        else:
            self.expr(node.value)
            self.code.emit(_OP["RETURN_VALUE"], "return value")

    def s_Abort(self, node) -> None:
        if node.value is None:
            self.code.emit(_OP["ABORT"], "abort")
        else:
            self.expr(node.value)
            self.code.emit(_OP["ABORT_VALUE"], "abort value")

    def s_Next(self, node) -> None:
        loop = self.loop_for(node, "next")
        self.pop_cases(loop)
        self.code.jump(bytes((_OP["JMP"],)), loop.next, "next")

    def s_Quit(self, node) -> None:
        loop = self.loop_for(node, "quit")
        self.pop_cases(loop)
        op = _OP["JNZ"] if loop.count else _OP["JMP"]
        self.code.jump(bytes((op,)), loop.quit, "quit")

    def loop_for(self, node, word) -> _Loop:
        if not self.loops:
            self.error(msg.NEXT_OUTSIDE_REPEAT.format(word=word), node)
            raise CompileFailure()
        return self.loops[-1]

    def pop_cases(self, loop: _Loop) -> None:
        if loop.cases:
            self.code.emit(push_const_bytes(8 * loop.cases) + bytes((_OP["POP"],)), "drop case values")

    # ------------------------------------------------------------------ if
    def s_If(self, node: If) -> None:
        code = self.code
        end = Label("if end")
        last = len(node.branches) - 1
        for i, br in enumerate(node.branches):
            code.pos = br.pos
            nxt = Label("next branch")
            try:
                self.expr(br.cond)
            except CompileFailure:
                pass
            code.jump(bytes((_OP["JNZ" if br.negate else "JZ"],)), nxt, "if")
            self.block(br.body)
            if i < last or node.else_body is not None:
                code.pos = br.pos
                code.jump(bytes((_OP["JMP"],)), end, "to end of if")
            code.mark(nxt)
        if node.else_body is not None:
            self.block(node.else_body)
        code.mark(end)

    # ------------------------------------------------------------------ case
    def s_Case(self, node: Case) -> None:
        if not node.items:      # OpenSpin: "No cases encountered" (at the statement after the case)
            self.error(msg.CASE_WITHOUT_MATCH, node)
            return
        code = self.code
        end = Label("case end")
        code.push_address(end, "case end")
        self.expr(node.value)
        other = None
        targets = []
        for item in node.items:
            if other is not None:
                self.error(msg.OTHER_NOT_LAST, item)
                break
            if item.values is None:
                other = item
                continue
            label = Label("case")
            targets.append((label, item))
            code.pos = item.pos
            for v in item.values:
                if isinstance(v, Range):
                    self.expr(v.low)
                    self.expr(v.high)
                    code.jump(bytes((_OP["CASE_RANGE"],)), label, "case range")
                elif isinstance(v, Str) and len(self.obj.char_bytes(v.text)) > 1:
                    for b in self.obj.char_bytes(v.text):   # "abc": one value per character
                        self.push_const(b)
                        code.jump(bytes((_OP["CASE_VALUE"],)), label, "case value")
                else:
                    self.expr(v)
                    code.jump(bytes((_OP["CASE_VALUE"],)), label, "case value")
        if self.loops:
            self.loops[-1].cases += 1
        try:
            if other is not None:
                code.pos = other.pos
                self.block(other.body)
            code.emit(_OP["CASE_DONE"], "case done")
            for label, item in targets:
                code.pos = item.pos
                code.mark(label)
                self.block(item.body)
                code.emit(_OP["CASE_DONE"], "case done")
        finally:
            if self.loops:
                self.loops[-1].cases -= 1
        code.mark(end)

    def no_strings(self, node) -> None:
        """string() is not allowed where an expression is compiled twice (repeat from/to/step)."""
        if node is None:
            return
        if isinstance(node, Builtin) and node.name == "string":
            self.error(msg.STRING_NOT_ALLOWED, node)
            raise CompileFailure()
        for value in vars(node).values():
            for child in (value if isinstance(value, list) else [value]):
                if hasattr(child, "pos") and child is not node and not isinstance(child, Pos):
                    self.no_strings(child)

    # ------------------------------------------------------------------ repeat
    def jmp(self, label, note) -> None:
        self.code.jump(bytes((_OP["JMP"],)), label, note)

    def loop_body(self, body, loop: _Loop) -> None:
        self.loops.append(loop)
        try:
            self.block(body)
        finally:
            self.loops.pop()

    def s_RepeatForever(self, node) -> None:
        top, end = Label("repeat"), Label("repeat end")
        self.code.mark(top)
        self.loop_body(node.body, _Loop(top, end))
        self.code.pos = node.pos
        self.jmp(top, "repeat")
        self.code.mark(end)

    def s_RepeatCount(self, node) -> None:
        code = self.code
        top, nxt, end = Label("repeat"), Label("repeat next"), Label("repeat end")
        self.expr(node.count)
        code.jump(bytes((_OP["TJZ"],)), end, "repeat n")
        code.mark(top)
        self.loop_body(node.body, _Loop(nxt, end, count=True))
        code.pos = node.pos
        code.mark(nxt)
        code.jump(bytes((_OP["DJNZ"],)), top, "repeat n")
        code.mark(end)

    def s_RepeatWhile(self, node) -> None:
        code = self.code
        top, nxt, end = Label("repeat"), Label("repeat next"), Label("repeat end")
        if not node.post:
            code.mark(top)
            self.expr(node.cond)
            code.jump(bytes((_OP["JNZ" if node.until else "JZ"],)), end, "repeat while")
            self.loop_body(node.body, _Loop(top, end))
            code.pos = node.pos
            self.jmp(top, "repeat")
        else:
            nxt.start_as = top      # until OpenSpin meets the test, next goes to the top (code.py)
            code.mark(top)
            self.loop_body(node.body, _Loop(nxt, end))
            code.mark(nxt)
            code.pos = node.cond.pos
            self.expr(node.cond)
            code.jump(bytes((_OP["JZ" if node.until else "JNZ"],)), top, "repeat while")
        code.mark(end)

    def s_RepeatFrom(self, node: RepeatFrom) -> None:
        code = self.code
        top, nxt, end = Label("repeat"), Label("repeat next"), Label("repeat end")
        for part in (node.start, node.stop, node.step):
            self.no_strings(part)
        self.expr(node.start)
        self.var(node.var, 1)
        code.mark(top)
        self.loop_body(node.body, _Loop(nxt, end))
        code.pos = node.pos
        code.mark(nxt)
        if node.step is not None:
            self.expr(node.step)
        self.expr(node.start)
        self.expr(node.stop)
        self.var(node.var, USING)
        code.jump(bytes((0x06 if node.step is not None else 0x02,)), top, "repeat from")
        code.mark(end)
