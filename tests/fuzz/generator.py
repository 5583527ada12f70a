"""A random Spin program generator: well-typed Spin 1 programs that store their results and stop.

``generate(seed)`` gives a :class:`Program`: its files (``{name: text}``;
``main.spin`` is the top object, children are ``fzN.spin``) and where its
results are (:class:`Results`: the top object's ``long results[N]``, the first
VAR of the top object, so at the start of its VAR block).  The same seed gives
the same program.

What a program contains (each object drawn at random from these):

* CON: integer constants in every number format (decimal, ``$hex``,
  ``%binary``, ``%%quaternary``, characters, ``_`` separators) built with every
  constant operator; float constants (``1.5``, ``2e-3``, ``float()``, ``PI``)
  with the float operators; ``round()``/``trunc()`` between them;
  enumerations (``#start, A, B[skip]``); constants defined after their use;
  child constants ``obj#NAME``; clock settings.
* VAR: longs, words and bytes, scalars and arrays.
* DAT: data lines of every size with size overrides in the line
  (``byte 1, word 2, long 3, 4``), repetition ``value[count]``, strings,
  alignment lines, labels alone on a line, tables of ``@label`` offsets,
  ``file "fzN.dat"`` (a generated data file), and ``org`` blocks of PASM
  (every mnemonic, condition, effect, ``#``/register/``$``/``:local``
  operands, ``call``/``_ret``, ``res``, ``fit``) that no cog runs.
* OBJ: generated child objects (up to two levels), the same file under two
  names, object arrays ``name[n]``, ``.spin`` written or not.
* methods (PUB/PRI) with parameters, a named or unnamed result, locals and
  local arrays; statements: assignments (every assignment operator, chains),
  unary assignments, ``++ -- ~ ~~ ?`` before and after, ``if/ifnot/elseif/
  elseifnot/else``, ``case`` with values, ranges, lists and ``other``
  (one-line and block arms), ``repeat`` (forever with ``quit``, ``n``,
  ``from..to..step``, ``while``/``until`` before and after) with
  ``next``/``quit``, calls of own and child methods (object arrays included)
  with and without ``\\``, ``abort``, ``return``, ``byte/word/longfill``
  and ``...move``, pins: ``outa[n]``, ``outa[a..b]``, ``dira``.
* expressions: every unary and binary operator, side effects in any operand
  (``(x := e)``, ``(x += e)``, ``++x``, ``x--``, ``?x``, ``x~``, ``~~x``), calls
  with results, ``lookup/lookupz/lookdown/lookdownz`` with ranges and strings,
  ``constant()``, ``round/trunc/float`` in code, ``@var``, ``@@table[i]``,
  ``byte/word/long[addr][i]``, ``x.byte[i]``, ``spr[i]``, ``strsize``,
  ``strcomp``, ``string()``, ``cogid``.

The top method ``main`` records values in ``results[k]`` as it goes and ends by
returning or by ``cogstop(cogid)``.  See gen_code.py for what keeps programs
well-defined and finite.
"""
from __future__ import annotations

import os
import struct
from dataclasses import dataclass, field

from .gen_code import ChildRef, Method, MethodGen, ObjectScope, Var
from .gen_const import ConstGen, ConstScope, int_literal
from .gen_data import DatGen
from .rand import Rand

__all__ = ["generate", "Program", "Results"]

TOP = "main.spin"
RESULTS = "results"

CLOCKS = [
    [],
    ["_clkmode = xtal1 + pll16x", "_xinfreq = 5_000_000"],
    ["_CLKMODE = XTAL1 + PLL8X", "_XINFREQ = 10_000_000"],
    ["_clkmode = rcfast"],
    ["_clkmode = rcslow"],
    ["_clkmode = xinput + pll4x", "_xinfreq = 20_000_000"],
    ["_clkmode = xtal2 + pll2x", "_clkfreq = 40_000_000"],
    ["_clkmode = xtal3", "_xinfreq = 12_000_000"],
]


@dataclass
class Results:
    """Where a generated program leaves its results.

    Attributes:
        name: the VAR array in the top object (``results``).
        var_offset: its byte offset from the start of the top object's VAR
            block (the header's ``vbase``).
        count: how many longs it has.
    """

    name: str
    var_offset: int
    count: int

    def read(self, binary: bytes, hub: bytes) -> list:
        """The ``count`` longs of the results array in ``hub`` (32 KB) of a run of ``binary``."""
        vbase = struct.unpack_from("<H", binary, 8)[0] + self.var_offset
        return list(struct.unpack_from(f"<{self.count}I", hub, vbase))


@dataclass
class Program:
    """A generated program: ``files`` (name -> Spin text), the top file's name, and its :class:`Results`."""

    seed: int
    files: dict
    results: Results
    top: str = TOP

    def write(self, folder: str) -> str:
        """Write every file into ``folder``; returns the top file's path."""
        for name, text in self.files.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8", newline="\n") as fh:
                fh.write(text)
        return os.path.join(folder, self.top)

    def text(self) -> str:
        """All files, each under a ``' ==== name`` line (top first)."""
        names = [self.top] + [n for n in self.files if n != self.top]
        return "".join(f"' ==== {n}\n{self.files[n]}" for n in names)


