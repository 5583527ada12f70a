"""Builds AST nodes (spinemu.frontend.ast) from the parser's reduced rules.

Each method is named after a rule alias in grammars/spin.lark and receives
that rule's kept children (tokens and already built nodes), left to right.
"""
from __future__ import annotations

from .ast import (
    Abort, AbortTrap, AddrOf, Assign, Binary, Builtin, Call, Case, CaseItem, ConDef, ConEnumName,
    ConEnumStart, Data, DataItem, DatFile, DatLabel, DatLine, ExprStmt, Fit, Float, Here, If,
    IfBranch, Instruction, KConst, LocalLabel, LocalVar, Lookup, MemberRef, MemRef, Method, NameRef,
    Next, Number, ObjAddr, ObjCall, ObjConst, ObjDecl, Operand, Org, Paren, PostOp, PreOp, Quit, Range,
    RegRef, RepeatCount, RepeatForever, RepeatFrom, RepeatWhile, Res, ResultRef, Return, SprRef, Str,
    Unary, VarDecl,
)
from .lexer import Token
from .source import Pos

__all__ = ["AstBuilder", "parse_number", "SIZES"]

SIZES = {"byte": 1, "word": 2, "long": 4}
#: assignment-operator spelling -> binary operator spelling
_ASSIGN_TO_BINARY = {
    "===": "==", "<>=": "<>", "=<=": "=<", "=>=": "=>", "<=": "<", ">=": ">",
}
_WORD_OPS = {"and": "AND", "or": "OR", "not": "NOT"}
#: precedence level of each binary operator (Propeller Manual table 2-9; lower binds tighter)
_LEVEL = {
    "->": 3, "<-": 3, ">>": 3, "<<": 3, "~>": 3, "><": 3, "&": 4, "|": 5, "^": 5,
    "*": 6, "**": 6, "/": 6, "//": 6, "+": 7, "-": 7, "#>": 8, "<#": 8,
    "==": 9, "<>": 9, "<": 9, ">": 9, "=<": 9, "=>": 9, "AND": 11, "OR": 12,
}
#: NOT's operand takes the operators of these levels that follow it
_NOT_OPERAND_LEVEL = 9
#: in method code, these start a constant expression that takes the rest of the expression
_CONSTANT_STARTERS = ("float", "round", "trunc")


def parse_number(text: str) -> int:
    """The value of a Spin integer literal.

    >>> parse_number("$7F"), parse_number("%10_10"), parse_number("%%13"), parse_number("1_000")
    (127, 10, 7, 1000)

    A decimal literal of more than 40 digits is far past 32 bits whatever its
    digits are: it reads as ``2**160`` (Python refuses to convert decimal text
    longer than 4,300 digits), and the constant folder reports it as too big.
    """
    t = text.replace("_", "")
    if t.startswith("$"):
        return int(t[1:], 16)
    if t.startswith("%%"):
        return int(t[2:], 4)
    if t.startswith("%"):
        return int(t[1:], 2)
    if len(t.lstrip("0")) > 40:
        return 1 << 160
    return int(t)


def _op_text(tok: Token) -> str:
    return _WORD_OPS.get(tok.value.lower(), tok.value)


