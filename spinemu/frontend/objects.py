"""Loading a program's object tree and folding each object's CON section.

An object is a .spin file.  ``OBJ`` lines name child objects; a name without
an extension gets ``.spin``; the file is looked up next to the file that
names it, then in the include directories (OpenSpin's ``-L``), ``SPINEMU_PATH``
and the installed tools' library folders, exactly first and then in any
letter case (with a warning): see search.py.  Each file is read and parsed
once, however many times it is used.

CON values (Propeller Manual, CON): ``name = expr`` and enumerations
(``#start``, ``name``, ``name[skip]``).  The counter starts at 0 in each CON
section and continues across its lines; definitions may refer to children's
constants (``obj#NAME``) and to constants defined further down, as far as
OpenSpin's two passes over the lines allow: ``A = B`` before ``B = 1`` works,
``A = B`` before ``B = C`` before ``C = 1`` does not, and neither does ``A = B``
before ``B = obj#C`` (the first pass does not see the children's constants).
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Optional

from ..diagnostics import CompileError, Diagnostic, ParseError
from .. import messages as msg
from .ast import ConEnumName, ConEnumStart, NameRef, ObjConst, SpinFile, key
from .constants import Const, ConstError, NotConstant, evaluate
from .obj_shadow import shadowed_object_hints
from .parser import parse_text
from .search import ENV_VAR, AmbiguousName, SearchPath, standard_object
from .source import read_source

__all__ = ["ObjectUnit", "load_program", "resolve_object_file", "ConstantTable", "child_constant",
           "not_found_message"]


@dataclass
class ConstantTable:
    """An object's constants: lower-case name -> (Const, definition node)."""

    values: dict = field(default_factory=dict)

    def get(self, name: str) -> Optional[Const]:
        entry = self.values.get(key(name))
        return entry[0] if entry else None


@dataclass
class ObjectUnit:
    """One object file: its AST, its children (per OBJ line) and its constants."""

    path: str
    spin: SpinFile
    children: list = field(default_factory=list)   # [(ObjDecl, ObjectUnit)]
    constants: ConstantTable = field(default_factory=ConstantTable)
    child_by_name: dict = field(default_factory=dict)
    hints: list = field(default_factory=list)       # Diagnostics about its OBJ lines (obj_shadow.py)
    #: where this program's OBJ and ``file`` names are looked up (shared by its units);
    #: its ``warnings`` collect the program's warnings
    search: SearchPath = field(default_factory=lambda: SearchPath(environ={}, standard=False))

    @property
    def name(self) -> str:
        return os.path.splitext(os.path.basename(self.path))[0]


def resolve_object_file(name: str, from_dir: str, include_dirs=()) -> Optional[str]:
    """The path of object file ``name`` (``.spin`` added if missing) in ``from_dir`` or ``include_dirs``, or ``None``.

    Only exact names, no environment, no installed libraries: :class:`SearchPath` does the full lookup.
    """
    try:
        found = SearchPath(list(include_dirs), environ={}, standard=False).find(_spin_name(name), from_dir)
    except AmbiguousName:
        return None
    return found.path if found and found.warning is None else None


def _spin_name(name: str) -> str:
    return name if name.lower().endswith(".spin") else name + ".spin"


def not_found_message(template: str, name: str, search: SearchPath, from_dir: str) -> str:
    """The "cannot find" message: every folder looked in and, for a Propeller Tool object, where it comes from."""
    text = template.format(name=name, where=search.describe(from_dir))
    standard = standard_object(name)
    if standard is not None:
        text += "; " + msg.STANDARD_OBJECT_HINT.format(name=standard, var=ENV_VAR)
    return text


