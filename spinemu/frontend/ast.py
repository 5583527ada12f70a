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

from dataclasses import MISSING, dataclass, field, fields
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
    "DatLine", "SpinFile", "VARIABLE_NODES", "walk",
]


def key(name: str) -> str:
    """The case-insensitive lookup key of a Spin name."""
    return name.lower()


_NODES: list = []


def walk(node):
    """Every node in ``node`` (a node or a list of them), the outer first; a SpinFile is not entered."""
    if isinstance(node, list):
        for x in node:
            yield from walk(x)
    elif hasattr(node, "__dataclass_fields__") and not isinstance(node, SpinFile):
        yield node
        for f in node.__dataclass_fields__:
            if f != "pos":
                yield from walk(getattr(node, f))


def _node(cls):
    """A dataclass whose ``__init__`` is made later, together with all others (fast import)."""
    if cls.__doc__ is None:  # spares dataclass() an inspect.signature() call
        cls.__doc__ = f"{cls.__name__} node."
    cls = dataclass(init=False, repr=False, eq=False)(cls)
    _NODES.append(cls)
    return cls


@_node
class Node:
    """Base of all nodes: every node knows where it starts."""

    pos: Pos

    def __repr__(self) -> str:
        inner = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in fields(self) if f.name != "pos")
        return f"{type(self).__name__}({inner})"

    def __eq__(self, other) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return all(getattr(self, f.name) == getattr(other, f.name) for f in fields(self))

    __hash__ = None


# ----------------------------------------------------------------------------- expressions
class Expr(Node):
    """Base of expression nodes."""


@_node
class Number(Expr):
    value: int
    text: str


@_node
class Float(Expr):
    value: float
    text: str


@_node
class Str(Expr):
    """A string literal: a character constant, or a list of characters."""

    text: str


@_node
class KConst(Expr):
    """A built-in constant: TRUE FALSE POSX NEGX PI and the clock-mode names."""

    name: str


@_node
class Here(Expr):
    """``$``: the current cog address in DAT."""


@_node
class LocalLabel(Expr):
    """``:name``: a DAT local label."""

    name: str


@_node
class NameRef(Expr):
    """A name, optionally indexed: a variable, a DAT label, a constant or a call without ()."""

    name: str
    index: Optional[Expr] = None


@_node
class MemberRef(Expr):
    """``base.size[sub]``: a byte/word/long inside a variable (``base`` a NameRef or ResultRef)."""

    base: Expr
    size: int
    sub: Optional[Expr]


@_node
class MemRef(Expr):
    """``size[base][index]``: main memory."""

    size: int
    base: Expr
    index: Optional[Expr]


@_node
class RegRef(Expr):
    """A cog register, optionally one bit ``[bit]`` or a bit range ``[hi..lo]``."""

    name: str
    bit: Optional[Expr] = None
    bit2: Optional[Expr] = None


@_node
class SprRef(Expr):
    index: Expr


@_node
class ResultRef(Expr):
    """``result``, optionally indexed (``result[i]``: the longs after it)."""

    index: Optional[Expr] = None


@_node
class Call(Expr):
    """A call of a method of this object (``name(args)``)."""

    name: str
    args: list


@_node
class ObjCall(Expr):
    """``obj.method(args)`` or ``obj[index].method(args)``."""

    obj: str
    index: Optional[Expr]
    method: str
    args: list


@_node
class ObjConst(Expr):
    """``obj#NAME``."""

    obj: str
    name: str


@_node
class Builtin(Expr):
    """A built-in command or function; ``name`` is lower case; ``args`` may be ``None`` (no parentheses)."""

    name: str
    args: Optional[list]


@_node
class Lookup(Expr):
    """``lookup(value: items)``; ``name`` is lookup/lookupz/lookdown/lookdownz."""

    name: str
    value: Expr
    items: list


@_node
class Unary(Expr):
    op: str
    operand: Expr


@_node
class Binary(Expr):
    op: str
    left: Expr
    right: Expr


@_node
class Assign(Expr):
    """``target := value`` (op ``":="``) or ``target OP= value`` (op is the binary operator)."""

    op: str
    target: Expr
    value: Expr


@_node
class PreOp(Expr):
    """``++x --x ~x ~~x ?x``."""

    op: str
    target: Expr


@_node
class PostOp(Expr):
    """``x++ x-- x~ x~~ x?``."""

    op: str
    target: Expr


@_node
class AddrOf(Expr):
    """``@x``."""

    target: Expr