class _Names:
    def __init__(self):
        self.counts: dict = {}

    def new(self, prefix: str) -> str:
        n = self.counts.get(prefix, 0)
        self.counts[prefix] = n + 1
        return f"{prefix}{n}"


@dataclass
class _Built:
    """A generated object file as its parent sees it."""

    filename: str
    methods: list          # PUB Methods
    consts: list           # integer constant names


class _ProgramGen:
    def __init__(self, seed: int):
        self.rng = Rand(seed)
        self.seed = seed
        self.files: dict = {}
        self.n_files = 0

    def program(self) -> Program:
        self._object(level=0, filename=TOP)
        return Program(self.seed, self.files, Results(RESULTS, 0, self.result_count))

    # ----------------------------------------------------------------- object
    def _object(self, level: int, filename: str) -> _Built:
        rng = self.rng
        names = _Names()
        top = level == 0
        sections: list[list[str]] = []

        children, obj_lines = self._children(level, names)
        cscope = ConstScope(child_ints=[f"{c.name}#{k}" for c in children for k in c.consts][:12])
        consts = ConstGen(rng, cscope)
        con_lines = self._con(consts, cscope, names, top)

        var_lines, vars_ = self._var(names, top)
        dat = DatGen(rng, consts, names, self._add_data_file)
        dat_lines = dat.section(rng.between(0, 6)) if rng.chance(0.8) else []
        for lb in dat.labels:
            vars_.append(Var(lb.name, lb.size, lb.count, "dat", writable=lb.count is not None, label=lb))

        scope = ObjectScope(vars_, consts, children=children, labels=dat.labels,
                            results=RESULTS if top else None)
        methods_text, pubs = self._methods(scope, names, top)
        if top:
            self.result_count = max(scope.result_count, 1)
            var_lines.insert(1, f"  long {RESULTS}[{self.result_count}]")

        sections.append(con_lines)
        if obj_lines:
            sections.append(obj_lines)
        sections.append(var_lines)
        if dat_lines and rng.chance(0.5):
            sections.append(dat_lines)
            dat_lines = []
        sections.append(methods_text)
        if dat_lines:
            sections.append(dat_lines)
        self.files[filename] = "\n".join(line for sec in sections for line in sec) + "\n"
        ints = [n for n in cscope.ints if not n.startswith("_")]
        return _Built(filename, pubs, ints)

    def _add_data_file(self, text: str) -> str:
        self.n_files += 1
        name = f"fz{self.n_files}.dat"
        self.files[name] = text
        return name

    def _children(self, level: int, names: _Names):
        rng = self.rng
        if level >= 2 or not rng.chance(0.7 if level == 0 else 0.3):
            return [], []
        built = []
        for _ in range(rng.between(1, 2 if level else 3)):
            self.n_files += 1
            built.append(self._object(level + 1, f"fz{self.n_files}.spin"))
        refs, lines = [], [rng.case("OBJ")]
        for b in built:
            for _ in range(rng.pick([1, 1, 1, 2])):
                name = names.new("c")
                count = rng.pick([None, None, 2, 3])
                stem = b.filename[:-5] if rng.chance(0.7) else b.filename
                lines.append(f"  {name}{f'[{count}]' if count else ''} : \"{stem}\"")
                refs.append(ChildRef(name, count, b.methods, b.consts))
        return refs, lines

    # -------------------------------------------------------------------- CON
    def _con(self, consts: ConstGen, cscope: ConstScope, names: _Names, top: bool) -> list:
        rng = self.rng
        defs = []        # (name, text), in definition (dependency) order
        deps = {}
        for _ in range(rng.between(1, 8)):
            consts.used = []
            if rng.chance(0.3):
                name = names.new("F")
                defs.append((name, consts.float_expr(rng.between(0, 2))))
                cscope.floats.append(name)
            else:
                name = names.new("K")
                defs.append((name, consts.int_expr(rng.between(0, 3))))
                cscope.ints.append(name)
            deps[name] = list(consts.used)      # "#": a child's constant
        # constants may be used before the line that defines them, as far as OpenSpin's
        # two passes over the CON lines resolve them
        if rng.chance(0.5):
            shuffled = list(defs)
            rng.shuffle(shuffled)
            if _two_passes_resolve([n for n, _ in shuffled], deps):
                defs = shuffled
        lines = [rng.case("CON")]
        if top:
            lines += ["  " + c for c in rng.pick(CLOCKS)]
            if rng.chance(0.2):
                lines.append(f"  _stack = {rng.between(16, 200)}")
        i = 0
        while i < len(defs):
            n = rng.pick([1, 1, 1, 2, 3])
            lines.append("  " + ", ".join(f"{rng.case(nm)} = {tx}" for nm, tx in defs[i:i + n]))
            i += n
        if rng.chance(0.5):
            lines.append(self._enum(consts, cscope, names))
        return lines

    def _enum(self, consts: ConstGen, cscope: ConstScope, names: _Names) -> str:
        rng = self.rng
        parts = []
        if rng.chance(0.7):
            start = int_literal(rng, rng.between(0, 20)) if rng.chance(0.7) else consts.int_expr(1)
            parts.append("#" + (f"({start})" if start[0] in "-+!|^<>~?@#=*/&" else start))
        for _ in range(rng.between(1, 5)):
            name = names.new("E")
            parts.append(f"{name}[{int_literal(rng, rng.between(0, 4))}]" if rng.chance(0.3) else name)
            cscope.ints.append(name)
        return "  " + ", ".join(parts)

    # -------------------------------------------------------------------- VAR
    def _var(self, names: _Names, top: bool):
        rng = self.rng
        lines = [rng.case("VAR")]
        vars_ = []
        for _ in range(rng.between(0 if not top else 1, 5)):
            size_word = rng.pick(["long", "long", "word", "byte"])
            size = {"long": 4, "word": 2, "byte": 1}[size_word]
            items = []
            for _ in range(rng.between(1, 3)):
                name = names.new({4: "g", 2: "w", 1: "b"}[size])
                count = rng.pick([None, None, 1, 2, 3, 4, 5, 8])
                items.append(f"{name}[{int_literal(rng, count)}]" if count else name)
                vars_.append(Var(name, size, count))
            lines.append(f"  {rng.case(size_word)} {', '.join(items)}")
        return lines, vars_

    # ---------------------------------------------------------------- methods
    def _methods(self, scope: ObjectScope, names: _Names, top: bool):
        rng = self.rng
        n = rng.between(1, 4) if top else rng.between(1, 3)
        recursive_at = rng.between(0, n - 1) if rng.chance(0.5) else None
        texts = []
        for i in range(n):
            recursive = i == recursive_at
            m = Method(names.new("m"), rng.between(1 if recursive else 0, 3),
                       pub=not top or rng.chance(0.3), aborts=rng.chance(0.25), recursive=recursive)
            texts.append((m, self._method(scope, m, names, budget=1500, statements=rng.between(2, 6))))
            scope.methods.append(m)
        pubs = [m for m in scope.methods if m.pub]
        order = list(texts)
        rng.shuffle(order)
        if top:
            main = Method("main", 0, pub=True)
            main_text = self._method(scope, main, names, budget=8000, statements=rng.between(8, 16), is_top=True)
            # main must be the first PUB (PRIs may come before it)
            first_pub = next((i for i, (m, _) in enumerate(order) if m.pub), len(order))
            order.insert(first_pub, (main, main_text))
        return [line for _, text in order for line in text], pubs

    def _method(self, scope: ObjectScope, m: Method, names: _Names, budget: int, statements: int,
                is_top: bool = False) -> list:
        rng = self.rng
        params = [Var(names.new("p"), 4, kind="param") for _ in range(m.params)]
        if m.recursive:
            params[0].writable = False
        locals_ = []
        for _ in range(rng.between(2 if not is_top else 3, 5)):
            count = rng.pick([None, None, None, 2, 4])
            locals_.append(Var(names.new("l"), 4, count, kind="local"))
        gen = MethodGen(rng, scope, m, params, locals_, budget, is_top=is_top, statements=statements)
        body = gen.body()
        if is_top:
            self._main_tail(gen)
        m.cost = max(1, gen.cost) * (5 if m.recursive else 1)
        m.aborts = m.aborts or gen.aborts
        head = f"{rng.case('PUB' if m.pub else 'PRI')} {m.name}"
        if params:
            head += f"({', '.join(p.name for p in params)})"
        if rng.chance(0.3):
            head += " : r"
        if locals_:
            head += " | " + ", ".join(f"{v.name}[{v.count}]" if v.count else v.name for v in locals_)
        if " : r" in head:
            body = [(i, _rename_result(t)) for i, t in body]
        return [head] + [" " * i + t for i, t in body] + [""]

    def _main_tail(self, gen: MethodGen) -> None:
        rng = self.rng
        for reg in ("outa", "dira"):
            gen.record(2, rng.case(reg))
        if rng.chance(0.2):
            gen.emit(2, f"{rng.case('cogstop')}({rng.case('cogid')})")


def _two_passes_resolve(order: list, deps: dict) -> bool:
    """Whether definitions in this order all resolve in two passes (each pass in order)."""
    known: set = set()
    for pass_no in range(2):
        if pass_no:
            known.add("#")
        for name in order:
            if name not in known and all(d in known for d in deps[name]):
                known.add(name)
    return all(name in known for name in order)


def _rename_result(text: str) -> str:
    """``result`` written as the method's result name ``r`` (both name the same long)."""
    import re
    return re.sub(r"\bresult\b", "r", text)


def generate(seed: int) -> Program:
    """The random program of ``seed`` (always the same for the same seed).

    >>> p = generate(1)
    >>> p.top in p.files and p.results.count >= 1
    True
    """
    return _ProgramGen(seed).program()
