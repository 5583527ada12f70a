"""A Spin program as Python modules: one module, one class per Spin object.

:func:`translate_program` loads the program with the front end, compiles it
with the compiler (whose symbols, layout and bytecode the translation uses),
and writes for each object a module like::

    class Stepper(spin.Object):
        '''Stepper motor object'''

        M_ENABLED = 0b0001                       # CON: class constants
        cogon = spin.Long(0)                     # VAR: hub RAM at vbase + 0
        Steps = spin.Byte(48, 4, dat=True)       # DAT: hub RAM at pbase + 48

        def setMode(self, m):                    # PUB/PRI: methods
            self.mode = m & 0b1111               # L49: update mode

Names keep their Spin spelling (Spin is case-insensitive, so every use is
spelled as the declaration); a name that is a Python keyword or clashes with
the runtime gets a trailing underscore.
"""
from __future__ import annotations

import keyword
import os
import re
from dataclasses import dataclass, field

from ..compiler.objcode import ObjectCompiler
from ..compiler.program import _compile_unit
from ..compiler import stmts as cstmts
from ..chip.timing import load_timing
from ..diagnostics import Diagnostic, SpinError
from ..frontend import ast as A
from ..frontend.ast import key
from ..frontend.objects import load_program
from ..compiler.symbols import MethodSymbol, ObjSymbol, VarSymbol
from ..compiler.dat import DatSymbol
from .code import Code, docstring_text
from .costs import price
from .stmts import MethodTranslator

__all__ = ["TranslateError", "ModuleText", "translate_program"]

_RESERVED_LOCALS = {"self", "spin", "cog", "wrap", "range", "max", "min", "abs", "ord"}
_RESERVED_ATTRS = {"at", "addr", "object_base", "string", "_pbase", "_vbase", "mro", "spin"}


#: the notes of the jumps the compiler makes for statements (compiler/stmts.py)
_JUMP_NOTES = frozenset(("if", "to end of if", "repeat", "repeat n", "repeat while", "repeat from",
                         "case value", "case range", "next", "quit"))


class TranslateError(SpinError):
    """A Spin construct the translator does not handle (it names the construct and its place)."""


@dataclass
class ModuleText:
    """One generated module: file name, class name, text, Spin line per Python line."""

    module: str
    class_name: str
    text: str
    spin_lines: list
    spin_path: str
    children: list = field(default_factory=list)


def _py_name(name: str, reserved=()) -> str:
    if keyword.iskeyword(name) or keyword.issoftkeyword(name) or name in reserved or name.startswith("__"):
        return name + "_"
    return name


def class_name(path: str) -> str:
    """``stepper_demo.spin`` -> ``StepperDemo``."""
    base = os.path.splitext(os.path.basename(path))[0]
    parts = [p for p in re.split(r"[^0-9A-Za-z]+", base) if p]
    name = "".join(p[:1].upper() + p[1:] for p in parts) or "SpinObject"
    return name if name[0].isalpha() else "Spin" + name


def module_name(path: str) -> str:
    base = os.path.splitext(os.path.basename(path))[0]
    name = re.sub(r"[^0-9A-Za-z_]", "_", base).lower() or "spin_object"
    return _py_name(name if not name[0].isdigit() else "m" + name)


