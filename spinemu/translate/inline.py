"""Inlining the runtime's hot helpers into a woven method (the Python engine's speed).

:mod:`spinemu.translate.weave` inserts each statement's cycle charge as a
call (``__spin_tick(276)``); the generated module the user reads never shows
them.  This pass, run on the woven tree before it is compiled, replaces the
hottest of those calls and of the hub accessors with the same arithmetic
written out in the method, on locals bound once at its start:

* a charge statement ``__spin_tick(k)`` / ``__spin_tick_at(k, access[, last])``
  / ``__spin_add(k)`` becomes the lines of :func:`spinemu.translate.runtime.tick`
  / ``tick_at`` / ``add``, with the running cog and its hub phase in locals
  (a method runs in one cog's greenlet from start to end); the hand-over to
  the scheduler stays where it was, at the same cycle, through
  :func:`~spinemu.translate.runtime.pause_tick` / ``pause_tick_at``;
* a charge after only *neutral* statements (:func:`_neutral`: values and hub
  variables, no calls but pure helpers, no ``cog``, no jumps) knows its fetch
  alignment as a constant, and takes over the previous charge's store of the
  cycle counter (done only on a hand-over, with the value it had); a loop
  body's first charge too, when both ways in leave the same alignment
  (:func:`_loop_entry`);
* ``self.x`` of a VAR/DAT variable and ``self.a[i]`` of an array (long, word,
  byte) read and write the hub's views directly, the address worked out as
  :mod:`spinemu.translate.spin`'s properties and array views do (a store at or
  past $8000 is dropped, as there);
* ``x = spin.mod(e, C)`` / ``spin.div`` by a positive constant: the short path
  of :func:`spinemu.translate.spin.mod` written out.

Python evaluates everything in the same order as before (values before
stores, an augmented target read before its value), so what a method
computes and when it pays is unchanged; only the calls go.
"""
from __future__ import annotations

import ast

from . import runtime, spin

__all__ = ["inline_method", "install"]

_COG, _PHASE, _T, _RT = "__spin_c", "__spin_p", "__spin_t", "__spin_RT"
_L, _LS = "__spin_L", "__spin_Ls"
_PAUSE, _PAUSE_AT = "__spin_pause_tick", "__spin_pause_tick_at"
_ADDR, _VALUE = "__spin_a", "__spin_v"
_DEFER = "__spin_defer"
_DIVIDEND, _DX = "__spin_m", "__spin_dx"


def _name(n: str, store: bool = False) -> ast.Name:
    return ast.Name(n, ast.Store() if store else ast.Load())


def _parse(src: str) -> list:
    return ast.parse(src).body


# ----------------------------------------------------------------------------- cycle charges
def _charge(stmt):
    """``(helper, constant args)`` if ``stmt`` is a woven charge statement, else None."""
    if not (isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call)):
        return None
    call = stmt.value
    if not isinstance(call.func, ast.Name) or call.keywords:
        return None
    if call.func.id not in ("__spin_tick", "__spin_tick_at", "__spin_add"):
        return None
    if not all(isinstance(a, ast.Constant) and isinstance(a.value, int) for a in call.args):
        return None
    return call.func.id, [a.value for a in call.args]


def _charge_lines(helper: str, args: list) -> list:
    """The lines of ``runtime.tick``/``tick_at``/``add`` for constant arguments."""
    c, t = _COG, _T
    if helper == "__spin_add":
        return _parse(f"{c}.t += {args[0]}")
    align = f"{t} = {c}.t + 12\n{t} += ({_PHASE} - {t}) & 15\n"
    if helper == "__spin_tick":
        k, = args
        return _parse(f"{align}if {t} >= {_RT}.limit:\n    {_PAUSE}({t})\n{c}.t = {t} + {k}")
    k, access, last = (list(args) + [-1])[:3]
    return _parse(f"{align}if {t} + {access} >= {_RT}.limit or {t} + {last} >= {_RT}.final:\n"
                  f"    {_PAUSE_AT}({t}, {access})\n{c}.t = {t} + {k}")