class _Loader:
    def __init__(self, search: SearchPath, defines=()):
        self.search = search
        self.defines = tuple(defines)
        self.units: dict[str, ObjectUnit] = {}
        self.errors: list[Diagnostic] = []
        self.syntax_errors = 0
        self.stack: list[str] = []

    def load(self, path: str, source=None) -> Optional[ObjectUnit]:
        real = os.path.realpath(path)
        if real in self.units:
            return self.units[real]
        if source is None:
            source = read_source(path)
            self.search.files[path] = source.digest      # (what was compiled, even if the file changes now)
        spin, errors = parse_text(source, self.defines)
        self.errors.extend(errors)
        self.syntax_errors += len(errors)
        unit = ObjectUnit(path, spin, search=self.search)
        self.units[real] = unit
        self.stack.append(real)
        here = os.path.dirname(os.path.abspath(path))
        seen: dict = {}
        for decl in spin.objs:
            if key(decl.name) in seen:
                self._error(msg.DUPLICATE.format(name=decl.name, line=seen[key(decl.name)]), decl, spin)
                continue
            seen[key(decl.name)] = decl.pos.line
            child_path = self._find(decl, here, spin)
            if child_path is None:
                continue
            if os.path.realpath(child_path) in self.stack:
                self._error(msg.OBJECT_RECURSION.format(name=decl.filename), decl, spin)
                continue
            libraries = [f.path for f in self.search.folders(here)[1:]]
            unit.hints.extend(shadowed_object_hints(decl, child_path, here, libraries, spin.source))
            # (the hint compares the file found with its namesakes in every library folder)
            self.search.dirs.update(libraries)
            for d in libraries:
                self.search.files.setdefault(os.path.join(d, os.path.basename(child_path)), None)
            child = self.load(child_path)
            if child is not None:
                unit.children.append((decl, child))
                unit.child_by_name.setdefault(key(decl.name), (decl, child))
        self.stack.pop()
        _fold_constants(unit, self.errors)
        return unit

    def _find(self, decl, here: str, spin: SpinFile) -> Optional[str]:
        """The file of OBJ line ``decl``, reporting it missing or ambiguous, warning about its case."""
        try:
            found = self.search.find(_spin_name(decl.filename), here)
        except AmbiguousName as exc:
            self._error(msg.AMBIGUOUS_FILE.format(name=decl.filename, folder=exc.folder,
                                                  candidates=", ".join(exc.candidates)), decl, spin)
            return None
        if found is None:
            self._error(not_found_message(msg.OBJECT_NOT_FOUND, decl.filename, self.search, here), decl, spin)
            return None
        if found.warning:
            self.search.warnings.append(self._diagnostic(found.warning, decl, spin, "warning"))
        return found.path

    def _diagnostic(self, text: str, node, spin: SpinFile, severity: str) -> Diagnostic:
        pos = node.pos
        return Diagnostic(text, pos.path, pos.line, pos.col, spin.source.line(pos.line), severity)

    def _error(self, text: str, node, spin: SpinFile) -> None:
        pos = node.pos
        self.errors.append(Diagnostic(text, pos.path, pos.line, pos.col, spin.source.line(pos.line)))


def child_constant(unit: ObjectUnit, node: ObjConst):
    """The value of ``obj#NAME`` (``node``) in ``unit``; ConstError if the object or the constant is unknown."""
    child = unit.child_by_name.get(key(node.obj))
    if child is None:
        raise ConstError(msg.UNDEFINED.format(name=node.obj), node)
    value = child[1].constants.get(node.name)
    if value is None:
        raise ConstError(msg.UNKNOWN_CONSTANT_IN_OBJECT.format(obj=node.obj, name=node.name), node)
    return value