class Names:
    """Python names for one object's Spin names (declared spelling, keyword-safe)."""

    def __init__(self, unit, locals_of=None):
        self.unit = unit
        self.attrs = {}
        spin = unit.spin
        for c in spin.cons:
            if getattr(c, "name", None):
                self.attrs[key(c.name)] = _py_name(c.name, _RESERVED_ATTRS)
        for v in spin.vars:
            self.attrs[key(v.name)] = _py_name(v.name, _RESERVED_ATTRS)
        for o in spin.objs:
            self.attrs[key(o.name)] = _py_name(o.name, _RESERVED_ATTRS)
        for m in spin.methods:
            self.attrs[key(m.name)] = _py_name(m.name, _RESERVED_ATTRS)
        for d in spin.dat:
            if d.label is not None and not d.label.local:
                self.attrs[key(d.label.name)] = _py_name(d.label.name, _RESERVED_ATTRS)
        self.locals = {}
        self.children = {key(decl.name): child for decl, child in unit.children}

    def attr(self, name: str) -> str:
        return self.attrs.get(key(name), _py_name(name, _RESERVED_ATTRS))

    def set_method(self, method, in_frame: bool = False) -> None:
        """Names for ``method``'s result, parameters and locals (``in_frame``: they are ``spin.Frame`` fields)."""
        self.locals = {}
        reserved = _RESERVED_LOCALS | ({"addr", "at"} if in_frame else set())
        names = ([method.result] if method.result else []) + [p for p, _ in method.params] + \
            [loc.name for loc in method.locals]
        for n in names:
            self.locals.setdefault(key(n), _py_name(n, reserved))

    def local(self, name: str) -> str:
        return self.locals.get(key(name), _py_name(name, _RESERVED_LOCALS))

    def temp_base(self, prefix: str) -> str:
        name = prefix
        while key(name) in self.locals or name in _RESERVED_LOCALS:
            name += "_"
        return name

    def child_method(self, obj: str, method: str) -> str:
        child = self.children[key(obj)]
        for m in child.spin.methods:
            if key(m.name) == key(method):
                return _py_name(m.name, _RESERVED_ATTRS)
        return _py_name(method, _RESERVED_ATTRS)

    def child_const(self, obj: str, name: str) -> str:
        child = self.children[key(obj)]
        for c in child.spin.cons:
            if getattr(c, "name", None) and key(c.name) == key(name):
                return _py_name(c.name, _RESERVED_ATTRS)
        return _py_name(name, _RESERVED_ATTRS)


class _StringTracker(cstmts.MethodCompiler):
    """The compiler's method compiler, noting where each ``string(...)`` lands in the string pool."""

    def __init__(self, obj, method):
        super().__init__(obj, method)
        self.string_index = {}

    def builtin(self, node, want):
        if node.name == "string":
            self.string_index[id(node)] = len(self.code.strings)
        return super().builtin(node, want)