# ----------------------------------------------------------------------------- hub variables
# bytes per element -> (local read view, local write view, RT's views, address shift, store mask)
_VIEWS = {4: (_LS, _L, "Ls", "L", 2, 0xFFFFFFFF),
          2: ("__spin_W", "__spin_W", "W", "W", 1, 0xFFFF),
          1: ("__spin_B", "__spin_B", "mem", "mem", 0, 0xFF)}


def _hub_var(cls, name: str):
    """``('scalar' | 'array', descriptor)`` if ``cls.name`` is a VAR/DAT variable, else None."""
    for klass in cls.__mro__:
        if name in klass.__dict__:
            d = klass.__dict__[name]
            if isinstance(d, spin._Scalar) and d.mem.size in _VIEWS:
                return "scalar", d
            if isinstance(d, spin._Elements) and d.mem.size in _VIEWS:
                return "array", d
            return None
    return None


def _shifted(e, shift: int):
    return ast.BinOp(e, ast.RShift(), ast.Constant(shift)) if shift else e


class _Hub(ast.NodeTransformer):
    """Rewrites the VAR/DAT variables' reads and stores; remembers which locals the method's start must bind."""

    def __init__(self, cls, this: str):
        self.cls, self.this = cls, this
        self.used: dict = {}        # local name -> its binding's source text
        self.views: set = set()     # element sizes whose views the method uses

    def _var(self, node, kind: str):
        """``(local, size)``: the local holding ``self.x``'s element index (scalar) or hub address (array), or None."""
        if not (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == self.this):
            return None
        found = _hub_var(self.cls, node.attr)
        if found is None or found[0] != kind:
            return None
        d = found[1]
        size = d.mem.size
        local = f"__spin_{kind[0]}_{node.attr}"
        base = f"{self.this}.{'_pbase' if d.dat else '_vbase'}"
        shift = _VIEWS[size][4]
        self.used[local] = (f"({base} + {d.offset}) >> {shift}" if shift else f"{base} + {d.offset}") \
            if kind == "scalar" else f"{self.this}.{node.attr}.addr"
        self.views.add(size)
        return local, size

    def _address(self, sub):
        """``((addr + (i << shift)) & 0xFFFF, size)`` for array element ``self.a[i]``, or None."""
        found = self._var(sub.value, "array")
        if found is None or isinstance(sub.slice, ast.Slice):
            return None
        local, size = found
        i = self.visit(sub.slice)
        shift = _VIEWS[size][4]
        if shift:
            i = ast.BinOp(i, ast.LShift(), ast.Constant(shift))
        return ast.BinOp(ast.BinOp(_name(local), ast.Add(), i), ast.BitAnd(), ast.Constant(0xFFFF)), size

    def _read(self, size: int, index) -> ast.Subscript:
        return ast.Subscript(_name(_VIEWS[size][0]), index, ast.Load())

    def _store_lines(self, size: int, index: str, limit: int, at=None) -> list:
        """``if index < limit: view[index] = __spin_v & mask``.

        ``at``: the store's moment, cycles after the statement's first fetch
        (weave.py's ``spin_store_at``); when another cog's access comes first,
        the chip makes the store then (:func:`spinemu.translate.runtime.defer_store`).
        """
        view, mask = _VIEWS[size][1], _VIEWS[size][5]
        if at is None:
            return _parse(f"if {index} < {limit}:\n    {view}[{index}] = {_VALUE} & {mask}")
        shift = _VIEWS[size][4]
        return _parse(f"if {index} < {limit}:\n"
                      f"    if {_T} + {at} >= {_RT}.limit:\n"
                      f"        {_DEFER}({shift}, ({index}) << {shift}, {_VALUE} & {mask}, {_T} + {at})\n"
                      f"    else:\n"
                      f"        {view}[{index}] = {_VALUE} & {mask}")

    def visit_Attribute(self, node):
        if isinstance(node.ctx, ast.Load):
            found = self._var(node, "scalar")
            if found is not None:
                return ast.copy_location(self._read(found[1], _name(found[0])), node)
        return self.generic_visit(node)

    def visit_Subscript(self, node):
        if isinstance(node.ctx, ast.Load):
            found = self._address(node)
            if found is not None:
                addr, size = found
                return ast.copy_location(self._read(size, _shifted(addr, _VIEWS[size][4])), node)
        return self.generic_visit(node)

    def _rewrite(self, node, target, value, op=None):
        """The statements for ``target = value`` (``op``: ``target op= value``), or None if ``target`` is not a hub variable."""
        if isinstance(target, ast.Attribute):
            found = self._var(target, "scalar")
            if found is None:
                return None
            local, size = found
            if op is not None:
                value = ast.BinOp(self._read(size, _name(local)), op, value)
            out = [ast.Assign([_name(_VALUE, True)], value)]
            out += self._store_lines(size, local, 0x8000 >> _VIEWS[size][4], getattr(node, "spin_store_at", None))
        elif isinstance(target, ast.Subscript):
            found = self._address(target)
            if found is None:
                return None
            addr, size = found
            shift = _VIEWS[size][4]
            at = ast.Assign([_name(_ADDR, True)], addr)
            if op is not None:          # the element is read before the value is computed
                value = ast.BinOp(self._read(size, _shifted(_name(_ADDR), shift)), op, value)
                out = [at, ast.Assign([_name(_VALUE, True)], value)]
            else:                       # the value is computed before the index
                out = [ast.Assign([_name(_VALUE, True)], value), at]
            index = f"{_ADDR} >> {shift}" if shift else _ADDR
            out += self._store_lines(size, index, 0x8000 >> shift, getattr(node, "spin_store_at", None))
        else:
            return None
        return [ast.fix_missing_locations(ast.copy_location(s, node)) for s in out]

    def visit_Assign(self, node):
        if len(node.targets) == 1:
            value = self.visit(node.value)
            out = self._rewrite(node, node.targets[0], value)
            if out is not None:
                return out
            node.value = value
            node.targets = [self.visit(node.targets[0])]
            return node
        return self.generic_visit(node)

    def visit_AugAssign(self, node):
        out = self._rewrite(node, node.target, self.visit(node.value), node.op)
        return out if out is not None else self.generic_visit(node)