def _fold_constants(unit: ObjectUnit, errors: list) -> None:
    """Evaluate the CON section of ``unit`` (its children are already folded)."""
    spin = unit.spin
    table = unit.constants.values
    pending_undefined: dict = {}

    def resolve(node):
        if isinstance(node, NameRef) and node.index is None:
            entry = table.get(key(node.name))
            if entry is not None:
                return entry[0]
            pending_undefined.setdefault(id(node), node)
            raise NotConstant(node)
        if isinstance(node, ObjConst):
            if first_pass[0]:
                raise NotConstant(node)     # OpenSpin's first pass does not see children's constants
            return child_constant(unit, node)
        raise NotConstant(node)

    char_bytes = spin.source.string_bytes
    # which CON section each item is in: enumerations restart at 0 per section
    items = _con_items_by_section(spin)
    done: set = set()
    reported: set = set()
    # OpenSpin reads the CON lines twice, in order: a constant may use one defined further
    # down only if that one is known by the end of the first pass
    first_pass = [True]
    for pass_no in range(2):
        first_pass[0] = pass_no == 0
        pending_undefined.clear()
        counter: Optional[int] = 0
        section = None
        for sec, item in items:
            if sec != section:
                section, counter = sec, 0
            if isinstance(item, ConEnumStart):
                try:
                    value = evaluate(item.value, resolve, char_bytes)
                    if value.is_float:
                        raise ConstError(msg.INTEGER_AND_FLOAT, item.value)
                    counter = value.bits
                except NotConstant:
                    counter = None
                except ConstError as exc:
                    _report(errors, spin, exc.node, exc.message, reported)
                    counter = None
                continue
            if isinstance(item, ConEnumName):
                step = 1
                if item.skip is not None:
                    try:
                        step = evaluate(item.skip, resolve, char_bytes).bits
                    except NotConstant:
                        step = None
                    except ConstError as exc:
                        _report(errors, spin, exc.node, exc.message, reported)
                        step = None
                if id(item) not in done and counter is not None:
                    _define(table, item.name, Const(counter & 0xFFFFFFFF), item, errors, spin, reported,
                            not first_pass[0])
                    done.add(id(item))
                counter = None if counter is None or step is None else counter + step
                continue
            if id(item) in done:
                continue
            try:
                value = evaluate(item.value, resolve, char_bytes)
            except NotConstant:
                continue
            except ConstError as exc:
                _report(errors, spin, exc.node, exc.message, reported)
                done.add(id(item))
                continue
            _define(table, item.name, value, item, errors, spin, reported, not first_pass[0])
            done.add(id(item))
    for node in pending_undefined.values():
        if key(node.name) in table:
            text = msg.CONSTANT_TOO_LATE.format(name=node.name)
        else:
            text = msg.UNDEFINED.format(name=node.name)
        _report(errors, spin, node, text, reported)


def _con_items_by_section(spin: SpinFile) -> list:
    """``(section number, item)`` for every CON item, in source order."""
    starts = [line for kind, line in spin.sections if kind == "CON"]
    out = []
    for item in spin.cons:
        sec = 0
        for i, line in enumerate(starts):
            if item.pos.line >= line:
                sec = i
        out.append((sec, item))
    return out


def _define(table, name, value, node, errors, spin, reported, second_pass: bool = False) -> bool:
    """Enter constant ``name``; a name defined twice is an error, except (as in OpenSpin) when the
    second pass meets it again with the value it already has (``cols = vga#cols`` on two lines)."""
    k = key(name)
    if k in table:
        if second_pass and table[k][0] == value:
            return False
        prev = table[k][1]
        _report(errors, spin, node, msg.DUPLICATE.format(name=name, line=prev.pos.line), reported)
        return False
    table[k] = (value, node)
    return True


def _report(errors, spin, node, text, reported) -> None:
    pos = node.pos
    ident = (pos.line, pos.col, text)
    if ident in reported:
        return
    reported.add(ident)
    errors.append(Diagnostic(text, pos.path, pos.line, pos.col, spin.source.line(pos.line)))


def load_program(path: str, include_dirs=(), source=None, defines=(), search: Optional[SearchPath] = None) -> ObjectUnit:
    """Load, parse and fold the constants of the object tree rooted at ``path``.

    Args:
        source: the top file's SourceText, if it is not to be read from ``path``
            (``path`` still decides where its OBJ files are looked for).
        search: where OBJ and ``file`` names are looked up; by default ``include_dirs``,
            then ``SPINEMU_PATH`` and the installed tools' library folders.  Warnings
            (names found in another letter case) end up in ``unit.search.warnings``.

    Raises:
        ParseError: syntax errors (of every file).
        CompileError: missing object files, bad or unknown constants.
    """
    loader = _Loader(search if search is not None else SearchPath(list(include_dirs)), defines)
    unit = loader.load(path, source)
    if loader.errors:
        cls = ParseError if loader.syntax_errors else CompileError
        raise cls(diagnostics=loader.errors)
    return unit