class ObjectTranslator:
    """Translates one object (one .spin file) to one module."""

    def __init__(self, unit, cobj, timing, classes: dict, values_used: frozenset = frozenset()):
        self.unit = unit
        self.values_used = values_used
        self.cobj = cobj
        self.timing = timing
        self.classes = classes
        errors: list = []
        self.oc = ObjectCompiler(unit, errors, set())
        self.oc.compile()
        self.names = Names(unit)
        self.infos = {key(m.name): m for m in cobj.methods}
        self._strings = {}
        self._dat_counts = _dat_counts(unit, self.oc)
        self.frame_methods: set = set()
        self._offsets = None
        self.cog_methods = _cog_methods(unit)

    # ------------------------------------------------------------------ lookups (for MethodTranslator)
    def unsupported(self, what: str, node):
        pos = node.pos
        src = self.unit.spin.source.line(pos.line) if pos else None
        raise TranslateError(diagnostics=[Diagnostic(
            f"cannot translate {what} to Python (not supported yet)", pos.path if pos else self.unit.path,
            pos.line if pos else None, pos.col if pos else None, src)])

    def lookup(self, name: str, node):
        c = self.oc.const(name)
        if c is not None:
            return "const", c.bits
        sym = self.oc.symbols.get(name)
        if isinstance(sym, VarSymbol):
            return "var", sym
        if isinstance(sym, DatSymbol):
            return "dat", _DatView(sym, self._dat_counts.get(key(sym.name), 1))
        if isinstance(sym, MethodSymbol):
            return "method", sym
        if isinstance(sym, ObjSymbol):
            return "obj", sym
        self.unsupported(f"the name '{name}'", node)

    def string_offset(self, method, node) -> int:
        table = self._strings.get(key(method.name))
        if table is None:
            mc = _StringTracker(self.oc, method)
            buf = mc.compile()
            spans, _end = buf.layout(self.infos[key(method.name)].offset)
            # each push of a string's address, in the order compiled: the compiler's own pool
            # addresses (some strings share one, as in OpenSpin: compiler/code.py)
            pushes = [((sp.data[1] & 0x7F) << 8) | sp.data[2] for sp in spans
                      if sp.note == "string" and sp.pos is not None]
            table = {nid: pushes[i] for nid, i in mc.string_index.items()}
            self._strings[key(method.name)] = table
        return table[id(node)]

    def offset_of(self, pos, method) -> int:
        """Object offset of the first bytecode compiled for the statement at ``pos`` (else the method's start)."""
        self._index_spans()
        found = self._offsets.get((pos.line, pos.col))
        return found if found is not None else self.infos[key(method.name)].offset

    def known_offset(self, pos):
        """Object offset of the first bytecode compiled at ``pos``, or None (nothing was compiled there)."""
        self._index_spans()
        return self._offsets.get((pos.line, pos.col))

    def compiled_at(self, pos) -> bytes:
        """The bytecode the compiler made for the statement at ``pos``, at its real place (so a jump has its real size)."""
        self._index_spans()
        return bytes(self._bytes.get((pos.line, pos.col), b""))

    def long_jumps_at(self, pos, note: str) -> list:
        """For each jump the compiler made at ``pos`` with ``note`` ("if", "repeat", "case value" ...), in
        order: is it the two-byte form?

        Read from the compiled object: a jump's size depends on the layout of
        everything between it and its target, other jumps included.
        """
        self._index_spans()
        return list(self._jumps.get((pos.line, pos.col, note), ()))

    def _index_spans(self) -> None:
        if self._offsets is None:
            self._offsets, self._bytes, self._jumps = {}, {}, {}
            for span in self.cobj.spans:
                if span.pos is not None and span.data:
                    at = (span.pos.line, span.pos.col)
                    self._offsets.setdefault(at, span.offset)
                    self._bytes.setdefault(at, bytearray()).extend(span.data)
                    if span.note in _JUMP_NOTES:
                        self._jumps.setdefault(at + (span.note,), []).append(len(span.data) > 2)

    def method_end(self, method) -> int:
        return self.infos[key(method.name)].end

    def uses_result(self, method) -> bool:
        names = {"result"} | ({key(method.result)} if method.result else set())
        return _mentions(method.body, names, result_ref=True)

    def gives_value(self, method) -> bool:
        """Must the Python method return a number where it falls off its end?

        Spin returns RESULT (0 unless set) from every method, Python returns
        ``None``: so a method returns 0 at its end when a call somewhere in
        the program uses its value, or when it returns a value elsewhere
        (consistent returns, PEP 8).
        """
        return (self.unit.path, key(method.name)) in self.values_used or \
            any(isinstance(n, A.Return) and n.value is not None for n in A.walk(method.body))

    def read_after(self, method, stmt, name: str) -> bool:
        return _count_mentions(method.body, name) > _count_mentions([stmt], name)

    # ------------------------------------------------------------------ module
    def translate(self) -> ModuleText:
        spin = self.unit.spin
        code = Code(spin)
        cls = self.classes[self.unit.path]
        doc = _file_doc(spin)
        base = docstring_text(os.path.basename(self.unit.path))
        code.raw('"""' + (docstring_text(doc[0]) if doc else base))
        for d in doc[1:]:
            code.raw(docstring_text(d))
        code.raw("")
        code.raw(f"Translated from {base} by spinemu.translate (generated: do not edit).")
        code.raw("Each statement ends with '# L<n>', its Spin source line. Spin longs are signed ints; `wrap`")
        code.raw("keeps a result to 32 bits. `cog` is the cog running the code (cog.OUTA[7:4] is outa[7..4]).")
        code.raw('"""')
        code.raw("from spinemu.translate import spin")
        code.raw("from spinemu.translate.spin import cog, wrap")
        children = []
        for decl, child in self.unit.children:
            if child.path not in [c.path for c in children]:
                children.append(child)
        for child in children:
            code.raw(f"from .{module_name(child.path)} import {self.classes[child.path]}")
        code.raw("")
        code.raw("")
        code.raw(f"class {cls}(spin.Object):")
        code.indent = 1
        code.line('"""' + docstring_text(_summary(doc, self.unit.path)) + '"""')
        code.line("")
        code.line(f'SPIN_FIRST_METHOD = "{self.names.attr(self.cobj.methods[0].name)}"'
                  if self.cobj.methods else "SPIN_FIRST_METHOD = None")
        self.constants(code)
        self.variables(code)
        self.objects(code)
        for m in spin.methods:
            self.method(code, m)
        self.dat(code)
        code.indent = 0
        code.raw("")
        code.raw("")
        code.raw("# Cycles each line costs on the chip (Python line: before, after, else/exit), woven in by")
        code.raw("# spinemu.translate.weave when the class first runs; see docs/translate.md.")
        table = code.charge_table()
        code.raw("SPIN_CYCLES = {")
        for line, row in table.items():
            code.raw(f"    {line}: {row!r},")
        code.raw("}")
        code.raw("# bytes each method's frame takes on the hub stack (result, parameters, locals), and")
        code.raw("# the stack bytes in use at calls made from a line (where a called method's frame goes)")
        sizes = {self.names.attr(m.name): 4 + 4 * m.nparams + m.locals_size for m in self.cobj.methods}
        code.raw(f"SPIN_FRAME_SIZES = {sizes!r}")
        code.raw(f"SPIN_METHODS = {({self.names.attr(m.name): m.index for m in self.cobj.methods})!r}")
        code.raw(f"SPIN_CALL_DEPTHS = {dict(sorted(code.call_depths.items()))!r}")
        if code.lookups:
            code.raw("# lookup/lookdown lines, each lookup on the line from the left: cycles per item, of")
            code.raw("# LOOK_DONE, and what a match adds per item")
            code.raw("SPIN_LOOKUPS = {")
            for line, row in sorted(code.lookups.items()):
                code.raw(f"    {line}: {row!r},")
            code.raw("}")
        return ModuleText(module_name(self.unit.path), cls, code.text(), code.spin_lines, self.unit.path,
                          [c.path for c in children])

    def constants(self, code: Code) -> None:
        items = [c for c in self.unit.spin.cons if isinstance(c, (A.ConDef, A.ConEnumName))]
        if not items:
            return
        code.line("")
        code.line("# CON: constants")
        defined = set()
        for c in items:
            value = self.oc.const(c.name)
            if value is None:
                continue
            text = _con_text(c, self.oc, value, defined, self.names)
            defined.add(key(c.name))
            spin_text = _con_source(self.unit.spin, c)
            plain = isinstance(c, A.ConDef) and (isinstance(c.value, A.Number) or text == spin_text)
            note = f"{spin_text}:" if spin_text and not plain and not text.startswith(spin_text) else ""
            code.line(f"{self.names.attr(c.name)} = {text}", c.pos.line, note=note.rstrip(":")
                      if not self.unit.spin.comments_at(c.pos.line) else note)

    def variables(self, code: Code) -> None:
        syms = {key(v.name): v for v in self.oc.symbols.vars}
        if not self.unit.spin.vars:
            return
        code.line("")
        code.line("# VAR: variables in hub RAM (offset from the object's VAR base)")
        kind = {1: "Byte", 2: "Word", 4: "Long"}
        for decl in self.unit.spin.vars:
            sym = syms[key(decl.name)]
            count = f", {sym.count}" if sym.count != 1 else ""
            code.line(f"{self.names.attr(decl.name)} = spin.{kind[sym.size]}({sym.offset}{count})", decl.pos.line)

    def objects(self, code: Code) -> None:
        if not self.unit.spin.objs:
            return
        code.line("")
        code.line("# OBJ: child objects")
        for decl, child in self.unit.children:
            sym = self.oc.symbols.get(decl.name)
            count = f", {sym.count}" if sym.count != 1 else ""
            code.line(f"{self.names.attr(decl.name)} = spin.Child({self.classes[child.path]}{count})", decl.pos.line)

    def dat(self, code: Code) -> None:
        labels = [s for s in self.cobj.dat_symbols.values() if not s.reserved]
        if not labels:
            return
        code.line("")
        code.line("# DAT: data in hub RAM (offset from the object's start; the values are in the image)")
        kind = {1: "Byte", 2: "Word", 4: "Long"}
        for s in sorted(labels, key=lambda s: s.offset):
            count = self._dat_counts.get(key(s.name), 1)
            extra = f", {count}" if count != 1 else ""
            code.line(f"{self.names.attr(s.name)} = spin.{kind[s.size]}({s.offset}{extra}, dat=True)", s.pos.line)

    def method(self, code: Code, m) -> None:
        from .stmts import needs_hub_frame
        self.names.set_method(m, needs_hub_frame(m))
        params = "".join(f", {self.names.local(p)}" for p, _ in m.params)
        code.line("")
        code.comments_before(m.pos.line)
        code.line(f"def {self.names.attr(m.name)}(self{params}):", m.pos.line)
        code.indent += 1
        doc = _method_doc(self.unit.spin, m)
        if doc:
            doc = [docstring_text(d) for d in doc]
            if len(doc) == 1:
                code.line('"' * 3 + doc[0] + '"' * 3)
            else:
                code.line('"' * 3 + doc[0])
                for d in doc[1:]:
                    code.line(d)
                code.line('"' * 3)
            code.skip_to(m.pos.line + len(doc) + 1)
        mt = MethodTranslator(self, m, code)
        uses_result = self.uses_result(m)
        if mt.in_frame:
            fields = [f"{self.names.local(m.result or 'result')}=0"]
            fields += [f"{self.names.local(p)}={self.names.local(p)}" for p, _ in m.params]
            for loc in m.locals:
                count = "" if loc.count is None else str(self.oc.count_of(loc.count))
                fields.append(f"{self.names.local(loc.name)}=spin.local({count})")
            code.line("# this method's variables live in hub RAM, on the cog's stack (their address is used)")
            code.line(f"{mt.frame_name} = spin.Frame({', '.join(fields)})")
            self.frame_methods.add(m.name)
        else:
            inits = [self.names.local(m.result or "result")] if uses_result else []
            unset = [loc.name for loc in m.locals if _needs_init(m, loc.name)]
            if key(m.name) in self.cog_methods and unset:
                # a cog can start here: its stack holds what cognew left (the interpreter's start words)
                if inits:
                    code.line(" = ".join(inits) + " = 0")
                inits = [self.names.local(n) for n in unset]
                offsets = ", ".join(str(mt.frame[key(n)].offset) for n in unset)
                code.line(f"{', '.join(inits)} = spin.left_on_stack({offsets})")
            else:
                inits += [self.names.local(n) for n in unset]
                if inits:
                    code.line(" = ".join(inits) + " = 0")
        last = None
        for st in m.body:
            _first, last = mt.statement(st)
        ret = mt.piece(lambda: mt.mc.code.emit(0x32))
        ends = m.body and isinstance(m.body[-1], (A.Return, A.Abort))
        if not ends:
            if uses_result or self.gives_value(m):
                line = code.line(f"return {mt.result_text() if uses_result else 0}")
                code.charge(line, "b", ret)
            elif last is None:
                line = code.line("pass")
                code.charge(line, "b", ret)
            else:
                code.charge(self._def_line(code, m), "a", ret)
        code.indent -= 1
        code.skip_to(m.end_line)

    def _def_line(self, code, m) -> int:
        for i in range(len(code.lines) - 1, -1, -1):
            if code.lines[i].lstrip().startswith(f"def {self.names.attr(m.name)}("):
                return i + 1
        raise AssertionError("method line not found")