# ----------------------------------------------------------------------------- the pass
# spin helpers that neither charge cycles nor touch the cog (a statement using only these is "neutral")
_PURE = {"wrap", "u32", "flag", "shr", "rol", "ror", "rev", "mul_high", "sqrt", "decode", "sign_extend_byte",
         "sign_extend_word", "random_forward", "random_reverse", "within", "span", "repeat_step"}
_OWN = (_COG, _T, _PHASE)
# what else a neutral statement may hold (nothing that jumps, defines code or suspends)
_PLAIN = (ast.Assign, ast.AugAssign, ast.If, ast.Pass, ast.Constant, ast.Attribute, ast.Subscript, ast.BinOp,
          ast.UnaryOp, ast.BoolOp, ast.Compare, ast.IfExp, ast.Tuple, ast.List, ast.Slice, ast.expr_context,
          ast.operator, ast.unaryop, ast.cmpop, ast.boolop)


def _neutral(stmt) -> bool:
    """Does ``stmt`` leave the cog's cycle counter alone, never hand over and never jump (values and hub memory)?"""
    if not isinstance(stmt, (ast.Assign, ast.AugAssign, ast.If, ast.Pass)):
        return False
    for n in ast.walk(stmt):
        if isinstance(n, ast.Call):
            f = n.func
            pure = (isinstance(f, ast.Name) and f.id == "wrap") or (
                isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and f.value.id == "spin"
                and f.attr in _PURE)
            if not pure or n.keywords:
                return False
        elif isinstance(n, ast.Name):
            if n.id == "cog" or n.id in _OWN:
                return False
        elif not isinstance(n, _PLAIN):
            return False
    return True


