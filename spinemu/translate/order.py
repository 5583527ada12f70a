"""Spin's evaluation order in the generated Python (a mix-in of the expression translator).

Spin evaluates an expression's operands left to right, each to the end,
as the compiler emits them (spinemu/compiler/exprs.py): a binary operator's
left operand, then its right; a call's arguments in order; ``lookup``'s
value, then its items; an assignment's value, then the target's index
expressions, then (``+=`` and friends) the target itself; ``obj[i].m(a)``
its argument, then the index; ``coginit(id, m(a), stack)`` ``a``, then
``stack``, then ``id``.

The translator writes an assignment, ``x++``, ``~x`` ... inside an
expression as a statement placed before the one that uses it (hoisted).
Python evaluates what stays in the expression after every hoisted statement,
so an operand that Spin evaluates *before* a later operand's side effect is
saved to a temporary first if that side effect could change it.  Where
Python's own order differs from Spin's (``x[i] += v``: Python reads the
target before ``v``; ``obj[i].m(a)``: Python indexes before the arguments),
the operand Spin evaluates first is saved if the other could change it, or
it could change the other.

Both decisions come from the Spin AST (:meth:`EvalOrder.effects`): which
variables an expression reads and writes, whether it calls a method and
whether the translator hoists part of it.  Nothing is saved where no side
effect is in the way, so the common expression reads as before.

Variables are places: a Python local (``l:<frame offset>``), a variable in
hub RAM (``v:<name>``, or ``v:<frame offset>`` for a local in a hub frame),
``HUB`` (any hub byte, through an address: ``long[p]``, a method call) and
``REG`` (the cog's registers, pins, counters and the clock).  An array
element is its array (an index is assumed to stay inside its array).
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, replace

from ..frontend import ast as A

__all__ = ["Effects", "EvalOrder", "Given", "HUB", "REG", "index_nodes", "index_paths"]

HUB = "@hub"
REG = "@reg"

#: built-ins that change nothing (reading them twice or not at all is the same)
PURE_BUILTINS = frozenset({"constant", "float", "round", "trunc", "string", "strsize", "strcomp", "cogid",
                           "clkfreq", "clkmode", "chipver"})
#: built-ins that read hub RAM
_HUB_READERS = frozenset({"strsize", "strcomp", "clkfreq", "clkmode", "chipver"})
#: built-ins whose bytecode is a timed event (costs.py): waits, cog starts and stops, clock changes
_EVENT_BUILTINS = frozenset(("waitcnt", "waitpeq", "waitpne", "waitvid", "cogstop", "cognew", "coginit",
                             "clkset", "reboot"))
#: built-ins a helper pays value-dependent cycles for (their bytecode is a timed event too)
_PAID_BUILTINS = frozenset(("strsize", "strcomp", "bytefill", "wordfill", "longfill", "bytemove", "wordmove",
                            "longmove"))
#: the unary operators that assign their variable (``~x`` sign-extends x in place)
ASSIGNING_UNARY = frozenset({"~", "~~", "?"})


@dataclass(frozen=True)
class Effects:
    """What evaluating an expression touches (see the module docstring for places)."""

    reads: frozenset = frozenset()
    writes: frozenset = frozenset()
    calls: bool = False          # runs a method or a built-in that changes something (inline in the Python)
    hoists: bool = False         # part of it becomes statements before the expression
    paid: bool = False           # cycles are paid when it runs (a division, a lookup, a register read)
    events: bool = False         # a timed event: a call, a register read or write, a wait, a cog start ...

    def __or__(self, other: "Effects") -> "Effects":
        return Effects(self.reads | other.reads, self.writes | other.writes, self.calls or other.calls,
                       self.hoists or other.hoists, self.paid or other.paid, self.events or other.events)

    @property
    def any(self) -> bool:
        return self.calls or self.hoists


NONE = Effects()
_STRINGS = "v:@strings"         # string() literals in the image: only a write through an address reaches them
_CALL = Effects(frozenset({HUB, REG}), frozenset({HUB, REG}), calls=True, paid=True, events=True)
_PAID = Effects(paid=True)
_PAID_EVENT = Effects(paid=True, events=True)     # a helper pays its cycles: a timed event of its statement
#: operators whose cycles depend on their operands (spinemu.translate.spin pays them when it runs)
_PAID_BINARY = frozenset(("/", "//"))
_PAID_UNARY = frozenset((">|",))


def overlap(reads, writes) -> bool:
    """Can a write to one of ``writes`` change what reading ``reads`` gives?"""
    if reads & writes:
        return True
    if HUB in writes and any(r == HUB or r.startswith("v:") for r in reads):
        return True
    return HUB in reads and any(w.startswith("v:") for w in writes)


def _hub_places(places) -> bool:
    return any(p == HUB or p == REG or p.startswith("v:") for p in places)


def index_paths(target) -> list:
    """The index expressions of an assignment target, in the order Spin evaluates them, as attribute paths."""
    t = type(target)
    if t in (A.NameRef, A.ResultRef, A.SprRef):
        return [("index",)] if target.index is not None else []
    if t is A.MemberRef:
        paths = [("base", "index")] if getattr(target.base, "index", None) is not None else []
        return paths + ([("sub",)] if target.sub is not None else [])
    if t is A.MemRef:
        return [("base",)] + ([("index",)] if target.index is not None else [])
    if t is A.RegRef:
        return [p for p in (("bit",), ("bit2",)) if getattr(target, p[0]) is not None]
    return []


def index_nodes(target) -> list:
    """The index expressions of an assignment target, in the order Spin evaluates them."""
    if isinstance(target, A.Paren):
        target = target.expr
    return [_get(target, p) for p in index_paths(target)]


def _get(node, path):
    for name in path:
        node = getattr(node, name)
    return node


def _with(node, path, value):
    """A copy of ``node`` with the field at ``path`` replaced (the original is left alone)."""
    node = copy.copy(node)
    if len(path) == 1:
        setattr(node, path[0], value)
    else:
        setattr(node, path[0], _with(getattr(node, path[0]), path[1:], value))
    return node


class EvalOrder:
    """Keeps Spin's evaluation order (needs ``lookup``, ``expr``, ``temp``, ``hoisted``, ``in_frame``)."""

    # ------------------------------------------------------------------ what an expression touches
    def effects(self, node) -> Effects:
        """What evaluating ``node`` (an expression, a list of them, or None) reads, writes, calls and hoists."""
        if node is None:
            return NONE
        if isinstance(node, list):
            e = NONE
            for n in node:
                e = e | self.effects(n)
            return e
        t = type(node)
        if t is A.NameRef:
            kind, _sym = self.lookup(node.name, node)
            if kind == "method":                # a call without parentheses
                return _CALL
            own = Effects(self.places(node)) if kind in ("local", "var", "dat") else NONE
            return own | self.effects(node.index)
        if t is A.ResultRef:
            return Effects(self.places(node)) | self.effects(node.index)
        if t is A.MemberRef:
            return Effects(self.places(node)) | self.effects(getattr(node.base, "index", None)) \
                | self.effects(node.sub)
        if t is A.MemRef:
            return Effects(self.mem_places(node)) | self.effects(node.base) | self.effects(node.index)
        if t in (A.RegRef, A.SprRef):         # a register read pays the rest of its statement (spin_cog._read_at)
            return Effects(frozenset({REG}), paid=True, events=True) | \
                self.effects([getattr(node, f, None) for f in ("bit", "bit2", "index")])
        if t is A.AbortTrap:
            call = node.call
            return self.effects(call) | (_CALL if isinstance(call, A.NameRef) else NONE)
        if t in (A.Call, A.ObjCall):
            return self.effects(node.args) | self.effects(getattr(node, "index", None)) | _CALL
        if t is A.Builtin:
            name = node.name.lower()
            inner = self.effects(node.args or [])
            if name not in PURE_BUILTINS:
                return inner | (_CALL if name in _EVENT_BUILTINS or name in _PAID_BUILTINS
                                else replace(_CALL, events=False))
            if name in _HUB_READERS:
                literal = node.args and all(isinstance(a, A.Builtin) and a.name.lower() == "string" for a in node.args)
                paid = name in ("strsize", "strcomp")
                return inner | Effects(frozenset({_STRINGS if literal else HUB}), paid=paid, events=paid)
            return inner
        if t is A.Assign:
            return self.effects(node.value) | self.effects(node.target) | self.writing(node.target)
        if t in (A.PreOp, A.PostOp):
            return self.effects(node.target) | self.writing(node.target)
        if t is A.Unary and node.op in ASSIGNING_UNARY:
            return self.effects(node.operand) | self.writing(node.operand)
        if t is A.AddrOf:                       # the address, not the value: only its index is read
            target = node.target.expr if isinstance(node.target, A.Paren) else node.target
            if isinstance(target, A.MemRef):
                return self.effects(target.base) | self.effects(target.index)
            return self.effects([_get(target, p) for p in index_paths(target)])
        if t in (A.Number, A.Float, A.Str, A.KConst, A.ObjConst):
            return NONE
        if t is Given:
            return NONE if node.node is None or node.x.saved else self.effects(node.node)
        e = _PAID_EVENT if (t is A.Binary and node.op in _PAID_BINARY or t is A.Unary and node.op in _PAID_UNARY) \
            else _PAID if t is A.Lookup else NONE
        if t is A.Lookup and self.lazy_items(node):
            e = replace(e, events=True)
        for f in getattr(node, "__dataclass_fields__", ()):
            if f != "pos":
                v = getattr(node, f)
                if isinstance(v, (A.Node, list)):
                    e = e | self.effects(v)
        return e

    def writing(self, target) -> Effects:
        """The places an assignment to ``target`` changes (hoisted: the translator writes it as a statement)."""
        if isinstance(target, A.Paren):
            return self.writing(target.expr)
        t = type(target)
        if t in (A.NameRef, A.ResultRef, A.MemberRef):
            return Effects(writes=self.places(target), hoists=True)
        if t in (A.RegRef, A.SprRef):
            return Effects(writes=frozenset({REG}), hoists=True, events=True)
        return Effects(writes=self.mem_places(target), hoists=True)

    def places(self, node) -> frozenset:
        """The places a NameRef, ResultRef or MemberRef names (see the module docstring).

        An indexed scalar (``x[1]``, ``result[2]``) or a member past the
        variable (``x.byte[5]``) reaches the variables after it: any hub place.
        """
        ref = node.base if isinstance(node, A.MemberRef) else node
        if isinstance(ref, A.ResultRef):
            kind, sym = "local", None
        else:
            kind, sym = self.lookup(ref.name, ref)
        size, count = (4, getattr(sym, "count", 1)) if kind == "local" else (getattr(sym, "size", 4), sym.count)
        if kind == "local":
            own = f"{'v' if self.in_frame else 'l'}:{getattr(sym, 'offset', 0)}"
        else:
            own = f"v:{ref.name.lower()}"
        inside = True
        if ref.index is not None:
            inside = count > 1
        if isinstance(node, A.MemberRef) and node.sub is not None:
            c = self.constant(node.sub)
            inside = inside and c is not None and 0 <= c < size // node.size
        return frozenset({own} if inside else {own, HUB})

    def mem_places(self, node) -> frozenset:
        """The places ``byte/word/long[base][index]`` reaches: the variable, for ``@var`` and a constant index
        inside it; else any hub place."""
        base = node.base.expr if isinstance(node.base, A.Paren) else node.base
        if isinstance(base, A.AddrOf) and isinstance(base.target, (A.NameRef, A.ResultRef)) \
                and base.target.index is None:
            ref = base.target
            kind, sym = ("local", None) if isinstance(ref, A.ResultRef) else self.lookup(ref.name, ref)
            if kind in ("local", "var", "dat") and (kind != "local" or self.in_frame):
                size = 4 * getattr(sym, "count", 1) if kind == "local" else sym.size * sym.count
                c = 0 if node.index is None else self.constant(node.index)
                if c is not None and 0 <= c * node.size and (c + 1) * node.size <= size:
                    return self.places(ref)
        return frozenset({HUB})

    def has_effects(self, node) -> bool:
        """Does evaluating ``node`` change anything (a method call, an assignment, ``x++``, a lock or cog built-in)?"""
        return self.effects(node).any

    # ------------------------------------------------------------------ keeping the order
    def disturbs(self, node, later, reorder: bool = False, hoisted: bool = False) -> bool:
        """Must the value of ``node`` be saved before the ``later`` operands (which Spin evaluates after it)?

        ``reorder``: Python evaluates ``later`` before ``node``'s text (else
        only their hoisted statements come first); ``hoisted``: statements
        were written for ``later`` (a value saved inside them), so what they
        do may all run first.
        """
        mine, theirs = self.effects(node), self.effects(later)
        if reorder:
            if mine.calls and (theirs.calls or theirs.paid or _hub_places(theirs.reads)) or \
                    mine.paid and theirs.events:
                return True                     # its call would come after theirs, what it pays after an event
            # they would run first: what they write must not reach its reads, nor its writes miss their reads
            return overlap(mine.reads, theirs.writes) or overlap(mine.writes, theirs.reads)
        if not (theirs.hoists or hoisted or self.event_mode and theirs.events):
            return False
        # their statements come first: a call of its own must not move after them, nor what it pays
        # (a division's loop) after a timed event of theirs
        return mine.calls or mine.paid and theirs.events or overlap(mine.reads, theirs.writes)

    def save(self, x, at: int):
        """Save ``x`` to a temporary whose statement goes at ``at`` in the hoisted list; the temporary's X."""
        tmp = self.temp("value")
        self.hoisted.insert(at, f"{tmp} = {x.text}")
        return type(x)(tmp, wrapped=x.wrapped, boolean=x.boolean, truthy=x.truthy, saved=True)

    def keep(self, nodes, xs, marks, reorder_after=None) -> list:
        """Save each translated operand that a later one could disturb (see :meth:`disturbs`).

        Args:
            nodes: the operands' nodes, in Spin's order.
            xs: their translations.
            marks: for each, the length of the hoisted list just after it was translated.
            reorder_after: an index k: Python evaluates operand k before the ones
                in front of it (``obj[i].m(a)``: the index, last in Spin's order).
        """
        xs = list(xs)
        end = len(self.hoisted)
        for i in reversed(range(len(nodes) - 1)):
            if xs[i].const is not None or xs[i].saved:
                continue
            later = nodes[i + 1:]
            # statements written for the later operands (their side effects, or values saved inside them
            # to keep their own order) all run before this operand's text
            hoisted = end > marks[i]
            if reorder_after is not None and i < reorder_after:
                must = self.disturbs(nodes[i], [nodes[reorder_after]], reorder=True) or \
                    self.disturbs(nodes[i], later, hoisted=hoisted)
            else:
                must = self.disturbs(nodes[i], later, hoisted=hoisted)
            if must:
                xs[i] = self.save(xs[i], marks[i])
                end += 1
        return xs

    def operands(self, nodes, reorder_after=None) -> list:
        """Translate ``nodes`` (evaluated by Spin in this order), keeping Spin's order; their X's."""
        xs, marks = [], []
        for n in nodes:
            xs.append(self.expr(n))
            marks.append(len(self.hoisted))
        return self.keep(nodes, xs, marks, reorder_after)

    def place(self, target, reuse: bool = False) -> str:
        """``target`` as Python text to assign to, its index expressions translated once, in Spin's order.

        ``reuse``: the text is evaluated more than once (``old = T; T += 1``,
        ``T = f(T)``, read again for the assignment's value), so an index that
        could give another value the second time (it calls a method, or reads
        what the assignment changes) or pays cycles when it runs (a division)
        is saved to a temporary first.
        """
        if isinstance(target, A.Paren):
            target = target.expr
        paths = index_paths(target)
        if not paths:
            return self._target_text(target)
        nodes = [_get(target, p) for p in paths]
        xs = self.operands(nodes)
        for k, (n, x) in enumerate(zip(nodes, xs)):
            if x.const is None and not x.saved and (reuse and self._unstable(n, target) or self.effects(n).events):
                # (an index with a call is computed before the store's line: its cycles after the
                # call are paid there, before the store)
                xs[k] = self.save(x, len(self.hoisted))
        given = target
        for p, x in zip(paths, xs):
            given = _with(given, p, Given(getattr(_get(target, p), "pos", None), x))
        return self._target_text(given)

    def _target_text(self, target) -> str:
        """A target's text (not a read of it: a register named here is no timed event)."""
        saved, self.placing = self.placing, True
        try:
            return self.expr(target).text
        finally:
            self.placing = saved


    def _unstable(self, index, target) -> bool:
        """Could ``index`` (of ``target``) give another value, or pay again, if evaluated a second time?"""
        e = self.effects(index)
        return e.calls or e.paid or overlap(e.reads, self.writing(target).writes)

    def index_first(self, target, reuse: bool) -> bool:
        """Does :meth:`place` evaluate an index of ``target`` in a statement of its own (hoisted)?

        Then the index comes before the value in the Python, whatever Python's
        order in ``T = V`` would be.
        """
        nodes = index_nodes(target)
        return any(self.effects(n).hoists or self.effects(n).events or reuse and self._unstable(n, target)
                   for n in nodes)

    def value_first(self, value_node, value, target, mark: int, reuse: bool, reads_target: bool = False):
        """Save the value of an assignment to ``target`` if Python would not compute it first, as Spin does.

        Spin computes the value, then the target's index, then (``OP=``,
        ``reads_target``) reads the target.  In ``T[i] = V`` Python computes
        ``V`` before ``i``, unless the index is hoisted; in ``T[i] OP= V`` it
        reads ``T[i]`` first.
        """
        if value.const is not None or value.saved:
            return value
        later = index_nodes(target) + ([target] if reads_target else [])
        moved = reads_target or self.index_first(target, reuse)
        if self.disturbs(value_node, later, reorder=moved):
            return self.save(value, mark)
        return value


class Given(A.Expr):
    """An operand translated already (its X); the translator returns it as it is.

    ``node``: the Spin expression it came from, if its text still evaluates it
    (what it does counts where Python could skip it: ``x OR= f(y)``).
    """

    def __init__(self, pos, x, node=None):
        self.pos = pos
        self.x = x
        self.node = node
