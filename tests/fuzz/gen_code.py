"""Random method bodies: expressions with side effects anywhere, every statement form, calls and aborts.

What keeps a generated method well-defined and finite:

* locals are assigned before anything reads them (Spin does not clear them);
* every index is reduced into its array (``(e) & 7``, ``((e) >> 1) // 5``),
  so reads and writes stay inside the variable they name;
* loops are bounded: ``repeat n`` with a small count, ``repeat x from a to
  b step s`` whose variable and bounds are locals the body cannot write
  (``reserved``) and whose step is never 0, ``while``/``until`` loops
  driven by a reserved counter (``repeat while k++ < 3 and ...``);
* calls go down a chain (a method calls only methods generated before it,
  and its children's methods), plus one method that calls itself with a
  depth parameter it cannot write; a method that may abort is called with
  ``\\`` from the top method and inside another call's arguments (an abort
  unwinding past a call being set up -- its arguments or its object index --
  makes the ROM interpreter run wild);
* ``cost`` estimates the bytecodes a call runs so the program stays small;
* the registers written are OUTA/DIRA (and OUTB/DIRB, FRQA/FRQB): no
  counter is started, nothing reads INA or CNT, so results do not depend on
  timing or the outside world.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .gen_const import INT_BINARY, INT_UNARY, WORD_OPS, ConstGen, int_literal, int_value, spaced, unary_text
from .gen_data import DatLabel
from .rand import Rand

ASSIGN_OPS = {":=": 12, "+=": 3, "-=": 3, "*=": 2, "**=": 1, "/=": 1, "//=": 1, "#>=": 1, "<#=": 1,
              "<<=": 1, ">>=": 1, "~>=": 1, "->=": 1, "<-=": 1, "><=": 1, "&=": 2, "|=": 2, "^=": 2,
              "AND=": 1, "OR=": 1, "===": 1, "<>=": 1, "<=": 1, ">=": 1, "=<=": 1, "=>=": 1}
PRE_POST = {"++x": 3, "--x": 3, "x++": 3, "x--": 3, "?x": 1, "x?": 1, "~x": 2, "~~x": 2, "x~": 2, "x~~": 2}
UNARY_STATEMENTS = ["-", "!", "||", "^^", "|<", ">|", "NOT"]
#: the largest product of loop counts a statement may sit in
MAX_MULT = 48


@dataclass
class Var:
    """A variable code can name: VAR, DAT label, parameter, local, ``result``."""

    name: str
    size: int                  # 1, 2, 4
    count: int | None = None   # None: a scalar
    kind: str = "var"          # var, dat, local, param, result
    writable: bool = True
    label: DatLabel | None = None

    @property
    def nbytes(self) -> int:
        return self.size * (self.count or 1)

    @property
    def global_(self) -> bool:
        return self.kind in ("var", "dat")


@dataclass
class Method:
    """A generated method as callers see it."""

    name: str
    params: int
    pub: bool = False
    aborts: bool = False
    cost: int = 1
    recursive: bool = False    # its first parameter is a depth: call with ``(e) & 3``


@dataclass
class ChildRef:
    """An OBJ line of the object being written: ``name : "file"`` or ``name[count] : "file"``."""

    name: str
    count: int | None
    methods: list              # PUB Methods of the child
    consts: list               # integer constant names of the child


@dataclass
class ObjectScope:
    """What the methods of one object can use."""

    vars: list                                  # Var (VAR and DAT)
    consts: ConstGen
    methods: list = field(default_factory=list)  # Methods generated so far (callable)
    children: list = field(default_factory=list)
    labels: list = field(default_factory=list)   # DatLabel
    results: str | None = None                  # the results array (top object only)
    result_count: int = 0


class MethodGen:
    """Writes one method's body (list of ``(indent, text)`` lines)."""

    def __init__(self, rng: Rand, obj: ObjectScope, method: Method, params: list, locals_: list,
                 budget: int, is_top: bool = False, statements: int = 8):
        self.rng = rng
        self.obj = obj
        self.method = method
        self.params = params
        self.locals = locals_
        self.budget = budget
        self.is_top = is_top
        self.statements = statements
        self.lines: list[tuple[int, str]] = []
        self.ready: list[Var] = [Var("result", 4, kind="result")] + list(params)
        self.reserved: list[str] = []
        self.loops = 0          # open loops (next/quit allowed when > 0)
        self.in_args = 0        # > 0 while writing a call's arguments
        self.mult = 1
        self.cost = 0
        self.aborts = False

    # ----------------------------------------------------------------- scope
    def variables(self, write: bool = False) -> list:
        out = [v for v in self.obj.vars if not write or v.writable] + self.ready
        if write:
            out = [v for v in out if v.writable and v.name not in self.reserved]
        return out

    def charge(self, units: int) -> None:
        self.cost += units * self.mult

    def can_afford(self, units: int) -> bool:
        return self.cost + units * self.mult <= self.budget

    # ------------------------------------------------------------ generation
    def body(self) -> list:
        """The whole method: locals set first, then random statements."""
        rng = self.rng
        for v in self.locals:
            self._init_local(v)
        for _ in range(self.statements):
            self.statement(2, 2)
        if self.method.recursive:
            self._recursion(2)
        if not self.is_top and rng.chance(0.4):
            self.emit(2, f"{rng.case('return')} {self.expr(2)}")
        return self.lines

    def emit(self, indent: int, text: str) -> None:
        self.lines.append((indent, text))
        self.charge(2)

    def _init_local(self, v: Var) -> None:
        rng = self.rng
        if v.count:
            how = rng.weighted({"fill": 2, "each": 1})
            if how == "fill":
                self.emit(2, f"{rng.case('longfill')}(@{v.name}, {self.expr(1)}, {v.count})")
            else:
                for i in range(v.count):
                    self.emit(2, f"{v.name}[{i}] := {self.expr(1)}")
        else:
            self.emit(2, f"{rng.case(v.name)} := {self.expr(1)}")
        self.ready.append(v)

    def _recursion(self, indent: int) -> None:
        rng = self.rng
        d = self.params[0].name
        self.emit(indent, f"{rng.case('if')} {d} > 0")
        self.in_args += 1
        call = f"{self.method.name}({d} - 1{''.join(', ' + self.expr(1) for _ in range(self.method.params - 1))})"
        self.in_args -= 1
        if self.method.aborts or rng.chance(0.2):
            call = "\\" + call
        op = rng.pick([":=", "+=", "^=", "-="])
        self.emit(indent + 2, f"result {op} {call}")

    # ------------------------------------------------------------ statements
    def block(self, indent: int, depth: int, n: int | None = None) -> None:
        for _ in range(n or self.rng.between(1, 3)):
            self.statement(indent, depth)

    def statement(self, indent: int, depth: int) -> None:
        rng = self.rng
        kinds = {
            "assign": 8, "op_assign": 4, "unary": 2, "pre_post": 2, "record": 6 if self.obj.results else 0,
            "if": 3 if depth > 0 else 0, "case": 2 if depth > 0 else 0, "repeat": 3 if depth > 0 else 0,
            "call": 3, "fill": 1, "next_quit": 2 if self.loops else 0,
            "abort": 1 if self.method.aborts and indent > 2 else 0,
            "return": 1 if not self.is_top and indent > 2 else 0,
            "pins": 2,
        }
        getattr(self, "st_" + rng.weighted(kinds))(indent, depth)

    def st_assign(self, indent, depth):
        lv = self.lvalue(2, write=True)
        text = f"{lv} := {self.expr(3)}"
        if self.rng.chance(0.1):    # a chain: a := b := expr
            text = f"{self.lvalue(1, write=True)} := {text}"
        self.emit(indent, text)

    def st_op_assign(self, indent, depth):
        op = self.rng.weighted(ASSIGN_OPS)
        self.emit(indent, f"{self.lvalue(2, write=True)} {self.rng.case(op)} {self.expr(3)}")

    def st_unary(self, indent, depth):
        op = self.rng.pick(UNARY_STATEMENTS)
        self.emit(indent, unary_text(self.rng.case(op) if op in WORD_OPS else op, self.lvalue(2, write=True)))

    def st_pre_post(self, indent, depth):
        self.emit(indent, self.pre_post(2))

    def st_record(self, indent, depth):
        self.record(indent, self.expr(3))

    def record(self, indent: int, value: str) -> None:
        """``results[k] := value`` with the next free ``k``."""
        k = self.obj.result_count
        self.obj.result_count += 1
        self.emit(indent, f"{self.obj.results}[{k}] := {value}")

    def st_pins(self, indent, depth):
        rng = self.rng
        reg = rng.case(rng.pick(["outa", "dira", "outa", "outb"]))
        kind = rng.weighted({"bit": 3, "range": 3, "whole": 1})
        if kind == "bit":
            target = f"{reg}[{self.pin(1)}]"
        elif kind == "range":
            target = f"{reg}[{self.pin(1)}..{self.pin(1)}]"
        else:
            target = reg
        form = rng.weighted({"assign": 4, "post": 2, "unary": 1})
        if form == "assign":
            self.emit(indent, f"{target} := {self.expr(2)}")
        elif form == "post":
            self.emit(indent, f"{target}{rng.pick(['~', '~~', '++', '--'])}")
        else:
            self.emit(indent, f"!{target}")

    def pin(self, depth: int) -> str:
        if self.rng.chance(0.6):
            return str(self.rng.between(0, 23))
        return f"({self.expr(depth)}) & 15"

    def st_if(self, indent, depth):
        rng = self.rng
        inner = indent + rng.pick([2, 2, 1, 3, 4])
        self.emit(indent, f"{rng.case(rng.pick(['if', 'if', 'ifnot']))} {self.expr(2)}")
        self.block(inner, depth - 1)
        for _ in range(rng.pick([0, 0, 1, 2])):
            self.emit(indent, f"{rng.case(rng.pick(['elseif', 'elseif', 'elseifnot']))} {self.expr(2)}")
            self.block(inner, depth - 1)
        if rng.chance(0.5):
            self.emit(indent, rng.case("else"))
            self.block(inner, depth - 1)

    def st_case(self, indent, depth):
        rng = self.rng
        self.emit(indent, f"{rng.case('case')} {self.expr(2)}")
        value_indent = indent + rng.pick([2, 2, 1, 4])
        for _ in range(rng.between(1, 4)):
            match = ", ".join(self.case_value() for _ in range(rng.pick([1, 1, 1, 2, 3])))
            self._case_arm(value_indent, match, depth)
        if rng.chance(0.5):
            self._case_arm(value_indent, rng.case("other"), depth)

    def _case_arm(self, indent, match, depth):
        rng = self.rng
        if rng.chance(0.3):
            before = len(self.lines)
            self.statement_simple(indent)
            i, text = self.lines[before]
            self.lines[before] = (indent, f"{match}: {text}")
        else:
            self.emit(indent, f"{match}:")
            self.block(indent + rng.pick([2, 2, 1, 3]), depth - 1)

    def statement_simple(self, indent):
        getattr(self, "st_" + self.rng.pick(["assign", "op_assign", "pre_post", "assign"]))(indent, 0)

    def case_value(self) -> str:
        rng = self.rng
        kind = rng.weighted({"const": 5, "range": 3, "expr": 1})
        if kind == "const":
            return self.small_const()
        if kind == "range":
            return f"{self.small_const()}..{self.small_const()}"
        return self.expr(1)

    def small_const(self) -> str:
        rng = self.rng
        if rng.chance(0.8):
            v = rng.between(0, 9)
            return int_literal(rng, v) if rng.chance(0.9) else f"-{v}"
        return self.obj.consts.int_term(0)

    def st_repeat(self, indent, depth):
        rng = self.rng
        free = [v for v in self.locals if v.count is None and v in self.ready and v.name not in self.reserved]
        kinds = {"count": 3, "from": 3 if len(free) >= 2 else 0, "while": 2 if free else 0,
                 "post": 2 if free else 0, "forever": 1 if free else 0}
        kind = rng.weighted(kinds)
        n = rng.between(1, 4)
        if self.mult * n > MAX_MULT:
            return self.st_assign(indent, depth)
        inner = indent + rng.pick([2, 2, 1, 3, 4])
        held = []
        r = rng.case("repeat")
        if kind == "count":
            count = int_literal(rng, n) if rng.chance(0.5) else f"({self.expr(2)}) & {n}"
            self.emit(indent, f"{r} {count}")
        elif kind == "from":
            var, bound = free[0], free[1]
            held = [var.name, bound.name]
            self.reserved.extend(held)
            self.emit(indent, f"{bound.name} := ({self.expr(2)}) & 7")
            start, stop = str(rng.between(-2, 7)), bound.name
            if rng.chance(0.5):
                start, stop = stop, start
            n = 10      # |start - stop| + 1
            if self.mult * n > MAX_MULT:
                n = 1
                stop = start
            step = ""
            if rng.chance(0.5):
                step = f" {rng.case('step')} {rng.pick(['1', '2', '3', '-1', '-2', '(' + bound.name + ' & 1) + 1'])}"
            self.emit(indent, f"{r} {var.name} {rng.case('from')} {start} {rng.case('to')} {stop}{step}")
        else:
            k = free[0]
            held = [k.name]
            self.reserved.extend(held)      # the condition may not write the counter either
            self.emit(indent, f"{k.name} := 0")
            if kind == "while":
                word = rng.pick(["while", "until"])
                cond = f"{k.name}++ < {n}" if word == "while" else f"++{k.name} > {n}"
                if rng.chance(0.4):
                    cond = f"({cond}) {'AND' if word == 'while' else 'OR'} ({self.expr(1)})"
                self.emit(indent, f"{r} {rng.case(word)} {cond}")
            else:
                self.emit(indent, r)
                if kind == "forever":
                    self.emit(inner, f"{rng.case('if')} ++{k.name} > {n}")
                    self.emit(inner + 2, rng.case("quit"))
        self.loops += 1
        self.mult *= n
        self.block(inner, depth - 1)
        self.mult //= n
        self.loops -= 1
        for name in held:
            self.reserved.remove(name)
        if kind == "post":
            word = rng.pick(["while", "until"])
            k = held[0]
            cond = f"{k}++ < {n}" if word == "while" else f"++{k} > {n}"
            self.emit(indent, f"{rng.case(word)} {cond}")

    def st_next_quit(self, indent, depth):
        rng = self.rng
        self.emit(indent, f"{rng.case('if')} {self.expr(2)}")
        self.emit(indent + 2, rng.case(rng.pick(["next", "quit"])))

    def st_abort(self, indent, depth):
        self.aborts = True
        if self.rng.chance(0.2):
            self.emit(indent, self.rng.case("abort"))
        else:
            self.emit(indent, f"{self.rng.case('abort')} {self.expr(2)}")

    def st_return(self, indent, depth):
        if self.rng.chance(0.3):
            self.emit(indent, self.rng.case("return"))
        else:
            self.emit(indent, f"{self.rng.case('return')} {self.expr(2)}")

    def st_call(self, indent, depth):
        call = self.call(2)
        if call is None:
            return self.st_assign(indent, depth)
        self.emit(indent, call)

    def st_fill(self, indent, depth):
        rng = self.rng
        targets = [v for v in self.variables(write=True) if v.kind != "result"]
        if not targets:
            return self.st_assign(indent, depth)
        dst = rng.pick(targets)
        sizes = [s for s in (1, 2, 4) if s <= dst.size]
        size = rng.pick(sizes)
        n = dst.nbytes // size
        word = {1: "byte", 2: "word", 4: "long"}[size]
        if rng.chance(0.5):
            self.emit(indent, f"{rng.case(word + 'fill')}(@{dst.name}, {self.expr(2)}, {self.index(n + 1, 1)})")
        else:
            sources = [v for v in self.variables() if v.size >= size and v.kind != "result"]
            src = rng.pick(sources)
            m = min(n, src.nbytes // size)
            self.emit(indent, f"{rng.case(word + 'move')}(@{dst.name}, @{src.name}, {self.index(m + 1, 1)})")

    # ----------------------------------------------------------- expressions
    def expr(self, depth: int) -> str:
        rng = self.rng
        self.charge(1)
        if depth <= 0 or rng.chance(0.25):
            return self.term(depth)
        kind = rng.weighted({"binary": 8, "unary": 2, "effect": 3, "call": 2, "lookup": 1, "paren": 1,
                             "fold": 1})
        if kind == "unary":
            op = rng.weighted(INT_UNARY)
            return unary_text(rng.case(op) if op in WORD_OPS else op, self.operand(depth - 1))
        if kind == "effect":
            return self.effect(depth - 1)
        if kind == "call":
            return self.call(depth - 1, value=True) or self.term(depth)
        if kind == "lookup":
            return self.lookup(depth - 1)
        if kind == "paren":
            return f"({self.expr(depth - 1)})"
        if kind == "fold":
            return self.folded()
        op = rng.weighted(INT_BINARY)
        text = f"{self.operand(depth - 1)}{spaced(rng.case(op) if op in WORD_OPS else op)}{self.operand(depth - 1)}"
        return f"({text})" if rng.chance(0.4) else text

    def operand(self, depth: int) -> str:
        """An expression usable as an operand (a word operator's or an assignment's result gets parentheses)."""
        text = self.expr(depth)
        if " := " in text and not text.startswith("("):
            return f"({text})"
        return text

    def term(self, depth: int) -> str:
        rng = self.rng
        globals_ = [v for v in self.obj.vars if v.global_]
        kind = rng.weighted({"literal": 5, "const": 3, "read": 8, "address": 1 if globals_ else 0,
                             "table": 1 if any(lb.table for lb in self.obj.labels) else 0,
                             "string": 1, "child_const": 1 if self.obj.children else 0,
                             "constant": 1, "cogid": 0.2})
        if kind == "literal":
            v = int_value(rng)
            text = int_literal(rng, v)
            return "-" + text if rng.chance(0.1) else text
        if kind == "const":
            return self.obj.consts.int_term(0)
        if kind == "address":
            v = rng.pick(globals_)
            return f"@{rng.case(v.name)}"
        if kind == "table":
            tab = rng.pick([lb for lb in self.obj.labels if lb.table])
            return f"{rng.case(self._mem_word(tab.size))}[@@{tab.name}[{self.index(len(tab.table), depth)}]]"
        if kind == "string":
            return self.string_term()
        if kind == "child_const":
            child = rng.pick(self.obj.children)
            if child.consts:
                return f"{child.name}#{rng.case(rng.pick(child.consts))}"
            return "0"
        if kind == "constant":
            return f"{rng.case('constant')}({self.obj.consts.int_expr(2)})"
        if kind == "cogid":
            return rng.case("cogid")
        return self.lvalue(depth)

    @staticmethod
    def _mem_word(size: int) -> str:
        return {1: "byte", 2: "word", 4: "long"}[size]

    def string_term(self) -> str:
        rng = self.rng
        strings = [lb for lb in self.obj.labels if lb.string]
        text = '"' + "".join(rng.pick("abcxyz019 ") for _ in range(rng.between(1, 6))) + '"'
        kind = rng.weighted({"strsize": 3, "strcomp": 2, "dat": 2 if strings else 0, "first": 1})
        if kind == "strsize":
            return f"{rng.case('strsize')}({rng.case('string')}({text}))"
        if kind == "strcomp":
            other = text if rng.chance(0.5) else '"' + rng.pick("abc") + '"'
            a = f"{rng.case('string')}({text})"
            b = f"@{rng.pick(strings).name}" if strings and rng.chance(0.3) else f"{rng.case('string')}({other})"
            return f"{rng.case('strcomp')}({a}, {b})"
        if kind == "dat":
            return f"{rng.case('strsize')}(@{rng.pick(strings).name})"
        return f"{rng.case('byte')}[{rng.case('string')}({text})]"

    def folded(self) -> str:
        """``round``/``trunc``/``float`` in code, alone or followed by constant terms, in parentheses."""
        rng = self.rng
        consts = self.obj.consts
        word = rng.pick(["round", "trunc", "float"])
        inner = consts.int_term(0) if word == "float" else consts.float_expr(1)
        text = f"{rng.case(word)}({inner})"
        for _ in range(rng.pick([0, 1, 1, 2])):
            op = rng.weighted(INT_BINARY) if word != "float" else rng.pick(["+", "-", "*", "#>"])
            more = consts.int_term(0) if word != "float" else consts.float_term()
            if op in ("/", "//"):
                text = f"({text}{spaced(op)}{consts.nonzero_divisor(more)})"
                continue
            text += spaced(op) + more
        if rng.chance(0.4):     # what comes before it stays run-time code
            text = f"{self.operand(1)}{spaced(rng.pick(['+', '-', '*', '^', '|']))}{text}"
        return f"({text})"

    def effect(self, depth: int) -> str:
        rng = self.rng
        kind = rng.weighted({"pre_post": 4, "assign": 3, "op_assign": 3})
        if kind == "pre_post":
            return self.pre_post(depth)
        lv = self.lvalue(depth, write=True)
        op = ":=" if kind == "assign" else rng.weighted(ASSIGN_OPS)
        return f"({lv} {rng.case(op)} {self.expr(depth)})"

    def pre_post(self, depth: int) -> str:
        form = self.rng.weighted(PRE_POST)
        return form.replace("x", self.lvalue(depth, write=True))

    def lookup(self, depth: int) -> str:
        rng = self.rng
        word = rng.pick(["lookup", "lookupz", "lookdown", "lookdownz"])
        items = []
        for _ in range(rng.between(1, 5)):
            kind = rng.weighted({"value": 5, "range": 2, "string": 1 if word.startswith("lookup") else 0})
            if kind == "value":
                items.append(self.small_const() if rng.chance(0.6) else self.expr(depth - 1))
            elif kind == "range":
                items.append(f"{self.small_const()}..{self.small_const()}")
            else:
                items.append('"' + "".join(rng.pick("abcdef") for _ in range(rng.between(1, 3))) + '"')
        sel = f"({self.expr(depth)}) & 7" if rng.chance(0.6) else self.expr(depth)
        return f"{rng.case(word)}({sel}: {', '.join(items)})"

    # ---------------------------------------------------------------- calls
    def call(self, depth: int, value: bool = False) -> str | None:
        """A call of a method of this object or of a child (``None`` when none fits the budget)."""
        rng = self.rng
        options = []
        for m in self.obj.methods:
            if m.cost * 1 <= self.budget:
                options.append((None, m))
        for child in self.obj.children:
            for m in child.methods:
                options.append((child, m))
        options = [(c, m) for c, m in options if self.can_afford(m.cost)]
        if not options:
            return None
        child, m = rng.pick(options)
        self.charge(m.cost)
        args = []
        self.in_args += 1
        for i in range(m.params):
            if i == 0 and m.recursive:
                args.append(f"({self.expr(depth)}) & 3")
            else:
                args.append(self.expr(depth))
        self.in_args -= 1
        name = rng.case(m.name)
        if child is not None:
            if child.count:
                self.in_args += 1       # the index is computed after the call's frame is set up
                name = f"{child.name}[{self.index(child.count, depth)}].{name}"
                self.in_args -= 1
            else:
                name = f"{child.name}.{name}"
        text = name + (f"({', '.join(args)})" if args else "")
        if m.aborts:
            # an abort must not unwind past a call whose arguments are being computed: the
            # ROM interpreter would then call through a frame that is gone (the program runs wild)
            if self.is_top or self.in_args or rng.chance(0.7):
                text = "\\" + text
            else:
                self.aborts = True
        elif rng.chance(0.1):
            text = "\\" + text
        return text

    # ------------------------------------------------------------ variables
    def index(self, n: int, depth: int) -> str:
        """An index expression whose value is in ``0..n-1``."""
        rng = self.rng
        if n <= 1:
            return "0"
        if rng.chance(0.3):
            return int_literal(rng, rng.between(0, n - 1))
        e = self.expr(depth)
        if n & (n - 1) == 0:
            return f"({e}) & {n - 1}"
        return f"(({e}) >> 1) // {n}"

    def lvalue(self, depth: int, write: bool = False) -> str:
        """A variable, element, memory location or register to read (or write)."""
        rng = self.rng
        vs = self.variables(write)
        arrays = [v for v in vs if v.count]
        wide = [v for v in vs if v.size > 1 and v.kind != "result"]
        mem = [v for v in vs if v.kind != "result"]
        kind = rng.weighted({"scalar": 6 if any(v.count is None for v in vs) else 0,
                             "element": 5 if arrays else 0, "sub": 1 if wide else 0, "mem": 2 if mem else 0,
                             "reg": 1, "spr": 0.5})
        if kind == "scalar":
            v = rng.pick([v for v in vs if v.count is None])
            return rng.case(v.name)
        if kind == "element":
            v = rng.pick(arrays)
            return f"{rng.case(v.name)}[{self.index(v.count, depth - 1)}]"
        if kind == "sub":
            v = rng.pick(wide)
            size = rng.pick([s for s in (1, 2) if s < v.size])
            word = self._mem_word(size)
            return f"{v.name}.{rng.case(word)}[{self.index(v.nbytes // size, depth - 1)}]"
        if kind == "mem":
            v = rng.pick(mem)
            size = rng.pick([s for s in (1, 2, 4) if s <= v.size])
            word = rng.case(self._mem_word(size))
            n = v.nbytes // size
            if n == 1 and rng.chance(0.5):
                return f"{word}[@{v.name}]"
            return f"{word}[@{v.name}][{self.index(n, depth - 1)}]"
        if kind == "spr":
            if rng.chance(0.5):
                return f"{rng.case('spr')}[{rng.pick([4, 5, 6, 7, 10, 11])}]"
            return f"{rng.case('spr')}[4 + (({self.expr(depth - 1)}) & 3)]"
        reg = rng.case(rng.pick(["outa", "dira", "outb", "dirb", "frqa", "frqb"] if write else
                                ["outa", "dira", "outb", "dirb", "frqa", "phsb"]))
        if reg.lower().startswith(("out", "dir")) and rng.chance(0.6):
            if rng.chance(0.5):
                return f"{reg}[{self.pin(depth - 1)}]"
            return f"{reg}[{self.pin(depth - 1)}..{self.pin(depth - 1)}]"
        return reg