@_node
class ObjAddr(Expr):
    """``@@x``: x plus the object's base address."""

    operand: Expr


@_node
class AbortTrap(Expr):
    """``\\call``."""

    call: Expr


@_node
class Range(Expr):
    low: Expr
    high: Expr


@_node
class Paren(Expr):
    """An expression in parentheses (kept so that back ends can tell ``-(x)`` from ``-x``)."""

    expr: Expr


VARIABLE_NODES = (NameRef, MemberRef, MemRef, RegRef, SprRef, ResultRef)


# ----------------------------------------------------------------------------- statements
class Stmt(Node):
    """Base of statement nodes."""


@_node
class ExprStmt(Stmt):
    expr: Expr


@_node
class Return(Stmt):
    value: Optional[Expr]


@_node
class Abort(Stmt):
    value: Optional[Expr]


@_node
class Next(Stmt):
    pass


@_node
class Quit(Stmt):
    pass


@_node
class IfBranch(Node):
    """``if``/``elseif`` (negate False) or ``ifnot``/``elseifnot`` (negate True)."""

    negate: bool
    cond: Expr
    body: list


@_node
class If(Stmt):
    branches: list            # [IfBranch], the first is the if
    else_body: Optional[list]
    else_pos: Optional[Pos] = None


@_node
class CaseItem(Node):
    values: Optional[list]     # [Expr | Range]; None for OTHER
    body: list


@_node
class Case(Stmt):
    value: Expr
    items: list


@_node
class RepeatForever(Stmt):
    body: list


@_node
class RepeatCount(Stmt):
    count: Expr
    body: list


@_node
class RepeatWhile(Stmt):
    """``repeat while/until c`` (post False) or ``repeat ... while/until c`` (post True)."""

    until: bool
    cond: Expr
    body: list
    post: bool


@_node
class RepeatFrom(Stmt):
    var: Expr
    start: Expr
    stop: Expr
    step: Optional[Expr]
    body: list


# ----------------------------------------------------------------------------- declarations
@_node
class ConDef(Node):
    name: str
    value: Expr


@_node
class ConEnumStart(Node):
    value: Expr


@_node
class ConEnumName(Node):
    name: str
    skip: Optional[Expr]


@_node
class VarDecl(Node):
    size: int                  # 1, 2 or 4
    name: str
    count: Optional[Expr]


@_node
class ObjDecl(Node):
    name: str
    count: Optional[Expr]
    filename: str


@_node
class LocalVar(Node):
    name: str
    count: Optional[Expr]


@_node
class Method(Node):
    public: bool
    name: str
    params: list               # [(name, Pos)]
    result: Optional[str]
    locals: list               # [LocalVar]
    body: list
    end_line: int = 0


# ----------------------------------------------------------------------------- DAT
@_node
class DatLabel(Node):
    name: str
    local: bool


@_node
class Operand(Node):
    immediate: bool
    expr: Expr


@_node
class Instruction(Node):
    cond: Optional[str]
    mnemonic: str
    operands: list             # [Operand]
    effects: list              # [str], lower case


@_node
class DataItem(Node):
    size: Optional[int]        # size override, or None
    value: Expr
    count: Optional[Expr]


@_node
class Data(Node):
    size: int
    items: list


@_node
class Org(Node):
    value: Optional[Expr]


@_node
class Res(Node):
    value: Optional[Expr]


@_node
class Fit(Node):
    value: Optional[Expr]


@_node
class DatFile(Node):
    filename: str


@_node
class DatLine(Node):
    label: Optional[DatLabel]
    body: Union[Instruction, Data, Org, Res, Fit, DatFile, None]


def _make_inits() -> None:
    """Give every node class its ``__init__`` (one ``exec`` for all: 10x faster than @dataclass)."""
    src = []
    env: dict = {"MISSING": MISSING}
    for i, cls in enumerate(_NODES):
        params, body = [], []
        for f in fields(cls):
            if f.default is MISSING:
                params.append(f.name)
            else:
                env[f"_d{i}_{f.name}"] = f.default
                params.append(f"{f.name}=_d{i}_{f.name}")
            body.append(f"    self.{f.name} = {f.name}")
        src.append(f"def _init{i}(self, {', '.join(params)}):\n" + "\n".join(body))
    exec("\n".join(src), env)
    for i, cls in enumerate(_NODES):
        cls.__init__ = env[f"_init{i}"]


_make_inits()


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