def _tick_lines(helper: str, args: list, known, store: bool, entry=None) -> list:
    """A charge written out.  ``known``: the cost of the charge just before it, with only neutral
    statements between (its fetch alignment is then a constant, and its store of the cycle counter
    was left to this one); ``store``: write the counter now (else the next charge does);
    ``entry``: the counter is stored and aligns ``entry`` cycles on (a loop's head, see :func:`_loop_entry`)."""
    c, t = _COG, _T
    catch_up = ""
    if known is not None:
        d = 12 + ((-known - 12) & 15)           # t was aligned, the counter is t + known: t + known + d is aligned
        head = f"{t} += {known + d}\n"
        catch_up = f"    {c}.t = {t} - {d}\n"   # what the counter holds in the bytecode engine at the hand-over
    elif entry is not None:
        head = f"{t} = {c}.t + {entry}\n"
    else:
        head = f"{t} = {c}.t + 12\n{t} += ({_PHASE} - {t}) & 15\n"
    if helper == "__spin_tick":
        k, = args
        src = f"{head}if {t} >= {_RT}.limit:\n{catch_up}    {_PAUSE}({t})\n"
    else:
        k, access, last = (list(args) + [-1])[:3]
        src = (f"{head}if {t} + {access} >= {_RT}.limit or {t} + {last} >= {_RT}.final:\n"
               f"{catch_up}    {_PAUSE_AT}({t}, {access})\n")
    if store:
        src += f"{c}.t = {t} + {k}\n"
    return _parse(src)


def _aligned_cost(charges: list, neutral: list, i: int):
    """The cost of the aligned charge that the statements before index ``i`` end with (only neutral ones after it), or None."""
    while i > 0 and neutral[i - 1]:
        i -= 1
    if i == 0 or charges[i - 1] is None or charges[i - 1][0] == "__spin_add":
        return None
    return charges[i - 1][1][0]


def _loop_entry(loop, charges: list, neutral: list, i: int):
    """For loop statement ``stmts[i]``: how far past the stored counter its body's first fetch aligns, or None.

    Known when both ways into the body (from before the loop, and back from
    its end) come from an aligned charge of costs that leave the same
    alignment, with only neutral statements (and a neutral ``range``/test)
    between, and no ``continue`` jumps back from elsewhere.
    """
    if isinstance(loop, ast.For):
        it = loop.iter
        if not (isinstance(it, ast.Call) and isinstance(it.func, ast.Name) and it.func.id == "range"
                and not it.keywords and _neutral(ast.Assign([loop.target], ast.Tuple(list(it.args), ast.Load())))):
            return None
    elif not (isinstance(loop, ast.While) and _neutral(ast.Assign([ast.Name("_", ast.Store())], loop.test))):
        return None
    if any(isinstance(n, ast.Continue) for n in ast.walk(loop)):
        return None
    body_charges = [_charge(s) for s in loop.body]
    body_neutral = [c is None and _neutral(s) for s, c in zip(loop.body, body_charges)]
    costs = (_aligned_cost(charges, neutral, i), _aligned_cost(body_charges, body_neutral, len(loop.body)))
    if None in costs:
        return None
    d = {12 + ((-k - 12) & 15) for k in costs}
    return d.pop() if len(d) == 1 else None


def _inline_body(stmts: list, entry=None) -> tuple:
    """Charge statements written out in ``stmts`` (and nested bodies); returns (new list, any inlined?).

    ``entry``: the alignment of the first fetch if the list starts a loop's body (:func:`_loop_entry`).
    """
    any_ = False
    charges = [_charge(s) for s in stmts]
    neutral = [c is None and _neutral(s) for s, c in zip(stmts, charges)]
    for i, s in enumerate(stmts):
        for field in ("body", "orelse", "finalbody"):
            body = getattr(s, field, None)
            if isinstance(body, list) and body and isinstance(body[0], ast.stmt) \
                    and not isinstance(s, (ast.FunctionDef, ast.ClassDef)):
                head = _loop_entry(s, charges, neutral, i) if field == "body" else None
                new, hit = _inline_body(body, head)
                setattr(s, field, new)
                any_ |= hit
        if isinstance(s, ast.Try):
            for h in s.handlers:
                h.body, hit = _inline_body(h.body)
                any_ |= hit
    out = []
    known = None            # the cost since the last aligned fetch (its counter store still to do), or None
    for i, (s, found) in enumerate(zip(stmts, charges)):
        if found is None:
            if not neutral[i]:
                known = entry = None
            out.append(s)
            continue
        any_ = True
        helper, args = found
        if helper == "__spin_add":
            if known is not None:
                known += args[0]
                continue
            lines = _charge_lines(helper, args)
            entry = None
        else:
            j = i + 1           # the next charge that aligns, past neutral statements and unaligned charges
            while j < len(stmts) and (neutral[j] or (charges[j] is not None and charges[j][0] == "__spin_add")):
                j += 1
            store = not (j < len(stmts) and charges[j] is not None)
            lines = _tick_lines(helper, args, known, store, entry)
            known = None if store else args[0]
            entry = None
        out.extend(ast.fix_missing_locations(ast.copy_location(n, s)) for n in lines)
    return out, any_


