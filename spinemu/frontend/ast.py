"""The Spin AST: plain dataclasses, each carrying its position (:class:`Pos`).

One front end, two back ends: the compiler (spinemu.compiler) and the
Spin->Python translator read the same tree.  Names keep the user's spelling;
symbol lookups are case-insensitive (use :func:`key`).  Operators are kept
as their Spin spelling in upper case for the word operators (``AND``).

Tree shape::

    SpinFile
      cons: [ConDef | ConEnumStart | ConEnumName]   (all CON sections, in order)
      vars: [VarDecl]   objs: [ObjDecl]   methods: [Method]   dat: [DatLine]
      sections: [(kind, line)]  comments: {line: [Comment]}

Expressions: Number, Float, Str, KConst, Here, LocalLabel, NameRef,
MemberRef, MemRef, RegRef, SprRef, ResultRef, Call, ObjCall, ObjConst,
Builtin, Lookup, Unary, Binary, Assign, PreOp, PostOp, AddrOf, ObjAddr,
AbortTrap, Range.  Statements: ExprStmt, Return, Abort, Next, Quit, If,
Case, RepeatForever, RepeatCount, RepeatWhile, RepeatFrom.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Union

from .source import Pos, SourceText

__all__ = [
    "key", "Node", "Expr", "Number", "Float", "Str", "KConst", "Here", "LocalLabel", "NameRef",
    "MemberRef", "MemRef", "RegRef", "SprRef", "ResultRef", "Call", "ObjCall", "ObjConst",
    "Builtin", "Lookup", "Unary", "Binary", "Assign", "PreOp", "PostOp", "AddrOf", "ObjAddr",
    "AbortTrap", "Range", "Paren", "Stmt", "ExprStmt", "Return", "Abort", "Next", "Quit", "If",
    "IfBranch", "Case", "CaseItem", "RepeatForever", "RepeatCount", "RepeatWhile", "RepeatFrom",
    "ConDef", "ConEnumStart", "ConEnumName", "VarDecl", "ObjDecl", "LocalVar", "Method",
    "DatLabel", "Instruction", "Operand", "DataItem", "Data", "Org", "Res", "Fit", "DatFile",
    "DatLine", "SpinFile", "VARIABLE_NODES",
]


def key(name: str) -> str:
    """The case-insensitive lookup key of a Spin name."""
    return name.lower()


@dataclass
class Node:
    pos: Pos


# ----------------------------------------------------------------------------- expressions
class Expr(Node):
    """Base of expression nodes."""


@dataclass
class Number(Expr):
    value: int
    text: str


@dataclass
class Float(Expr):
    value: float
    text: str


@dataclass
class Str(Expr):
    """A string literal: a character constant, or a list of characters."""

    text: str


@dataclass
class KConst(Expr):
    """A built-in constant: TRUE FALSE POSX NEGX PI and the clock-mode names."""

    name: str


@dataclass
class Here(Expr):
    """``$``: the current cog address in DAT."""


@dataclass
class LocalLabel(Expr):
    """``:name``: a DAT local label."""

    name: str


@dataclass
class NameRef(Expr):
    """A name, optionally indexed: a variable, a DAT label, a constant or a call without ()."""

    name: str
    index: Optional[Expr] = None


@dataclass
class MemberRef(Expr):
    """``base.size[sub]``: a byte/word/long inside a variable (``base`` a NameRef or ResultRef)."""

    base: Expr
    size: int
    sub: Optional[Expr]


@dataclass
class MemRef(Expr):
    """``size[base][index]``: main memory."""

    size: int
    base: Expr
    index: Optional[Expr]


@dataclass
class RegRef(Expr):
    """A cog register, optionally one bit ``[bit]`` or a bit range ``[hi..lo]``."""

    name: str
    bit: Optional[Expr] = None
    bit2: Optional[Expr] = None


@dataclass
class SprRef(Expr):
    index: Expr


@dataclass
class ResultRef(Expr):
    """``result``, optionally indexed (``result[i]``: the longs after it)."""

    index: Optional[Expr] = None


@dataclass
class Call(Expr):
    """A call of a method of this object (``name(args)``)."""

    name: str
    args: list


@dataclass
class ObjCall(Expr):
    """``obj.method(args)`` or ``obj[index].method(args)``."""

    obj: str
    index: Optional[Expr]
    method: str
    args: list


@dataclass
class ObjConst(Expr):
    """``obj#NAME``."""

    obj: str
    name: str


@dataclass
class Builtin(Expr):
    """A built-in command or function; ``name`` is lower case; ``args`` may be ``None`` (no parentheses)."""

    name: str
    args: Optional[list]


@dataclass
class Lookup(Expr):
    """``lookup(value: items)``; ``name`` is lookup/lookupz/lookdown/lookdownz."""

    name: str
    value: Expr
    items: list


@dataclass
class Unary(Expr):
    op: str
    operand: Expr


@dataclass
class Binary(Expr):
    op: str
    left: Expr
    right: Expr