class _DatView:
    """A DAT label as the expression translator sees it (``count``: elements on its line)."""

    def __init__(self, sym, count):
        self.sym = sym
        self.count = count
        self.size = sym.size


def _dat_counts(unit, oc) -> dict:
    from ..frontend.constants import evaluate
    counts = {}
    for line in unit.spin.dat:
        if line.label is None or line.label.local or not isinstance(line.body, A.Data):
            continue
        n = 0
        for item in line.body.items:
            if item.count is None:
                n += 1
            else:
                try:
                    n += evaluate(item.count, oc.resolve_const, oc.char_bytes).bits
                except Exception:
                    n += 1
        counts[key(line.label.name)] = max(n, 1)
    return counts


def _con_text(c, oc, value, defined: set, names) -> str:
    """A constant's Python value: its Spin expression if it only uses numbers and constants
    defined above it in the class, else the folded value."""
    from .exprs import number_text
    bits = value.bits
    v = bits - (1 << 32) if bits & 0x80000000 else bits
    if isinstance(c, A.ConDef) and not value.is_float:
        e = c.value
        if isinstance(e, A.Number):
            return number_text(e)
        simple = _simple_con_expr(e, defined, names)
        if simple is not None and _python_value(e, oc) == v:      # no 32-bit wrap-around in it
            return simple
    return str(v)


