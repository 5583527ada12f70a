"""Weaving the cycle charges into a translated class, and loading translated modules.

A generated module reads as plain Python; its cycle costs sit in one table
at its end, ``SPIN_CYCLES = {line: (before, after, else)}``.  When a class
first runs (:func:`prepare`), its methods are parsed from the module's own
source, a charge is inserted before or after the statement on each listed
line (``else`` charges go into the ``else:`` of an ``if``, ``while`` or ``for``,
created if missing: a taken branch, a loop's exit), and the methods are
compiled again from that tree, keeping the module's line numbers for
tracebacks.  This is how pytest rewrites ``assert`` statements: the file you
read is the file that runs, plus bookkeeping that does not change what it
computes.

Each ``spin.lookup``-like call gets its row of ``SPIN_LOOKUPS`` (what its
items cost) as a third argument.

A line whose calls start at different stack depths (``SPIN_CALL_DEPTHS``
lists ``(method, depth)`` for it) has each call wrapped as
``__spin_call_at(depth, method, args...)`` so the callee's hub frame lands
where the bytecode interpreter puts it (:func:`spinemu.translate.spin.call_at`).
In a statement with several calls, ``(method, depth, cycles)`` also gives what
each call after the first pays as it starts (``spin_pay=cycles``): the
bytecodes since the call before it.

Each charge is ``(aligned, extra)``: ``aligned`` cycles charged with a
bytecode fetch's hub alignment (:func:`spinemu.translate.runtime.tick`),
``extra`` cycles without (:func:`~spinemu.translate.runtime.add`).  Before
a woven method is compiled, :func:`spinemu.translate.inline.inline_method`
writes the statement-level charges and the hub variables' accesses out as
local arithmetic (the Python engine's hot path).
"""
from __future__ import annotations

import ast
import importlib.util
import inspect
import os
import sys

from . import runtime, spin
from .inline import inline_method, install

__all__ = ["prepare", "load_package"]

_TICK, _TICK_AT, _TICK_READ, _ADD = "__spin_tick", "__spin_tick_at", "__spin_tick_read", "__spin_add"
_CALL_AT = "__spin_call_at"
_THEN = "__spin_then"
_PAY_CALL = "__spin_pay_call"
#: spin helpers that pay cycles depending on values (costs.PAID_HELPERS)
_PAID_HELPERS = frozenset(("div", "mod", "encode", "strsize", "strcomp", "bytefill", "wordfill", "longfill",
                           "bytemove", "wordmove", "longmove"))


def _call(name, args, anchor):
    call = ast.Expr(ast.Call(ast.Name(name, ast.Load()), [ast.Constant(a) for a in args], []))
    return ast.fix_missing_locations(ast.copy_location(call, anchor))


def _charge_stmts(charge, anchor) -> list:
    if charge is None:
        return []
    aligned, extra = charge[0], charge[1]
    out = []
    if extra:                   # belongs to the last bytecode already paid for: first
        out.append(_call(_ADD, (extra,), anchor))
    if len(charge) > 3:
        access = charge[2][0] if isinstance(charge[2], (tuple, list)) else charge[2]
        out.append(_call(_TICK_READ, (aligned, access, charge[3]), anchor))
    elif aligned is not None:
        if len(charge) > 2:
            access = tuple(charge[2])[:2] if isinstance(charge[2], (tuple, list)) else (charge[2],)
            out.append(_call(_TICK_AT, (aligned, *access), anchor))
        else:
            out.append(_call(_TICK, (aligned,), anchor))
    return out


def _calls_in_order(stmt, lambdas: bool = False) -> list:
    """The calls in a statement's own expressions (not its body), in the order Python makes them
    (``lambdas``: also those in a lookup item's lambda, which runs when the lookup reaches it)."""
    out = []

    def visit(n):
        if isinstance(n, ast.stmt) and n is not stmt or isinstance(n, ast.Lambda) and not lambdas:
            return                      # a nested body's statements are lines of their own; a lookup item's
            #                             lambda runs (and pays) on its own
        children = list(ast.iter_child_nodes(n))
        if isinstance(n, ast.Assign):   # the value runs before the targets' indexes
            children = [n.value] + n.targets
        for c in children:
            visit(c)
        if isinstance(n, ast.Call):
            out.append(n)

    visit(stmt)
    return out


def _method_name(call):
    f = call.func
    if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and f.value.id == "spin" \
            and f.attr in _PAID_HELPERS:
        return "@" + f.attr             # a helper that pays value-dependent cycles (spin.div ...)
    if isinstance(f, ast.Attribute) and f.attr == "trap" and call.args and isinstance(call.args[0], ast.Attribute):
        return call.args[0].attr        # spin.trap(self.f, x): Spin's \f(x)
    return f.attr if isinstance(f, ast.Attribute) else None