@dataclass
class Assign(Expr):
    """``target := value`` (op ``":="``) or ``target OP= value`` (op is the binary operator)."""

    op: str
    target: Expr
    value: Expr


@dataclass
class PreOp(Expr):
    """``++x --x ~x ~~x ?x``."""

    op: str
    target: Expr


@dataclass
class PostOp(Expr):
    """``x++ x-- x~ x~~ x?``."""

    op: str
    target: Expr


@dataclass
class AddrOf(Expr):
    """``@x``."""

    target: Expr


@dataclass
class ObjAddr(Expr):
    """``@@x``: x plus the object's base address."""

    operand: Expr


@dataclass
class AbortTrap(Expr):
    """``\\call``."""

    call: Expr


@dataclass
class Range(Expr):
    low: Expr
    high: Expr


@dataclass
class Paren(Expr):
    """An expression in parentheses (kept so that back ends can tell ``-(x)`` from ``-x``)."""

    expr: Expr


VARIABLE_NODES = (NameRef, MemberRef, MemRef, RegRef, SprRef, ResultRef)


# ----------------------------------------------------------------------------- statements
class Stmt(Node):
    """Base of statement nodes."""


@dataclass
class ExprStmt(Stmt):
    expr: Expr


@dataclass
class Return(Stmt):
    value: Optional[Expr]


@dataclass
class Abort(Stmt):
    value: Optional[Expr]


@dataclass
class Next(Stmt):
    pass


@dataclass
class Quit(Stmt):
    pass


@dataclass
class IfBranch(Node):
    """``if``/``elseif`` (negate False) or ``ifnot``/``elseifnot`` (negate True)."""

    negate: bool
    cond: Expr
    body: list


@dataclass
class If(Stmt):
    branches: list            # [IfBranch], the first is the if
    else_body: Optional[list]
    else_pos: Optional[Pos] = None


@dataclass
class CaseItem(Node):
    values: Optional[list]     # [Expr | Range]; None for OTHER
    body: list


@dataclass
class Case(Stmt):
    value: Expr
    items: list


@dataclass
class RepeatForever(Stmt):
    body: list


@dataclass
class RepeatCount(Stmt):
    count: Expr
    body: list


@dataclass
class RepeatWhile(Stmt):
    """``repeat while/until c`` (post False) or ``repeat ... while/until c`` (post True)."""

    until: bool
    cond: Expr
    body: list
    post: bool


@dataclass
class RepeatFrom(Stmt):
    var: Expr
    start: Expr
    stop: Expr
    step: Optional[Expr]
    body: list


# ----------------------------------------------------------------------------- declarations
@dataclass
class ConDef(Node):
    name: str
    value: Expr


@dataclass
class ConEnumStart(Node):
    value: Expr


@dataclass
class ConEnumName(Node):
    name: str
    skip: Optional[Expr]


@dataclass
class VarDecl(Node):
    size: int                  # 1, 2 or 4
    name: str
    count: Optional[Expr]


@dataclass
class ObjDecl(Node):
    name: str
    count: Optional[Expr]
    filename: str


@dataclass
class LocalVar(Node):
    name: str
    count: Optional[Expr]


@dataclass
class Method(Node):
    public: bool
    name: str
    params: list               # [(name, Pos)]
    result: Optional[str]
    locals: list               # [LocalVar]
    body: list
    end_line: int = 0


# ----------------------------------------------------------------------------- DAT
@dataclass
class DatLabel(Node):
    name: str
    local: bool


@dataclass
class Operand(Node):
    immediate: bool
    expr: Expr


@dataclass
class Instruction(Node):
    cond: Optional[str]
    mnemonic: str
    operands: list             # [Operand]
    effects: list              # [str], lower case


@dataclass
class DataItem(Node):
    size: Optional[int]        # size override, or None
    value: Expr
    count: Optional[Expr]


@dataclass
class Data(Node):
    size: int
    items: list


@dataclass
class Org(Node):
    value: Optional[Expr]


@dataclass
class Res(Node):
    value: Optional[Expr]


@dataclass
class Fit(Node):
    value: Optional[Expr]


@dataclass
class DatFile(Node):
    filename: str


@dataclass
class DatLine(Node):
    label: Optional[DatLabel]
    body: Union[Instruction, Data, Org, Res, Fit, DatFile, None]


# ----------------------------------------------------------------------------- file
@dataclass
class SpinFile:
    """A parsed source file; ``comments`` maps a line number to its comments."""

    path: str
    source: SourceText
    cons: list = field(default_factory=list)
    vars: list = field(default_factory=list)
    objs: list = field(default_factory=list)
    methods: list = field(default_factory=list)
    dat: list = field(default_factory=list)
    sections: list = field(default_factory=list)
    comments: dict = field(default_factory=dict)

    def comments_at(self, line: int) -> list:
        """The comments that start on ``line`` (texts without delimiters)."""
        return self.comments.get(line, [])