def _python_value(e, oc):
    """What Python computes for a simple constant expression (None if it cannot)."""
    if isinstance(e, A.Number):
        return e.value - (1 << 32) if e.value & 0x80000000 else e.value
    if isinstance(e, A.NameRef):
        c = oc.const(e.name)
        return None if c is None else (c.bits - (1 << 32) if c.bits & 0x80000000 else c.bits)
    if isinstance(e, A.Paren):
        return _python_value(e.expr, oc)
    left, right = _python_value(e.left, oc), _python_value(e.right, oc)
    if left is None or right is None:
        return None
    return {"+": left + right, "-": left - right, "*": left * right}[e.op]


def _con_source(spin, c) -> str:
    """The Spin text of a constant's value (``xtal1 + pll16x``)."""
    if not isinstance(c, A.ConDef):
        return ""
    src = spin.source.line(c.pos.line) or ""
    rest = src[c.pos.col - 1:].split("'")[0].split("{")[0]
    _, _, value = rest.partition("=")
    return value.split(",")[0].strip()


def _simple_con_expr(e, defined: set, names):
    if isinstance(e, A.Number):
        from .exprs import number_text
        return number_text(e) if e.value < 0x80000000 else None
    if isinstance(e, A.NameRef) and e.index is None and key(e.name) in defined:
        return names.attr(e.name)
    if isinstance(e, A.Paren):
        inner = _simple_con_expr(e.expr, defined, names)
        return f"({inner})" if inner else None
    if isinstance(e, A.Binary) and e.op in ("+", "-", "*"):
        left, right = _simple_con_expr(e.left, defined, names), _simple_con_expr(e.right, defined, names)
        if left and right:
            return f"{left} {e.op} {right}"
    return None