class AstBuilder:
    """Parser callbacks; ``path`` goes into every node's position."""

    def __init__(self, path: str):
        self.path = path
        #: building method code (not CON/DAT): round/trunc/float start constant groups
        self.in_code = False
        self._groups: set = set()

    def pos(self, item) -> Pos:
        if isinstance(item, Token):
            return Pos(self.path, item.line, item.col)
        return item.pos

    # ------------------------------------------------------------------ CON / VAR / OBJ
    def con_line(self, ch):
        return [c for c in ch if not isinstance(c, Token)]

    def con_item(self, ch):  # pragma: no cover - every alternative is aliased
        return ch[0]

    def con_def(self, ch):
        return ConDef(self.pos(ch[0]), ch[0].value, ch[2])

    def con_enum_start(self, ch):
        return ConEnumStart(self.pos(ch[0]), ch[1])

    def con_enum_name(self, ch):
        return ConEnumName(self.pos(ch[0]), ch[0].value, ch[2] if len(ch) > 2 else None)

    def var_line(self, ch):
        size = SIZES[ch[0].value.lower()]
        return [VarDecl(d.pos, size, d.name, d.count) for d in ch[1:] if not isinstance(d, Token)]

    def var_decl(self, ch):
        return LocalVar(self.pos(ch[0]), ch[0].value, ch[2] if len(ch) > 2 else None)

    def obj_line(self, ch):
        count = ch[2] if len(ch) > 4 else None
        return ObjDecl(self.pos(ch[0]), ch[0].value, count, ch[-1].value)

    # ------------------------------------------------------------------ methods
    def method(self, ch):
        head, name = ch[0], ch[1]
        params, result, local_vars = [], None, []
        for c in ch[2:-1]:
            if isinstance(c, tuple) and c[0] == "params":
                params = c[1]
            elif isinstance(c, tuple) and c[0] == "result":
                result = c[1]
            elif isinstance(c, tuple) and c[0] == "locals":
                local_vars = c[1]
        return Method(self.pos(head), head.type == "PUB", name.value, params, result, local_vars, ch[-1])

    def params(self, ch):
        return ("params", [(t.value, self.pos(t)) for t in ch if t.type == "NAME"])

    def method_result(self, ch):
        return ("result", ch[1].value)

    def locals(self, ch):
        return ("locals", [c for c in ch if isinstance(c, LocalVar)])

    def local_decl(self, ch):
        return LocalVar(self.pos(ch[0]), ch[0].value, ch[2] if len(ch) > 2 else None)

    def block(self, ch):
        return list(ch)

    # ------------------------------------------------------------------ statements
    def expr_stmt(self, ch):
        return ExprStmt(ch[0].pos, ch[0])

    def return_stmt(self, ch):
        return Return(self.pos(ch[0]), ch[1] if len(ch) > 1 else None)

    def abort_stmt(self, ch):
        return Abort(self.pos(ch[0]), ch[1] if len(ch) > 1 else None)

    def next_stmt(self, ch):
        return Next(self.pos(ch[0]))

    def quit_stmt(self, ch):
        return Quit(self.pos(ch[0]))

    def if_stmt(self, ch):
        head = ch[0]
        branches = [IfBranch(self.pos(head), head.type == "IFNOT", ch[1], ch[2])]
        else_body, else_pos = None, None
        for part in ch[3:]:
            if isinstance(part, IfBranch):
                branches.append(part)
            else:
                else_pos, else_body = part
        return If(self.pos(head), branches, else_body, else_pos)

    def elseif_part(self, ch):
        return IfBranch(self.pos(ch[0]), ch[0].type == "ELSEIFNOT", ch[1], ch[2])

    def else_part(self, ch):
        return (self.pos(ch[0]), ch[1])

    def case_stmt(self, ch):
        return Case(self.pos(ch[0]), ch[1], [c for c in ch[2:] if isinstance(c, CaseItem)])

    def case_item(self, ch):
        values = ch[0]
        body = ch[-1]
        pos = values[0] if isinstance(values, tuple) else values[0].pos
        return CaseItem(pos, None if isinstance(values, tuple) else values, body)

    def case_values(self, ch):
        if len(ch) == 1 and isinstance(ch[0], Token):
            return (self.pos(ch[0]),)  # OTHER
        return [c for c in ch if not isinstance(c, Token)]

    def range_item(self, ch):
        if len(ch) == 3:
            return Range(ch[0].pos, ch[0], ch[2])
        return ch[0]

    def repeat_forever(self, ch):
        return RepeatForever(self.pos(ch[0]), ch[1])

    def repeat_post(self, ch):
        return RepeatWhile(self.pos(ch[0]), ch[2].type == "UNTIL", ch[3], ch[1], True)

    def repeat_count(self, ch):
        return RepeatCount(self.pos(ch[0]), ch[1], ch[2])

    def repeat_while(self, ch):
        return RepeatWhile(self.pos(ch[0]), ch[1].type == "UNTIL", ch[2], ch[3], False)

    def repeat_from(self, ch):
        step = ch[7] if len(ch) == 9 else None
        return RepeatFrom(self.pos(ch[0]), ch[1], ch[3], ch[5], step, ch[-1])

    # ------------------------------------------------------------------ expressions
    def assign(self, ch):
        tok = ch[1]
        if tok.type == "ASSIGN":
            op = ":="
        else:
            spelled = tok.value
            low = spelled.lower()
            if low in ("and=", "or="):
                op = low[:-1].upper()
            else:
                op = _ASSIGN_TO_BINARY.get(spelled, spelled[:-1])
        return Assign(ch[0].pos, op, ch[0], ch[2])

    def binop(self, ch):
        op = _op_text(ch[1])
        return self._attach(ch[0], op, ch[2]) or Binary(ch[0].pos, op, ch[0], ch[2])

    def _attach(self, node, op: str, right):
        """``node op right`` when an open operand at the right end of ``node`` takes ``op``, else None.

        The grammar binds by the usual precedence; OpenSpin differs in two
        places, both of which reach to the right over the operators that follow:

        * ``NOT`` stands wherever a term may and its operand is everything of
          comparison level or tighter after it: ``x + NOT y + z`` is
          ``x + NOT (y + z)``, ``NOT a == b`` is ``NOT (a == b)``;
        * in method code, ``float(``, ``round(`` and ``trunc(`` start a
          constant expression that takes every operator and operand after it
          up to the end of the enclosing expression: ``x * round(1.5) + 2`` is
          ``x * constant(round(1.5) + 2)`` (and ``round(1.5) + x`` is an error,
          ``x`` not being a constant).  The group becomes a ``constant()``
          whose ``starter`` attribute names the word that began it.
        """
        t = type(node)
        if t is Binary:
            inner = self._attach(node.right, op, right)
            return None if inner is None else Binary(node.pos, node.op, node.left, inner)
        if t is Unary:
            inner = self._attach(node.operand, op, right)
            if inner is not None:
                return Unary(node.pos, node.op, inner)
            if node.op == "NOT" and _LEVEL[op] <= _NOT_OPERAND_LEVEL:
                return Unary(node.pos, "NOT", Binary(node.operand.pos, op, node.operand, right))
            return None
        if t is Builtin and self.in_code:
            if id(node) in self._groups:
                group = Builtin(node.pos, "constant", [Binary(node.pos, op, node.args[0], right)])
            elif node.name in _CONSTANT_STARTERS and node.args:
                group = Builtin(node.pos, "constant", [Binary(node.pos, op, node, right)])
            else:
                return None
            group.starter = getattr(node, "starter", node.name)   # for the back ends' messages
            self._groups.add(id(group))
            return group
        return None

    def unop(self, ch):
        return Unary(self.pos(ch[0]), _op_text(ch[0]), ch[1])

    def pre_op(self, ch):
        return PreOp(self.pos(ch[0]), ch[0].value, ch[1])

    def post_op(self, ch):
        return PostOp(ch[0].pos, ch[1].value, ch[0])

    def addr_of(self, ch):
        return AddrOf(self.pos(ch[0]), ch[1])

    def obj_addr(self, ch):
        return ObjAddr(self.pos(ch[0]), ch[1])

    def number(self, ch):
        return Number(self.pos(ch[0]), parse_number(ch[0].value), ch[0].value)

    def float_number(self, ch):
        return Float(self.pos(ch[0]), float(ch[0].value.replace("_", "")), ch[0].value)

    def string_lit(self, ch):
        return Str(self.pos(ch[0]), ch[0].value)

    def kconst(self, ch):
        return KConst(self.pos(ch[0]), ch[0].value.lower())

    def here(self, ch):
        return Here(self.pos(ch[0]))

    def local_label(self, ch):
        return LocalLabel(self.pos(ch[0]), ch[0].value[1:])

    def paren(self, ch):
        return Paren(self.pos(ch[0]), ch[1])

    def abort_trap(self, ch):
        call = ch[1]
        if isinstance(call, Token):
            call = NameRef(self.pos(call), call.value)
        return AbortTrap(self.pos(ch[0]), call)

    def obj_const(self, ch):
        return ObjConst(self.pos(ch[0]), ch[0].value, ch[2].value)

    def builtin(self, ch):
        args = ch[2] if len(ch) > 2 else None
        return Builtin(self.pos(ch[0]), ch[0].value.lower(), args)

    def lookup(self, ch):
        items = [c for c in ch[4:] if not isinstance(c, Token)]
        return Lookup(self.pos(ch[0]), ch[0].value.lower(), ch[2], items)

    def args(self, ch):
        return [c for c in ch if not isinstance(c, Token)]

    def call(self, ch):
        return Call(self.pos(ch[0]), ch[0].value, ch[2])

    def obj_call(self, ch):
        obj = ch[0]
        if ch[1].type == "LSQB":
            index, method, rest = ch[2], ch[5], ch[6:]
        else:
            index, method, rest = None, ch[2], ch[3:]
        args = rest[1] if rest else []
        return ObjCall(self.pos(obj), obj.value, index, method.value, args)

    def name_ref(self, ch):
        return NameRef(self.pos(ch[0]), ch[0].value, ch[2] if len(ch) > 1 else None)

    def member_ref(self, ch):
        name, size_tok, rest = ch[0], ch[2], ch[3:]
        sub = rest[1] if rest else None
        if name.type == "RESULT":
            base = ResultRef(self.pos(name))
        else:
            base = NameRef(self.pos(name), name.value)
        return MemberRef(self.pos(name), base, SIZES[size_tok.value.lower()], sub)

    def mem_ref(self, ch):
        index = ch[5] if len(ch) > 4 else None
        return MemRef(self.pos(ch[0]), SIZES[ch[0].value.lower()], ch[2], index)

    def reg_ref(self, ch):
        bit = ch[2] if len(ch) > 2 else None
        bit2 = ch[4] if len(ch) > 4 else None
        return RegRef(self.pos(ch[0]), ch[0].value.lower(), bit, bit2)

    def spr_ref(self, ch):
        return SprRef(self.pos(ch[0]), ch[2])

    def result_ref(self, ch):
        return ResultRef(self.pos(ch[0]), ch[2] if len(ch) > 1 else None)

    # ------------------------------------------------------------------ DAT
    def dat_line(self, ch):
        label = body = None
        for c in ch:
            if isinstance(c, DatLabel):
                label = c
            else:
                body = c
        first = label or body
        return DatLine(first.pos, label, body) if first is not None else None

    def dat_label(self, ch):
        tok = ch[0]
        if tok.type == "LOCALNAME":
            return DatLabel(self.pos(tok), tok.value[1:], True)
        return DatLabel(self.pos(tok), tok.value, False)

    def dat_body(self, ch):  # pragma: no cover - every alternative is aliased
        return ch[0]

    def instruction(self, ch):
        cond = None
        if ch[0].type == "COND":
            cond, ch = ch[0].value.lower(), ch[1:]
        op = ch[0]
        operands, effects = [], []
        for c in ch[1:]:
            if isinstance(c, tuple) and c[0] == "operands":
                operands = c[1]
            elif isinstance(c, tuple) and c[0] == "effects":
                effects = c[1]
        return Instruction(self.pos(op), cond, op.value.lower(), operands, effects)

    def operands(self, ch):
        return ("operands", [c for c in ch if isinstance(c, Operand)])

    def operand(self, ch):
        if len(ch) == 2:
            return Operand(self.pos(ch[0]), True, ch[1])
        return Operand(ch[0].pos, False, ch[0])

    def effects(self, ch):
        return ("effects", [t.value.lower() for t in ch if t.type == "EFFECT"])

    def data(self, ch):
        return Data(self.pos(ch[0]), SIZES[ch[0].value.lower()],
                    [c for c in ch[1:] if isinstance(c, DataItem)])

    def data_item(self, ch):
        size = None
        pos = self.pos(ch[0])           # the size override when there is one (errors point at it)
        if isinstance(ch[0], Token) and ch[0].type == "SIZE":
            size, ch = SIZES[ch[0].value.lower()], ch[1:]
        count = ch[2] if len(ch) > 1 else None
        return DataItem(pos, size, ch[0], count)

    def org(self, ch):
        return Org(self.pos(ch[0]), ch[1] if len(ch) > 1 else None)

    def res(self, ch):
        return Res(self.pos(ch[0]), ch[1] if len(ch) > 1 else None)

    def fit(self, ch):
        return Fit(self.pos(ch[0]), ch[1] if len(ch) > 1 else None)

    def dat_file(self, ch):
        return DatFile(self.pos(ch[0]), ch[1].value)