class _Divisions(ast.NodeTransformer):
    """``x = spin.mod(e, C)`` / ``spin.div`` by a positive constant: :func:`spin.mod`'s short path written out."""

    def __init__(self):
        self.hit = False

    def visit_Assign(self, node):
        v = node.value
        if not (len(node.targets) == 1 and isinstance(node.targets[0], ast.Name) and isinstance(v, ast.Call)
                and isinstance(v.func, ast.Attribute) and isinstance(v.func.value, ast.Name)
                and v.func.value.id == "spin" and v.func.attr in ("mod", "div") and len(v.args) == 2
                and not v.keywords and isinstance(v.args[1], ast.Constant) and type(v.args[1].value) is int
                and 0 < v.args[1].value <= spin.POSX):
            return node
        self.hit = True
        x, b = node.targets[0].id, v.args[1].value
        op = "%" if v.func.attr == "mod" else "//"
        keep = ast.Assign([_name(_DIVIDEND, True)], v.args[0])
        rest = _parse(f"if 0 <= {_DIVIDEND} <= {spin.POSX}:\n"
                      f"    {_COG}.t += {_DX}[{b.bit_length()}]\n"
                      f"    {x} = {_DIVIDEND} {op} {b}\n"
                      f"else:\n    {x} = spin.{v.func.attr}({_DIVIDEND}, {b})")
        return [ast.fix_missing_locations(ast.copy_location(n, node)) for n in [keep] + rest]


def inline_method(fn: ast.FunctionDef, cls) -> ast.FunctionDef:
    """Write the charges, hub variable accesses and constant divisions of woven method ``fn`` (of class ``cls``) out."""
    prologue = []
    args = fn.args.posonlyargs + fn.args.args
    if args and args[0].arg == "self":
        hub = _Hub(cls, "self")
        fn.body = [n for s in fn.body for n in _as_list(hub.visit(s))]
        for size in sorted(hub.views):
            load, store, rt_load, rt_store = _VIEWS[size][:4]
            prologue += _parse(f"{load} = {_RT}.{rt_load}")
            if store != load:
                prologue += _parse(f"{store} = {_RT}.{rt_store}")
        prologue += [_parse(f"{local} = {src}")[0] for local, src in hub.used.items()]
    fn.body, charged = _inline_body(fn.body)
    if charged:
        divisions = _Divisions()
        fn.body = [n for s in fn.body for n in _as_list(divisions.visit(s))]
        if divisions.hit:
            prologue = _parse(f"{_DX} = {_RT}.div_extra") + prologue
        prologue = _parse(f"{_COG} = {_RT}.cog\n{_PHASE} = {_COG}.hub_phase") + prologue
    anchor = fn.body[0]
    fn.body = [ast.copy_location(s, anchor) for s in prologue] + fn.body
    return ast.fix_missing_locations(fn)


def _as_list(x) -> list:
    return x if isinstance(x, list) else [x]


def install(namespace: dict) -> None:
    """Put the names inlined code uses into a generated module's namespace."""
    namespace[_RT] = spin.RT
    namespace[_PAUSE] = runtime.pause_tick
    namespace[_PAUSE_AT] = runtime.pause_tick_at
    namespace[_DEFER] = runtime.defer_store