def _file_doc(spin) -> list:
    """The ``''`` comment lines at the top of a file (before its first code)."""
    out = []
    n = 1
    while True:
        src = spin.source.line(n)
        if src is None or (src.strip() and not src.lstrip().startswith(("'", "{"))):
            break
        for c in spin.comments_at(n):
            if c.kind in ("''", "{{"):
                for part in c.text.splitlines() or [""]:
                    part = part.strip()
                    out.append("" if set(part) <= {"="} else part)
        n += 1
    while out and not out[-1]:
        out.pop()
    while out and not out[0]:
        out.pop(0)
    return out


def _summary(doc: list, path: str) -> str:
    """One line about the object: the file header's "Purpose" line, else its first line."""
    for d in doc:
        if d.lower().startswith("purpose"):
            return d.split(" ", 1)[-1].lstrip(". ").strip() or d
    return doc[0] if doc else f"The Spin object {os.path.basename(path)}."


def _method_doc(spin, m) -> list:
    out = []
    n = m.pos.line + 1
    while True:
        src = (spin.source.line(n) or "").strip()
        cs = spin.comments_at(n)
        if not src and not out:
            n += 1
            if n > m.pos.line + 3:
                break
            continue
        if cs and all(c.kind == "''" for c in cs) and src.startswith("''"):
            out.append(cs[0].text.strip())
            n += 1
            continue
        break
    return out


def _mentions(body, names: set, result_ref=False) -> bool:
    for n in A.walk(body):
        if result_ref and isinstance(n, A.ResultRef):
            return True
        if isinstance(n, A.NameRef) and key(n.name) in names:
            return True
        if isinstance(n, (A.Return, A.Abort)) and n.value is None:
            return True
    return False