def _wrap_calls(stmt, depths: list, k: int = 0) -> int:
    """``f(args)`` -> ``__spin_call_at(depth, f, args)`` for the calls of a line whose calls start at different depths.

    ``depths`` lists ``(method, depth)`` in the order the Spin calls run,
    which is the order Python makes them; each call takes the next entry of
    its name from ``k`` on.  Returns where the next line of the statement
    (values hoisted before it) goes on.
    """
    for call in _calls_in_order(stmt):
        name = _method_name(call)
        j = next((j for j in range(k, len(depths)) if depths[j][0] == name), None)
        if j is None:
            continue
        pay = depths[j][2] if len(depths[j]) > 2 else None      # cycles since the event before
        if name.startswith("@"):
            if pay is not None:
                call.args = [ast.copy_location(ast.Constant(pay), call), call.func] + call.args
                call.func = ast.copy_location(ast.Name(_PAY_CALL, ast.Load()), call)
            k = j + 1
            continue
        call.args = [ast.copy_location(ast.Constant(depths[j][1]), call), call.func] + call.args
        call.func = ast.copy_location(ast.Name(_CALL_AT, ast.Load()), call)
        if pay is not None:
            kw = ast.keyword("spin_pay", ast.copy_location(ast.Constant(pay), call))
            call.keywords.append(ast.copy_location(kw, call))
        k = j + 1
    return k


def _add_lookup_costs(stmt, rows: list) -> None:
    """``spin.lookup(v, items)`` -> ``spin.lookup(v, items, costs)``: each lookup of the line gets its row of
    ``SPIN_LOOKUPS`` (listed from the left, by where each call starts)."""
    calls = [c for c in _calls_in_order(stmt, lambdas=True) if isinstance(c.func, ast.Attribute)
             and c.func.attr in _LOOKUPS and isinstance(c.func.value, ast.Name) and c.func.value.id == "spin"]
    calls.sort(key=lambda c: c.col_offset)
    for call, row in zip(calls, rows):
        call.args.append(ast.copy_location(ast.Constant(_frozen(row)), call))


def _frozen(row):
    return tuple(_frozen(x) for x in row) if isinstance(row, (list, tuple)) else row


_LOOKUPS = frozenset(("lookup", "lookupz", "lookdown", "lookdownz"))


def _weave_body(stmts: list, table: dict, depths: dict, lookups: dict) -> list:
    out = []
    calls = None                    # (line, its depths, how many its calls used)
    for k, s in enumerate(stmts):
        for field in ("body", "orelse", "finalbody"):
            if isinstance(getattr(s, field, None), list) and not isinstance(s, ast.FunctionDef):
                setattr(s, field, _weave_body(getattr(s, field), table, depths, lookups))
        if isinstance(s, ast.FunctionDef):
            # a lookup item's or case value's local function: its lines are paid with the item, but a
            # lookup in it pays its own items as it reaches them
            for inner in ast.walk(s):
                if isinstance(inner, ast.stmt) and inner is not s and inner.lineno in lookups:
                    _add_lookup_costs(inner, lookups[inner.lineno])
        if isinstance(s, ast.Try):
            for h in s.handlers:
                h.body = _weave_body(h.body, table, depths, lookups)
        listed = depths.get(s.lineno)
        if listed.__class__ is list:
            # the next line of one statement (a value hoisted before it) goes on where this one stopped
            going_on = calls is not None and calls[0] == s.lineno - 1 and calls[1] == listed \
                and calls[2] < len(listed)
            calls = (s.lineno, listed, _wrap_calls(s, listed, calls[2] if going_on else 0))
        if s.lineno in lookups:
            _add_lookup_costs(s, lookups[s.lineno])
        row = table.get(s.lineno)
        if row is None:
            out.append(s)
            continue
        before, after, other = row[:3]
        post = row[4] if len(row) > 4 else None
        alternatives = None
        if len(row) > 3 and isinstance(s, ast.If):
            if isinstance(s.test, ast.BoolOp) and isinstance(s.test.op, ast.Or):
                alternatives = s.test.values
            elif len(row[3]) == 1:
                alternatives = [s.test]
        if alternatives is not None and len(alternatives) == len(row[3]):
            # one charge before each alternative: ``if tick(a) or x == 1 or tick(b) or x == 2:``; a value
            # that calls pays the rest once it is computed: ``tick(a) or then(b, x == self.f())``
            values = []
            for charge, value in zip(row[3], alternatives):
                if charge and isinstance(charge[0], tuple):
                    charge, computed = charge
                    value = ast.copy_location(ast.Call(ast.Name(_THEN, ast.Load()),
                                                       [ast.Constant(computed[0]), value], []), value)
                values += [c.value for c in _charge_stmts(charge, s)] + [value]
            test = ast.BoolOp(ast.Or(), values) if len(values) > 1 else values[0]
            s.test = ast.fix_missing_locations(ast.copy_location(test, s.test))
        elif len(row) > 3 and isinstance(s, ast.While):
            # charged each time the loop's condition is evaluated: ``while tick(...) or cond:``
            charge = _charge_stmts(row[3], s)
            s.test = ast.copy_location(ast.BoolOp(ast.Or(), [c.value for c in charge] + [s.test]), s.test)
        out.extend(_charge_stmts(before, s))
        if post is not None and isinstance(s, (ast.Return, ast.Raise, ast.Assign, ast.AugAssign)) and \
                getattr(s, "exc" if isinstance(s, ast.Raise) else "value", None) is not None:
            # paid once the value is computed, before it is stored or returned:
            # ``value = ...; tick(); x = value`` (a store after the run's end does not happen)
            field = "exc" if isinstance(s, ast.Raise) else "value"
            keep = ast.copy_location(ast.Assign([ast.Name("__spin_value", ast.Store())], getattr(s, field)), s)
            out.append(ast.fix_missing_locations(keep))
            out.extend(_charge_stmts(post, s))
            setattr(s, field, ast.copy_location(ast.Name("__spin_value", ast.Load()), s))
            out.append(ast.fix_missing_locations(s))
            out.extend(_charge_stmts(after, s))
            continue
        if before is not None and len(before) > 2 and isinstance(before[2], (tuple, list)) \
                and len(before[2]) > 2 and isinstance(s, (ast.Assign, ast.AugAssign)) and _run_ends_here(stmts, k, table):
            # a store that ends its run (x := a + b, x++, x += n): made this many cycles after the run's first
            # fetch; when another cog's access comes first, the store waits for its moment (inline.py)
            s.spin_store_at = before[2][2]
        out.append(s)
        if other is not None and isinstance(s, (ast.If, ast.While, ast.For)):
            s.orelse = _charge_stmts(other, s) + s.orelse
        out.extend(_charge_stmts(post, s))
        out.extend(_charge_stmts(after, s))
    return out


