"""Spin expressions as Python expressions.

Each Spin expression becomes a Python expression string (:class:`X`) with its
precedence and whether its value is already a Spin long (``wrapped``: signed,
32 bits).  ``+ - * <<`` and friends are left unwrapped, as Python computes
them; :meth:`ExprTranslator.value` wraps a result with ``wrap(...)`` only where
the difference shows (a store to a local, a comparison, a call argument, a
truth test).  Stores to hub variables and registers keep the low bits anyway.

Spin expressions with side effects (``x := y``, ``x++``, ``x~``) become
statements placed before the one that uses them (``hoist``), in Spin's
evaluation order; a value computed before such a side effect is first saved
in a temporary so that it keeps Spin's meaning (order.py decides, from the
AST).

Operator mapping (Propeller Manual v1.2, "Operators"): Python's operator
where it means the same on signed values (``+ - * & | ^ ~ == < max min``),
a call of :mod:`spinemu.translate.spin` where it does not (``/`` is
``spin.div``, ``//`` is ``spin.mod``, ``>>`` is ``spin.shr``, ...).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..frontend import ast as A
from ..frontend.constants import float_bits
from .order import _EVENT_BUILTINS, _PAID_BUILTINS, ASSIGNING_UNARY, EvalOrder

__all__ = ["X", "ExprTranslator", "PREC"]

# Python precedence levels (higher binds tighter)
PREC = {"or": 1, "and": 2, "not": 3, "cmp": 4, "|": 5, "^": 6, "&": 7, "<<": 8, ">>": 8,
        "+": 9, "-": 9, "*": 10, "unary": 11, "atom": 14}


@dataclass
class X:
    """A translated expression: Python text, its precedence, is it a Spin long, is it a comparison/bool."""

    text: str
    prec: int = 14
    wrapped: bool = True
    boolean: bool = False
    const: object = None          # its value, if a constant
    saved: bool = False           # a temporary assigned once (nothing can change it)
    truthy: bool = False          # a Python and/or: its value is an operand's, true or false only as a condition

    def paren(self, prec: int) -> str:
        return f"({self.text})" if self.prec < prec else self.text


class Event(str):
    """A line that makes one of its statement's timed events (a call, a register read or write, a wait,
    a cog start or stop, a lookup paid item by item): see ``MethodTranslator.timed_statement``."""


#: registers whose value changes with time: a read-modify-write of one is timed by its read
TIME_REGISTERS = frozenset(("CNT", "INA", "INB", "PHSA", "PHSB"))

_CMP = {"==": "==", "<>": "!=", "<": "<", ">": ">", "=<": "<=", "=>": ">="}
_PY_BIN = {"+": "+", "-": "-", "*": "*", "&": "&", "|": "|", "^": "^"}
_HELPER_BIN = {"/": "spin.div", "//": "spin.mod", ">>": "spin.shr", "<-": "spin.rol", "->": "spin.ror",
               "><": "spin.rev", "**": "spin.mul_high"}
_HELPER_UN = {"^^": "spin.sqrt", ">|": "spin.encode", "|<": "spin.decode"}
_KCONST = {"true": ("spin.TRUE", -1), "false": ("spin.FALSE", 0), "posx": ("spin.POSX", 0x7FFFFFFF),
           "negx": ("spin.NEGX", -0x80000000)}
_REG_NAMES = ("PAR", "CNT", "INA", "INB", "OUTA", "OUTB", "DIRA", "DIRB", "CTRA", "CTRB", "FRQA",
              "FRQB", "PHSA", "PHSB", "VCFG", "VSCL")


def _signed(v: int) -> int:
    v &= 0xFFFFFFFF
    return v - (1 << 32) if v & 0x80000000 else v


def number_text(node) -> str:
    """A Spin number literal as Python writes it (``%0011`` -> ``0b0011``, ``$FF`` -> ``0xFF``).

    Spin allows what Python does not (``%0111__0000``, ``$_FF_``): runs of
    underscores become one; a spelling Python would still refuse, or read as
    another value, is written as the decimal value.
    """
    v = _signed(node.value)
    t = re.sub("_+", "_", node.text.strip()).rstrip("_")
    if v != node.value or not t:
        return str(v)
    if t.startswith("%%"):
        return str(v)
    if t.startswith("%"):
        t = "0b" + t[1:].lstrip("_")
    elif t.startswith("$"):
        t = "0x" + t[1:].lstrip("_")
    elif t.replace("_", "").isdigit():
        t = t.lstrip("0_") or "0"           # Python has no leading zeros in decimals
    else:
        return str(v)
    try:
        if int(t, 0) == v:
            return t
    except ValueError:
        pass
    return str(v)


class ExprTranslator(EvalOrder):
    """Mix-in of the method translator (stmts.py): needs ``names``, ``lookup``, ``hoisted``, ``temp``, ``error``."""

    # ------------------------------------------------------------------ entry points
    def value(self, node) -> str:
        """``node`` as a Spin long (wrapped if needed)."""
        x = self.expr(node)
        return self.wrapped(x).text

    def wrapped(self, x: X) -> X:
        if x.boolean:
            return X(f"spin.flag({x.text})")
        if x.wrapped:
            return x
        return X(f"wrap({x.text})")

    # ------------------------------------------------------------------ timed events
    def event(self, x: X, node) -> X:
        """In a statement with several timed events (``timed_statement``), the event ``node`` on a line of
        its own: ``value = self.f(a)``; else ``x`` as it is."""
        if not self.event_mode or node is self.top_node or self.placing:
            return x
        tmp = self.temp("value")
        self.hoisted.append(Event(f"{tmp} = {x.text}"))
        return X(tmp, wrapped=x.wrapped, boolean=x.boolean, truthy=x.truthy, saved=True)

    def is_event(self, node) -> bool:
        """Is evaluating ``node`` itself a timed event (its last bytecode a call, a wait, a cog start ...)?"""
        t = type(node)
        if t in (A.Call, A.ObjCall, A.AbortTrap):
            return True
        if t is A.NameRef:
            return self.lookup(node.name, node)[0] == "method"
        if t is A.Builtin:
            return node.name.lower() in _EVENT_BUILTINS or node.name.lower() in _PAID_BUILTINS
        if t is A.Binary:
            return node.op in ("/", "//")
        if t is A.Unary:
            return node.op == ">|"
        return t in (A.RegRef, A.SprRef) or t is A.Lookup and self.lazy_items(node)

    def line(self, text: str, event: bool) -> str:
        """A hoisted line; an ``Event`` line if it makes a timed event in a statement written event by event."""
        return Event(text) if event and self.event_mode else text

    def store_event(self, target, reads: bool = False) -> bool:
        """Is the line that stores to ``target`` (``reads``: the line that reads it, in a read-modify-write
        written as two lines) the timed event of the assignment?  A register's write is; a
        read-modify-write of a register that changes with time (``phsa += 1``) is timed by its read."""
        if isinstance(target, A.Paren):
            target = target.expr
        if isinstance(target, A.RegRef):
            return reads == (target.name.upper() in TIME_REGISTERS)
        return isinstance(target, A.SprRef) and not reads

    def num(self, x: X) -> X:
        """``x`` as a number: a comparison becomes Spin's TRUE (-1) or FALSE; other values stay as they are."""
        return X(f"spin.flag({x.text})") if x.boolean else x

    def cond(self, node) -> str:
        """``node`` as a Python condition."""
        x = self.expr(node)
        if x.boolean:
            return x.text
        return self.wrapped(x).text

    def expr(self, node) -> X:
        method = getattr(self, "x_" + type(node).__name__, None)
        if method is None:
            self.unsupported(type(node).__name__, node)
        return method(node)

    # ------------------------------------------------------------------ atoms
    def x_Number(self, node) -> X:
        return X(number_text(node), 14 if node.value < 0x80000000 else 11, const=_signed(node.value))

    def x_Float(self, node) -> X:
        bits = float_bits(node.value)
        return X(str(_signed(bits)), const=_signed(bits))

    def x_Str(self, node) -> X:
        data = self.obj.char_bytes(node.text)
        if len(data) != 1:
            self.unsupported("a string of several characters outside string()", node)
        return X(f"ord({node.text!r})" if 32 <= data[0] < 127 and len(node.text) == 1 else str(data[0]),
                 const=data[0])

    def x_KConst(self, node) -> X:
        k = node.name.lower()
        if k in _KCONST:
            text, v = _KCONST[k]
            return X(text, const=v)
        c = self.constant(node)
        return X(str(c), const=c)

    def x_Paren(self, node) -> X:
        return self.expr(node.expr)

    def x_Given(self, node) -> X:
        return node.x

    def constant(self, node, spin_constant: bool = False):
        """The folded value of a constant expression, or None.

        In a method a DAT label is a variable and ``@label`` depends on where
        the object sits, so only CON names fold; inside Spin's ``constant()``
        (``spin_constant``) the compiler's rules apply, a DAT label is its offset.
        """
        from ..frontend.constants import ConstError, NotConstant, evaluate
        resolve = self.obj.resolve_const if spin_constant else self._resolve_con
        try:
            c = evaluate(node, resolve, self.obj.char_bytes)
        except (NotConstant, ConstError, KeyError, TypeError):
            return None
        return _signed(c.bits)

    def _resolve_con(self, node):
        if isinstance(node, A.AddrOf) or (isinstance(node, A.NameRef) and self.obj.const(node.name) is None):
            return None
        return self.obj.resolve_const(node)

    # ------------------------------------------------------------------ names
    def x_NameRef(self, node) -> X:
        kind, sym = self.lookup(node.name, node)
        if kind == "const":
            return X(f"self.{self.names.attr(node.name)}", const=sym)
        if kind == "method":
            return self.x_Call(node)
        return self.read_var(kind, sym, node)

    def x_ResultRef(self, node) -> X:
        if node.index is not None:
            if not self.in_frame:
                self.unsupported("an indexed result (result[i])", node)
            return X(f'{self.frame_name}.at("{self.result_name}")[{self.value(node.index)}]')
        return X(f"{self.frame_name}.{self.result_name}" if self.in_frame else self.result_name)

    def read_var(self, kind, sym, node) -> X:
        index = getattr(node, "index", None)
        if kind == "local":
            name = self.names.local(node.name)
            if not self.in_frame:
                if index is not None:
                    self.unsupported(f"an indexed local variable ({node.name}[...])", node)
                return X(name)
            if index is None:
                return X(f"{self.frame_name}.{name}" + ("[0]" if sym.count > 1 else ""))
            if sym.count > 1:
                return X(f"{self.frame_name}.{name}[{self.value(index)}]")
            return X(f'{self.frame_name}.at("{name}")[{self.value(index)}]')
        attr = self.names.attr(node.name)
        if index is None:
            if sym.count > 1:
                return X(f"self.{attr}[0]")       # an array's name alone is its first element
            return X(f"self.{attr}")
        i = self.value(index)
        if sym.count > 1:
            return X(f"self.{attr}[{i}]")
        return X(f'self.at("{attr}")[{i}]')

    def x_MemberRef(self, node) -> X:
        base = node.base
        if isinstance(base, A.ResultRef):
            kind, name = "local", self.result_name
        else:
            kind, sym = self.lookup(base.name, base)
            name = self.names.local(base.name) if kind == "local" else self.names.attr(base.name)
        if kind not in ("var", "dat", "local") or (kind == "local" and not self.in_frame):
            self.unsupported("a member access (x.byte[i]) of a local variable", node)
        owner = self.frame_name if kind == "local" else "self"
        i = self.value(node.sub) if node.sub is not None else "0"
        index = self.value(base.index) if getattr(base, "index", None) is not None else "0"
        return X(f'{owner}.at("{name}", {index}, size={node.size})[{i}]')

    def x_MemRef(self, node) -> X:
        mem = {1: "byte", 2: "word", 4: "long"}[node.size]
        if node.index is None:
            return X(f"spin.{mem}[{self.num(self.expr(node.base)).text}]")
        base, index = map(self.num, self.operands([node.base, node.index]))
        return X(f"spin.{mem}[{base.text}, {index.text}]")

    def x_RegRef(self, node) -> X:
        name = node.name.upper()
        if node.bit is None:
            return self.event(X(f"cog.{name}"), node)
        if node.bit2 is None:
            return self.event(X(f"cog.{name}[{self.num(self.expr(node.bit)).text}]"), node)
        hi, lo = map(self.num, self.operands([node.bit, node.bit2]))
        return self.event(X(f"cog.{name}[{hi.text}:{lo.text}]"), node)

    def x_SprRef(self, node) -> X:
        return self.event(X(f"cog.spr[{self.num(self.expr(node.index)).text}]"), node)

    def child(self, node, index, x: X = None) -> str:
        """The child object ``node.obj`` (``obj[i]``); an array named without an index is its element 0, as in Spin.

        Spin indexes the object table from the OBJ line's first entry, so
        ``obj[0]`` of a single object is that object; an index past the OBJ
        line reaches another entry, which Python cannot follow.
        """
        obj = f"self.{self.names.attr(node.obj)}"
        count = self.lookup(node.obj, node)[1].count
        if index is None:
            return obj + ("[0]" if count > 1 else "")
        c = self.constant(index)
        if count == 1 and c == 0:
            return obj
        if count == 1 or (c is not None and not 0 <= c < count):
            self.unsupported(f"an index on object '{node.obj}' past its {count} instance{'s' if count > 1 else ''}", node)
        return obj + f"[{self.wrapped(x).text if x is not None else self.value(index)}]"

    def x_ObjConst(self, node) -> X:
        obj = self.child(node, None)
        value = self.constant(node)
        return X(f"{obj}.{self.names.child_const(node.obj, node.name)}", const=value)

    # ------------------------------------------------------------------ calls
    def x_Call(self, node) -> X:
        func, args = self.call_parts(node)
        return self.event(X(f"{func}({', '.join(args)})"), node)

    x_ObjCall = x_Call

    def call_parts(self, node) -> tuple:
        """``(the method as Python, [its arguments])`` of a call (``f(a)``, ``f``, ``obj[i].f(a)``).

        Spin pushes the arguments left to right, then an object index;
        Python indexes first, so the arguments are saved first where that matters.
        """
        if isinstance(node, A.NameRef):
            node = A.Call(node.pos, node.name, [])
        if isinstance(node, A.Call):
            kind, _sym = self.lookup(node.name, node)
            if kind != "method":
                self.unsupported(f"a call of '{node.name}', which is not a method", node)
            return f"self.{self.names.attr(node.name)}", [self.wrapped(x).text for x in self.operands(node.args)]
        method = self.names.child_method(node.obj, node.method)
        index = self.effects(node.index)
        if node.index is None or self.constant(node.index) is not None and not (index.any or index.paid):
            args = [self.wrapped(x).text for x in self.operands(node.args)]
            return f"{self.child(node, node.index)}.{method}", args
        *args, index = self.operands(node.args + [node.index], reorder_after=len(node.args))
        return f"{self.child(node, node.index, index)}.{method}", [self.wrapped(a).text for a in args]

    def x_AbortTrap(self, node) -> X:
        func, args = self.call_parts(node.call)
        return self.event(X(f"spin.trap({', '.join([func] + args)})"), node)

    # ------------------------------------------------------------------ operators
    def x_Unary(self, node) -> X:
        op = node.op.upper() if node.op.isalpha() else node.op
        x = self.expr(node.operand)
        if op != "NOT":
            x = self.num(x)
        if op == "+":
            return x
        if op == "-":
            if x.const is not None and isinstance(node.operand, (A.Number, A.NameRef, A.ObjConst)):
                # -NEGX leaves 32 bits (a constant may be listed by its bits: $8000_0000)
                return X(f"-{x.paren(11)}", 11, wrapped=_signed(x.const) != -0x80000000, const=_signed(-x.const))
            return X(f"-{x.paren(11)}", 11, wrapped=False)
        if op == "!":
            return X(f"~{x.paren(11)}", 11, wrapped=x.wrapped)
        if op == "NOT":
            return X(f"not {self.truth(x)}", PREC["not"], boolean=True)
        if op == "||":
            return X(f"abs({self.wrapped(x).text})", wrapped=False)
        if op in _HELPER_UN:
            return self.event(X(f"{_HELPER_UN[op]}({x.text})"), node) if op == ">|" else X(f"{_HELPER_UN[op]}({x.text})")
        if op in ASSIGNING_UNARY:
            return self.pre_op(A.PreOp(node.pos, op, node.operand))
        self.unsupported(f"the operator {node.op}", node)

    def truth(self, x: X) -> str:
        """``x`` as the operand of Python's ``not`` (``not (a and b)`` keeps its parentheses)."""
        return x.paren(PREC["not"]) if x.boolean else self.wrapped(x).paren(PREC["cmp"])

    def x_Binary(self, node) -> X:
        op = node.op.upper() if node.op.isalpha() else node.op
        left, right = self.operands([node.left, node.right])
        if op not in ("AND", "OR"):
            left, right = self.num(left), self.num(right)
        if op in _CMP:
            return X(f"{self.wrapped(left).paren(5)} {_CMP[op]} {self.wrapped(right).paren(5)}", 4, boolean=True)
        if op in ("AND", "OR"):
            right_effects = self.effects(node.right)
            if right_effects.any or right_effects.paid:
                # Spin evaluates both operands (no short cut): `ok := start_a and start_b` calls both,
                # `a and b / c` pays for the division
                sym = "&" if op == "AND" else "|"
                p = PREC[sym]
                lt, rt = (x.paren(p + 1) if x.boolean and not x.truthy
                          else f"bool({x.text if x.boolean else self.wrapped(x).text})" for x in (left, right))
                return X(f"{lt} {sym} {rt}", p, boolean=True)
            word = op.lower()
            lp, rp = PREC[word], PREC[word] + 1
            lt = left.paren(lp) if left.boolean else self.wrapped(left).paren(lp)
            rt = right.paren(rp) if right.boolean else self.wrapped(right).paren(rp)
            return X(f"{lt} {word} {rt}", lp, boolean=True, truthy=True)
        if op in _PY_BIN:
            p = PREC[op]
            wrapped = op in ("&", "|", "^") and left.wrapped and right.wrapped and not left.boolean \
                and not right.boolean
            lt = self.wrapped(left).paren(p) if left.boolean else left.paren(p)
            rt = self.wrapped(right).paren(p + 1) if right.boolean else right.paren(p + 1)
            return X(f"{lt} {op} {rt}", p, wrapped=wrapped)
        if op == "<<":
            count = right.const & 31 if right.const is not None else None
            rt = str(count) if count is not None else f"({right.paren(PREC['&'] + 1)} & 31)"
            return X(f"{left.paren(9)} << {rt}", 8, wrapped=False)
        if op == "~>":
            count = right.const & 31 if right.const is not None else None
            rt = str(count) if count is not None else f"({right.paren(PREC['&'] + 1)} & 31)"
            return X(f"{self.wrapped(left).paren(9)} >> {rt}", 8)
        if op == "#>":
            return X(f"max({self.value_x(left)}, {self.value_x(right)})")
        if op == "<#":
            return X(f"min({self.value_x(left)}, {self.value_x(right)})")
        if op in _HELPER_BIN:
            x = X(f"{_HELPER_BIN[op]}({left.text}, {right.text})")
            return self.event(x, node) if op in ("/", "//") and node.pos is not None else x
        self.unsupported(f"the operator {node.op}", node)

    def value_x(self, x: X) -> str:
        return self.wrapped(x).text

    # ------------------------------------------------------------------ side effects
    def x_Assign(self, node) -> X:
        if not self.narrow(node.target) and not isinstance(node.target, A.RegRef):
            text = self.assign(node, reuse=True)
            return self.reread(node.target, text)
        # a byte/word/bit-field target keeps the low bits, but the expression's value is the whole result
        value = self.expr(node.value)
        mark = len(self.hoisted)
        text = self.place(node.target, reuse=True)
        value = self.value_first(node.value, value, node.target, mark, True, reads_target=node.op != ":=")
        if node.op != ":=":
            op = node.op.upper() if node.op.isalpha() else node.op
            value = self.binop(op, X(text), value, node.value)
        tmp = self.temp("value")
        reads = node.op != ":="
        paid = node.op in ("/", "//")       # (the helper's line is the timed event)
        self.hoisted.append(self.line(f"{tmp} = {self.wrapped(value).text}",
                                      reads and (paid or self.store_event(node.target, True))))
        self.hoisted.append(self.line(f"{text} = {tmp}", self.store_event(node.target, False) and not paid if reads else
                                      isinstance(node.target, (A.RegRef, A.SprRef))))
        return X(tmp, saved=True)

    def x_PreOp(self, node) -> X:
        return self.pre_op(node)

    def pre_op(self, node) -> X:
        if (node.op in ("~", "~~", "?") and self.narrow(node.target)) or isinstance(node.target, A.RegRef):
            # the value is what was computed (a register such as CNT does not keep what is written)
            old = self.place(node.target, reuse=True)
            new = {"~": f"spin.sign_extend_byte({old})", "~~": f"spin.sign_extend_word({old})",
                   "?": f"spin.random_forward({old})", "++": f"wrap({old} + 1)", "--": f"wrap({old} - 1)"}[node.op]
            tmp = self.temp("value")
            self.hoisted.append(self.line(f"{tmp} = {new}", self.store_event(node.target, True)))
            self.hoisted.append(self.line(f"{old} = {tmp}", self.store_event(node.target)))
            target = node.target.expr if isinstance(node.target, A.Paren) else node.target
            if node.op in ("++", "--") and isinstance(target, A.RegRef) and target.bit is not None:
                kept = self.temp("value")       # ++/-- of a bit field leaves the field as stored
                self.hoisted.append(f"{kept} = {old}")
                return X(kept, saved=True)
            return X(tmp, saved=True)
        text = self.step(node.target, node.op, reuse=True)
        return self.reread(node.target, text)

    def narrow(self, target) -> bool:
        """Is ``target`` narrower than a long (its stored value may differ from the assigned one)?"""
        if isinstance(target, (A.MemRef, A.MemberRef)):
            return target.size < 4
        if isinstance(target, A.RegRef):
            return target.bit is not None
        if isinstance(target, A.NameRef):
            kind, sym = self.lookup(target.name, target)
            return kind in ("var", "dat") and sym.size < 4
        return False

    def x_PostOp(self, node) -> X:
        if node.op == "?":          # x? leaves the new value, like ?x (Propeller Manual, "Random")
            if self.narrow(node.target) or isinstance(node.target, A.RegRef):
                text = self.place(node.target, reuse=True)
                tmp = self.temp("value")
                self.hoisted.append(self.line(f"{tmp} = spin.random_reverse({text})", self.store_event(node.target, True)))
                self.hoisted.append(self.line(f"{text} = {tmp}", self.store_event(node.target)))
                return X(tmp, saved=True)
            text = self.step(node.target, node.op, post=True, reuse=True)
            return self.reread(node.target, text)
        text = self.place(node.target, reuse=True)
        old = self.temp("old_" + _short(node.target))
        self.hoisted.append(self.line(f"{old} = {text}", self.store_event(node.target, True)))
        self.step(node.target, node.op, post=True, text=text, timed=self.store_event(node.target))
        return X(old, saved=True)

    def reread(self, target, text: str) -> X:
        """The value an assignment leaves: the target read again (unindexed longs), else a saved copy."""
        if isinstance(target, (A.NameRef, A.ResultRef)) and getattr(target, "index", None) is None:
            kind, sym = self.lookup(getattr(target, "name", "result"), target)
            if kind == "local" or getattr(sym, "size", 4) == 4:
                return X(text)
        tmp = self.temp("value")
        self.hoisted.append(f"{tmp} = {text}")
        return X(tmp, saved=True)

    # ------------------------------------------------------------------ addresses
    def x_AddrOf(self, node) -> X:
        t = node.target
        if isinstance(t, A.Paren):
            t = t.expr
        if isinstance(t, A.NameRef):
            kind, sym = self.lookup(t.name, t)
            if kind in ("var", "dat"):
                attr = self.names.attr(t.name)
                if t.index is None:
                    return X(f'self.addr("{attr}")')
                return X(f'self.addr("{attr}", {self.value(t.index)})')
            if kind == "local" and self.in_frame:
                name = self.names.local(t.name)
                if t.index is None:
                    return X(f'{self.frame_name}.addr("{name}")')
                return X(f'{self.frame_name}.addr("{name}", {self.value(t.index)})')
            self.unsupported(f"the address of a local variable (@{t.name})", node)
        if isinstance(t, A.ResultRef) and self.in_frame:
            if t.index is None:
                return X(f'{self.frame_name}.addr("{self.result_name}")')
            return X(f'{self.frame_name}.addr("{self.result_name}", {self.value(t.index)})')
        if isinstance(t, A.MemRef):
            size = t.size
            if t.index is None:
                return self.num(self.expr(t.base))
            base, index = map(self.num, self.operands([t.base, t.index]))
            return X(f"{base.paren(9)} + {size} * {index.paren(10)}", 9, wrapped=False)
        if isinstance(t, A.MemberRef):
            return X(_member_addr(self.expr(t).text, t.size), 9, wrapped=False)
        self.unsupported("this address-of (@) form", node)

    def x_ObjAddr(self, node) -> X:
        return X(f"self.object_base() + {self.num(self.expr(node.operand)).paren(10)}", 9, wrapped=False)

    # ------------------------------------------------------------------ lookups
    def x_Lookup(self, node) -> X:
        """``spin.lookup(i, [a, b, c])``; items Spin might not reach, if they call, assign or pay cycles when
        they run, are evaluated only when reached (``lambda: self.f(x)``, or a local function for an
        assignment) and each item is paid as it is reached."""
        items = []
        costs = []
        down = node.name.lower().startswith("lookdown")
        each = self.lazy_items(node)
        value = self.value(node.value)
        for item in node.items:
            if isinstance(item, A.Range):
                text = f"spin.span({self.value(item.low)}, {self.value(item.high)})" if not each else \
                    f"spin.span({self.lazy(item.low).text}, {self.lazy(item.high).text})"
                items.append(self.deferred(item, text) if each else text)
                costs.append(self.lookup_item_cost([item.low, item.high], down, True, each))
            elif isinstance(item, A.Str) and len(self.obj.char_bytes(item.text)) > 1:
                for b in self.obj.char_bytes(item.text):
                    items.append(str(b))
                    costs.append(self.lookup_item_cost([A.Number(item.pos, b, str(b))], down, False, each))
            else:
                items.append(self.deferred(item, self.wrapped(self.lazy(item)).text) if each else self.value(item))
                costs.append(self.lookup_item_cost([item], down, False, each))
        text = f"spin.{node.name.lower()}({value}, [{', '.join(items)}])"
        self.lookup_costs[text] = self.lookup_row(costs, each)
        return self.event(X(text), node) if each else X(text)

    def lazy_items(self, node) -> bool:
        """Must ``node``'s items be evaluated one at a time (one that Spin might not reach calls, assigns or
        pays cycles when it runs, or the first assigns)?"""
        return any(self.effects(i).any or self.effects(i).paid for i in node.items[1:]) or \
            self.effects(node.items[:1]).hoists

    def deferred(self, item, text: str) -> str:
        """``text`` (an item's value) evaluated only when the lookup reaches it."""
        e = self.effects(item)
        if not (e.any or e.paid):
            return text
        if text.endswith("()") and text[:-2].isidentifier():
            return text[:-2]                # a local function already
        return f"lambda: {text}"

    def lazy(self, node) -> X:
        """``node`` as Python evaluated only when Python reaches it (a lookup item, a case value).

        Its hoisted statements can't go before the statement that uses it:
        they go into a local function, written before that statement, whose
        call is the value (``nonlocal`` names the Python locals it assigns).
        """
        outer, self.hoisted = self.hoisted, []
        mode, self.event_mode = self.event_mode, False     # its events are not the statement's
        try:
            x = self.expr(node)
            body = self.hoisted
        finally:
            self.hoisted, self.event_mode = outer, mode
        if not body:
            return x
        name = self.temp("reached")
        assigned = self.python_locals(self.effects(node).writes)
        lines = ([f"nonlocal {', '.join(assigned)}"] if assigned else []) + body + [f"return {self.wrapped(x).text}"]
        self.hoisted.append((f"def {name}():", lines))
        return X(f"{name}()")

    def python_locals(self, places) -> list:
        """The Python names of the method's Python locals among ``places`` (order.py)."""
        names = {0: self.result_name}
        for sym in self.frame.values():
            names[sym.offset] = self.names.local(sym.name)
        return sorted({names[int(p[2:])] for p in places if p.startswith("l:") and int(p[2:]) in names})

    def x_Range(self, node):
        self.unsupported("a range outside case or lookup", node)


def _short(target) -> str:
    name = getattr(target, "name", None) or "value"
    return name if name.isidentifier() else "value"


def _member_addr(text: str, size: int) -> str:
    # self.at("x", i, size=n)[j]  ->  self.at("x", i, size=n).addr + n * (j)
    head, _, idx = text.rpartition("[")
    return f"{head}.addr + {size} * ({idx[:-1]})"