def _values_used(units) -> frozenset:
    """``(object path, method key)`` of each method whose value a call in the program uses.

    A call statement (``f(x)``, ``\\f(x)``) drops the value, as does starting
    the method in a cog (``cognew(f(x), @stack)``); any other call uses it.
    """
    used = set()
    for u in units:
        methods = {key(m.name) for m in u.spin.methods}
        children = {key(decl.name): child.path for decl, child in u.children}
        dropped = set()
        for n in A.walk([m.body for m in u.spin.methods]):
            if isinstance(n, A.ExprStmt):
                dropped.add(id(n.expr.call if isinstance(n.expr, A.AbortTrap) else n.expr))
            elif isinstance(n, A.Builtin) and n.name in ("cognew", "coginit") and n.args:
                dropped.update(id(a.expr if isinstance(a, A.Paren) else a) for a in n.args)
            elif id(n) in dropped:
                continue
            elif isinstance(n, A.Call) or (isinstance(n, A.NameRef) and key(n.name) in methods):
                used.add((u.path, key(n.name)))
            elif isinstance(n, A.ObjCall) and key(n.obj) in children:
                used.add((children[key(n.obj)], key(n.method)))
    return frozenset(used)


def _count_mentions(body, name: str) -> int:
    return sum(1 for n in A.walk(body) if isinstance(n, A.NameRef) and key(n.name) == name)


def _cog_methods(unit) -> set:
    """Keys of the methods of ``unit`` that a ``cognew``/``coginit`` starts a cog in."""
    found = set()
    for m in unit.spin.methods:
        for n in A.walk(m.body):
            if isinstance(n, A.Builtin) and n.name.lower() in ("cognew", "coginit") and n.args:
                first = n.args[0] if n.name.lower() == "cognew" else n.args[min(1, len(n.args) - 1)]
                first = first.expr if isinstance(first, A.Paren) else first
                if isinstance(first, (A.Call, A.NameRef)):
                    found.add(key(first.name))
    return found


def _needs_init(m, name: str) -> bool:
    """Does local ``name`` need ``= 0`` at the start (is it possibly read before the first assignment)?"""
    for st in m.body:
        if isinstance(st, A.RepeatFrom) and isinstance(st.var, A.NameRef) and key(st.var.name) == key(name) \
                and not _count_mentions([st.start, st.stop] + ([st.step] if st.step else []), key(name)):
            return False
        if isinstance(st, A.ExprStmt) and isinstance(st.expr, A.Assign) and st.expr.op == ":=" \
                and isinstance(st.expr.target, A.NameRef) and key(st.expr.target.name) == key(name) \
                and _count_mentions([st.expr.value], key(name)) == 0:
            return False
        if _count_mentions([st], key(name)):
            return True
    return False


def translate_program(src_path: str, include_dirs=()):
    """Translate the program rooted at ``src_path``.

    Returns:
        ``(modules, compiled)``: one :class:`ModuleText` per object (the top
        object first) and the :class:`~spinemu.compiler.CompiledProgram`.

    Raises:
        ParseError, CompileError: the program does not compile.
        TranslateError: it uses a construct the translator does not handle.
    """
    top = load_program(os.fspath(src_path), include_dirs)
    compiled = _compile_unit(top)
    by_unit = {id(c.unit): c for c in compiled.objects}
    units, seen = [], set()

    def visit(unit):
        if unit.path in seen:
            return
        seen.add(unit.path)
        units.append(unit)
        for _decl, child in unit.children:
            visit(child)

    visit(top)
    modules = {}
    for u in units:
        other = modules.setdefault(module_name(u.path), u.path)
        if other != u.path:
            raise TranslateError(f"'{os.path.basename(other)}' and '{os.path.basename(u.path)}' would both "
                                 f"become the Python module '{module_name(u.path)}.py'; rename one of them",
                                 path=u.path)
    classes, used = {}, set()
    for u in units:
        name = class_name(u.path)
        while name in used:
            name += "_"
        used.add(name)
        classes[u.path] = name
    timing = load_timing()
    values_used = _values_used(units)
    modules = [ObjectTranslator(u, _cobj_for(u, by_unit, compiled), timing, classes, values_used).translate()
               for u in units]
    return modules, compiled


def _cobj_for(unit, by_unit, compiled):
    c = by_unit.get(id(unit))
    if c is not None:
        return c
    for obj in compiled.objects:
        if obj.unit.path == unit.path:
            return obj
    raise KeyError(unit.path)


assert price  # costs are computed through MethodTranslator