def _run_ends_here(stmts: list, k: int, table: dict) -> bool:
    """Does the run charged before ``stmts[k]`` end with it (the next statement, if any, pays its own)?"""
    if k + 1 == len(stmts):
        return True
    row = table.get(stmts[k + 1].lineno)
    return row is not None and row[0] is not None


def _weave_function(fn: ast.FunctionDef, table: dict, depths: dict, lookups: dict) -> ast.FunctionDef:
    fn.body = _weave_body(fn.body, table, depths, lookups)
    row = table.get(fn.lineno)
    if row is not None and row[1] is not None:
        fn.body.extend(_charge_stmts(row[1], fn.body[-1]))
    return fn


def prepare(cls) -> None:
    """Weave the cycle charges into ``cls`` (a translated class) and its child classes, once."""
    if cls.__dict__.get("_spin_woven"):
        return
    module = sys.modules[cls.__module__]
    table = getattr(module, "SPIN_CYCLES", {})
    source = inspect.getsource(module)
    tree = ast.parse(source, filename=module.__file__)
    module.__dict__[_TICK] = runtime.tick
    module.__dict__[_TICK_AT] = runtime.tick_at
    module.__dict__[_TICK_READ] = runtime.tick_read
    module.__dict__[_ADD] = runtime.add
    module.__dict__[_CALL_AT] = spin.call_at
    module.__dict__[_THEN] = runtime.then
    module.__dict__[_PAY_CALL] = runtime.pay_call
    install(module.__dict__)
    depths = getattr(module, "SPIN_CALL_DEPTHS", {})
    lookups = getattr(module, "SPIN_LOOKUPS", {})
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == cls.__name__:
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    fn = inline_method(_weave_function(item, table, depths, lookups), cls)
                    code = compile(ast.Module([fn], []), module.__file__, "exec")
                    ns: dict = {}
                    exec(code, module.__dict__, ns)    # defines the woven function (no user strings)
                    setattr(cls, item.name, ns[item.name])
    cls._spin_woven = True
    for value in vars(cls).values():
        if isinstance(value, spin.Child):
            prepare(value.cls)


_loaded = 0


def load_package(out_dir):
    """Import the generated modules in ``out_dir`` as a fresh package; returns the package module.

    Its ``TOP`` is the top object's class; each module is importable as
    ``package.<module>`` (``importlib.import_module(package.__name__ + ".stepper")``).
    """
    out_dir = os.fspath(out_dir)
    global _loaded
    _loaded += 1
    name = f"spinemu_translated_{_loaded}"
    init = os.path.join(out_dir, "__init__.py")
    spec = importlib.util.spec_from_file_location(name, init, submodule_search_locations=[out_dir])
    package = importlib.util.module_from_spec(spec)
    sys.modules[name] = package
    spec.loader.exec_module(package)
    return package


def import_module(package, module: str):
    """Import ``package.module`` (a generated module)."""
    return importlib.import_module(f"{package.__name__}.{module}")
