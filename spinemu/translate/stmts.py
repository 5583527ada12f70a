"""Spin statements as Python statements, and what each costs.

One :class:`MethodTranslator` per method writes the method's lines into a
:class:`~spinemu.translate.code.Code` and records, for the Python lines it
writes, the cycles the weaver (weave.py) charges before or after them:

==========================  =============================================  ==========================
Spin                        Python                                         charged
==========================  =============================================  ==========================
``if c`` / ``elseif``       ``if c:`` / ``elif c:`` / ``else:``            condition + JZ before it;
                                                                           JMP after the branch
``case v``                  ``if v == 1: ... elif v in (2, 3): ...``       compares per branch, CASE_DONE
``repeat``                  ``while True:``                                JMP after the body
``repeat n``                ``for _ in range(n):``                         n + TJZ; DJNZ per pass
``repeat while c``          ``while c:``                                   c + JZ per pass; JMP
``repeat ... until c``      ``while True: ...; if c: break``               c + JZ per pass
``repeat x from a to b``    ``for x in range(a, b + 1):`` (constant        REPEAT per pass
                            bounds) or a ``while True`` with
                            ``spin.repeat_step``
``next`` / ``quit``         ``continue`` / ``break``                       the jump (and case pops)
``abort v`` / ``\\f(x)``    ``raise spin.Abort(v)`` / ``spin.trap(f, x)``
==========================  =============================================  ==========================

Costs come from the compiler's own bytecode for each piece (costs.py).
"""
from __future__ import annotations

from contextlib import contextmanager

from ..compiler.code import CodeBuffer, Label
from ..compiler import stmts as cstmts
from ..frontend import ast as A
from ..frontend.ast import key
from .costs import Op, anchor_at, call_depths, ceil16, chain, drop_result_delta, price, jump_op, split, split_read
from .exprs import Event, ExprTranslator, X
from .order import _EVENT_BUILTINS, _PAID_BUILTINS, Given
from .loops import LoopTranslator

__all__ = ["MethodTranslator"]

_PY_AUG = {"+", "-", "*", "&", "|", "^"}


class MethodTranslator(ExprTranslator, LoopTranslator):
    """Translates one Spin method (see the module docstring).

    Args:
        objt: the object translator (program.py): names, symbols, the compiler's object.
        method: the ``ast.Method``.
        code: where the lines go.
    """

    def __init__(self, objt, method, code):
        self.objt = objt
        self.obj = objt.oc
        self.names = objt.names
        self.method = method
        self.code = code
        self.T = objt.timing
        self.mc = _Compiler(self.obj, method)
        self.frame = self.mc.frame
        self.result_name = self.names.local(method.result or "result")
        self.in_frame = needs_hub_frame(method)
        self.frame_name = self.names.temp_base("loc")
        self.hoisted: list = []
        self.loops: list = []
        self.temps: set = set()
        self.lookup_costs: dict = {}         # the text of each lookup call: what its items cost
        self.event_mode = False              # one line per timed event (timed_statement)
        self.placing = False                 # translating an assignment's target (not a read of it)
        self.top_node = None
        self.event_lines: list = []
        self._lazy = None
        self.exits: set = set()             # lines that leave their block (return, raise, break, continue)
        self.last_data = b""
        #: stack bytes the enclosing statements keep while this one runs (a repeat count: 4, a case: 8)
        self.held = 0
        self.cur_pos = method.pos
        self.path = method.pos.path
        self.stmts: list = []               # the statements being translated, outermost first
        self._node_offsets: dict = {}       # id(statement) -> {id(expression): object offset}

    # ------------------------------------------------------------------ helpers for exprs.py
    def unsupported(self, what: str, node):
        self.objt.unsupported(what, node)

    def lookup(self, name: str, node):
        k = key(name)
        if k in self.frame:
            return "local", self.frame[k]
        if k == "result":
            from ..compiler.symbols import LocalSymbol
            return "local", LocalSymbol("result", 0, 1)
        return self.objt.lookup(name, node)

    def temp(self, prefix: str) -> str:
        base = self.names.temp_base(prefix)
        name, n = base, 1
        while name in self.temps:
            n += 1
            name = f"{base}{n}"
        self.temps.add(name)
        return name

    # ------------------------------------------------------------------ costs
    def piece(self, fn, loop_count: bool = False, offset: int = None, **kw) -> list:
        """Price the bytecode the compiler makes for ``fn()`` (a statement or expression).

        A lookup whose items are evaluated one by one at run time (see
        ``x_Lookup``) is priced without its items (laid out, so that addresses
        keep their size, but left out): the runtime pays each item it reaches.
        ``last_data``: the bytecode priced (the calls in such items run inside
        the lookup's search).  ``offset``: where the piece is laid out (else
        where the current statement starts).
        """
        self.mc.lazy = frozenset(id(n) for n in self.lazy_lookups())
        data = self._compiled(fn, loop_count, offset)
        self.last_data = data
        return price(self.T, data, **kw)

    def lazy_lookups(self) -> list:
        """The lookups of this method whose items are evaluated one by one at run time (see ``x_Lookup``)."""
        if self._lazy is None:
            self._lazy = [n for n in A.walk(self.method.body) if isinstance(n, A.Lookup) and self.lazy_items(n)]
        return self._lazy

    def _compiled(self, fn, loop_count: bool, offset: int = None) -> bytes:
        mc = self.mc
        saved = mc.code, mc.loops
        mc.code = CodeBuffer()
        mc.code.pos = self.cur_pos          # (a string's push has a place; the string pool does not)
        nxt, end = Label(), Label()
        mc.loops = [cstmts._Loop(nxt, end, count=loop_count)]
        try:
            fn()
            mc.code.mark(nxt)
            mc.code.mark(end)
            # laid out where the statement really is, so that address pushes get their real size
            spans, _ = mc.code.layout(self.objt.offset_of(self.cur_pos, self.method) if offset is None else offset)
        finally:
            mc.code, mc.loops = saved
        out = []
        for sp in spans:
            if sp.pos is None and sp.note == "string":
                continue                    # the string pool
            if sp.pos is _ITEMS:            # a lookup item paid at run time
                continue
            out.append(sp.data)
        return b"".join(out)

    def callee(self, data, i: int) -> tuple:
        """``(parameter count, Python name)`` of the method the CALL/CALL_OBJ at ``data[i]`` calls."""
        if data[i] == 0x05:
            m = self.obj.symbols.methods[data[i + 1] - 1]
            return m.nparams, self.names.attr(m.name)
        entry, method = data[i + 1], data[i + 2]
        for sym in self.obj.symbols.objects:
            if sym.index <= entry < sym.index + sym.count:
                pubs = [m for m in sym.unit.spin.methods if m.public]
                return len(pubs[method - 1].params), self.names.child_method(sym.name, pubs[method - 1].name)
        return 0, None

    def note_depths(self, lines, data: bytes = None, runs=None, ops=None) -> None:
        """Record the stack bytes in use at the calls of ``data`` (the piece compiled last), for ``lines``.

        One number when every call of the statement starts at the same depth;
        else ``[(method, depth), ...]`` in the order the calls run
        (``f(g(x), g(y))``: g above f's frame, the second g one long higher,
        then f); the weaver hands each call its own depth.  ``runs``: the
        cycles each call after the first pays before it starts (a statement
        whose timed events are calls: ``[(method, depth, cycles), ...]``);
        ``ops``: the statement's priced bytecode, whose helper calls that pay
        cycles (``("@div", None, cycles)``) are listed among the calls.
        """
        calls = call_depths(self.last_data if data is None else data, self.callee)
        if runs is not None and ops is not None:
            listed, found = [], iter(calls)
            for o in ops:
                if o.kind == "call":
                    d, name = next(found, (0, None))
                    listed.append((name, d + self.held))
                elif o.kind == "paid":
                    listed.append(("@" + o.helper, None))
            if len(runs) == len(listed):
                depth = [(name, d, run) for (name, d), run in zip(listed, runs)]
                for line in lines:
                    if line is not None:
                        self.code.call_depths[line] = depth
                return
        if not calls:
            return
        if runs is not None and len(runs) == len(calls):
            depth = [(name, d + self.held, run) for (d, name), run in zip(calls, runs)]
        elif all(d == calls[0][0] for d, _ in calls):
            depth = calls[0][0] + self.held if calls[0][0] + self.held else None
        else:
            depth = [(name, d + self.held) for d, name in calls]
        if depth is not None:
            for line in lines:
                if line is not None:
                    self.code.call_depths[line] = depth

    def expr_ops(self, node, at=None) -> list:
        """The priced bytecode of expression ``node``, laid out where the compiler put it (a lookup's
        end address is one byte or two by where it is), else where the code at ``at`` (a position: a
        branch, a case value, a loop's test) is, else where the current statement is."""
        offset = self.node_offset(node)
        if at is None:
            return self.piece(lambda: self.mc.expr(node), offset=offset)
        saved, self.cur_pos = self.cur_pos, at
        try:
            return self.piece(lambda: self.mc.expr(node), offset=offset)
        finally:
            self.cur_pos = saved

    def node_offset(self, node):
        """The object offset of the first bytecode of expression ``node`` in an enclosing statement being
        translated, as the compiler lays the statement out (None: not found)."""
        for st in reversed(self.stmts):
            found = self._node_offsets.get(id(st))
            if found is None:
                found = self._node_offsets[id(st)] = self._offsets_in(st)
            if id(node) in found:
                return found[id(node)]
        return None

    def _offsets_in(self, st) -> dict:
        """``{id(expression): object offset}`` of statement ``st`` compiled whole where it is."""
        mc = self.mc
        marks: dict = {}
        had = "expr" in mc.__dict__
        inner = mc.expr

        def expr(n):
            label = Label()
            mc.code.mark(label)
            marks.setdefault(id(n), (n, label))     # (the node kept alive: its id stays its own)
            inner(n)

        mc.expr = expr
        mc.lazy = frozenset(id(n) for n in self.lazy_lookups())
        saved = mc.code, mc.loops
        mc.code = CodeBuffer()
        mc.code.pos = st.pos
        nxt, end = Label(), Label()
        mc.loops = [cstmts._Loop(nxt, end)]
        try:
            mc.block([st])
            mc.code.mark(nxt)
            mc.code.mark(end)
            at = mc.code.label_offsets(self._start_of(mc.code, st))
        finally:
            mc.code, mc.loops = saved
            if had:
                mc.expr = inner
            else:
                del mc.expr
        return {k: at[label] for k, (_, label) in marks.items()}

    def _start_of(self, code, st) -> int:
        """Where the compiled object puts statement ``st`` (compiled into ``code``): its first span whose
        source position the object lists (a loop with its test at the end starts with its body)."""
        start = self.objt.offset_of(st.pos, self.method)
        for _ in range(4):              # an address push before the anchor may change size with the start
            spans, _ = code.layout(start)
            anchor = next(((sp.offset, real) for sp in spans if sp.data and getattr(sp.pos, "line", None)
                           and (real := self.objt.known_offset(sp.pos)) is not None), None)
            if anchor is None or anchor[0] == anchor[1]:
                break
            start += anchor[1] - anchor[0]
        return start

    def lookup_item_cost(self, exprs, down: bool, is_range: bool, each: bool = False) -> tuple:
        """``(cycles of the item, extra cycles when it matches)`` of one lookup/lookdown item.

        ``each`` (items paid one by one at run time): ``(cycles up to its last
        call or register write, or before its last register read, cycles from
        there on, extra when it matches)``.
        """
        T = self.T
        ops = [o for e in exprs for o in self.expr_ops(e)]
        name = ("lookdown" if down else "lookup") + ("_range" if is_range else "_value")
        table = getattr(T, name)
        if each:
            ops.append(Op(0x10, table[False]))
            # around its last event, as a case value: an item ``f(outa)`` pays its call before the
            # method runs, though the register read comes first
            around = _around_event(ops)
            before, after = around if isinstance(around, tuple) else (ops, [])
            return chain(before), chain(after), table[True] - table[False]
        found, missed = ceil16(table[True] + 12), ceil16(table[False] + 12)
        return sum(ceil16(o.rest + 12) for o in ops) + missed, found - missed

    def lookup_row(self, costs: list, each: bool) -> tuple:
        """A lookup's row of ``SPIN_LOOKUPS`` (see spinemu.translate.spin.lookup)."""
        done = ceil16(self.T.look_done + 12)
        if each:
            return ("each", done, tuple(costs))
        return ([c for c, _ in costs], done, [f for _, f in costs])

    def long_jump(self, pos, note: str, k: int = 0) -> bool:
        """Is the ``k``-th jump the compiler made at ``pos`` with ``note`` the two-byte form (compiled object)?"""
        found = self.objt.long_jumps_at(pos, note)
        return found[k] if k < len(found) else False

    def charge(self, line: int, slot: str, ops, first: bool = False) -> None:
        """Charge ``ops`` at ``slot`` of ``line``; nothing runs after a return, abort, next or quit.

        ``first``: before what the line pays already (see ``Code.charge``).
        """
        if line is not None and ops and not (slot == "a" and line in self.exits):
            self.code.charge(line, slot, list(ops), first)

    def charge_add(self, line: int, slot: str, cycles: int) -> None:
        if line is not None and cycles and not (slot == "a" and line in self.exits):
            self.code.charge_add(line, slot, cycles)

    # ------------------------------------------------------------------ emitting
    def emit(self, text, node=None) -> int:
        """Write one line (or a hoisted block: ``(header, [lines or blocks])``); its (first) line number."""
        if isinstance(text, tuple):
            header, body = text
            first = self.emit(header, node)
            self.code.indent += 1
            for item in body:
                self.emit(item, node)
            self.code.indent -= 1
            return first
        line = self.code.line(text, node.pos.line if node is not None else None)
        if self.held:                       # a call at the start of this line: above what the enclosing statements hold
            self.code.call_depths.setdefault(line, self.held)
        rows = [self.lookup_costs[call] for call in _lookup_calls(text)]   # for the runtime, left to right
        if rows:
            self.code.lookups[line] = rows
        return line

    def block(self, stmts) -> tuple:
        """Emit a body (indented); ``(first line, last statement line)``."""
        self.code.indent += 1
        first = last = None
        try:
            for st in stmts:
                f, last = self.statement(st)
                first = first or f
            if first is None:                   # no statements, or none that writes a line
                first = last = self.emit("pass")
        finally:
            self.code.indent -= 1
        return first, last

    def statement(self, st) -> tuple:
        self.cur_pos = st.pos
        self.code.comments_before(st.pos.line)
        method = getattr(self, "s_" + type(st).__name__)
        self.stmts.append(st)
        try:
            return method(st)
        finally:
            self.stmts.pop()

    def flush(self, main, node) -> tuple:
        """Emit the hoisted lines and ``main`` (a line or None); ``(first, last)``.

        ``self.event_lines`` gets the numbers of the lines that make a timed
        event (``Event`` lines, see :meth:`timed_statement`), in order.
        """
        lines = self.hoisted + ([main] if main else [])
        self.hoisted = []
        first = last = None
        self.event_lines = []
        for text in lines:
            last = self.emit(text, node)
            first = first or last
            if isinstance(text, Event):
                self.event_lines.append(last)
        if first is None:
            first = last = self.emit("pass", node)
        return first, last

    @contextmanager
    def timed_statement(self, ops, top=None):
        """Translate a statement whose bytecodes ``ops`` have several timed events, one line per event.

        One charge before a statement and one after its call (or read) place
        one event at its cycle.  A statement with more (``x := f(a) + g(b)``,
        ``outa := ina + f(x)``, two register reads) is written with each event
        on a line of its own (``value = self.f(a)``), in Spin's order, and
        each line pays the bytecodes from the event before it (see
        :meth:`charge_events`).  ``top``: the statement's own expression when
        it is an event itself (a call as a statement): it stays on the last line.
        """
        saved = self.event_mode, self.top_node
        self.event_mode = not _one_event(ops) and not _calls_only(ops)
        self.top_node = top
        try:
            yield self.event_mode
        finally:
            self.event_mode, self.top_node = saved

    def charge_events(self, ops, first: int, last: int) -> bool:
        """Charge a statement written by :meth:`timed_statement`: each event line pays the bytecodes since
        the event before it, what follows the last event is paid after it.  False if the lines do not
        match the events (the caller charges the statement as one)."""
        runs, kinds = _segments(ops)
        lines = self.event_lines
        if len(lines) != len(kinds) or not lines:
            return False
        for line, run in zip(lines, runs):
            self.charge(line, "b", run)
        if lines[-1] == last:
            # after a write: after the line; after a call, read or lookup: before the store or return
            self.charge(last, "a" if kinds[-1] == "write" else "p", runs[-1])
        else:
            self.charge(lines[-1] + 1, "b", runs[-1])
        return True

    # ------------------------------------------------------------------ simple statements
    def s_ExprStmt(self, st) -> tuple:
        e = st.expr
        t = type(e)
        main = None
        ops = self.piece(lambda: self.mc.block([st]), run_params=self.run_params(st))
        data = self.last_data
        with self.timed_statement(ops, top=e) as timed:
            if t is A.Assign:
                self.assign(e)
            elif t is A.PreOp:
                self.step(e.target, e.op)
            elif t is A.PostOp:
                self.step(e.target, e.op, post=True)
            elif t is A.Unary and isinstance(e.operand, A.VARIABLE_NODES) and self.constant(e) is None:
                self.unary_assign(e)
            elif t is A.AbortTrap:
                main = self.expr(e).text[:-1] + ", keep_result=False)"
            else:
                main = self.expr(e).text
            if timed and main is not None and self.is_event(e):
                main = Event(main)
        first, last = self.flush(main, st)
        self.charge_statement(ops, data, first, last, timed)
        if t in (A.Call, A.ObjCall) or (t is A.NameRef and main):
            self.charge_add(last, "p", drop_result_delta(self.T))
        return first, last

    def run_params(self, st) -> int:
        """Parameters of the Spin method a ``cognew``/``coginit`` in ``st`` starts (for RUN's cost)."""
        for n in A.walk([st]):
            if isinstance(n, A.Builtin) and n.name.lower() in ("cognew", "coginit") and n.args:
                first = n.args[0] if n.name.lower() == "cognew" else n.args[min(1, len(n.args) - 1)]
                first = first.expr if isinstance(first, A.Paren) else first
                if isinstance(first, A.Call):
                    return len(first.args)
        return 0

    def result_text(self) -> str:
        return f"{self.frame_name}.{self.result_name}" if self.in_frame else self.result_name

    def s_Return(self, st) -> tuple:
        ops = self.piece(lambda: self.mc.block([st]))
        data = self.last_data
        with self.timed_statement(ops, top=st.value) as timed:
            if st.value is None:
                main = f"return {self.result_text()}" if self.objt.uses_result(self.method) else "return"
            else:
                main = f"return {self.value(st.value)}"
            if timed and st.value is not None and self.is_event(st.value):
                main = Event(main)
        return self.ending(st, main, ops, data, timed)

    def s_Abort(self, st) -> tuple:
        ops = self.piece(lambda: self.mc.block([st]))
        data = self.last_data
        with self.timed_statement(ops, top=st.value) as timed:
            if st.value is not None:
                main = f"raise spin.Abort({self.value(st.value)})"
                if timed and self.is_event(st.value):
                    main = Event(main)
                return self.ending(st, main, ops, data, timed)
        value = self.result_text() if self.objt.uses_result(self.method) else "0"
        return self.ending(st, f"raise spin.Abort({value}, bare=True)", ops, data, False)

    def ending(self, st, main, ops, data, timed: bool) -> tuple:
        """``return``/``abort``: what comes after a call in the value is paid after the value (weave.py)."""
        first, last = self.flush(main, st)
        self.charge_statement(ops, data, first, last, timed)
        self.exits.add(last)
        return first, last

    def emit_hoisted(self, node) -> tuple:
        """Emit the hoisted lines (before a condition); ``(first line or None, last line or None)``;
        ``self.event_lines`` gets the ``Event`` lines."""
        first = last = None
        self.event_lines = []
        for h in self.hoisted:
            last = self.emit(h, node)
            first = first or last
            if isinstance(h, Event):
                self.event_lines.append(last)
        self.hoisted = []
        return first, last

    def charge_decision(self, ops, data, first: int, lines, timed: bool) -> list:
        """Charge the bytecodes ``ops`` of a value Python decides on (a condition and its jump, a case
        selector, a repeat count), written on ``lines`` (``first`` the first of them); returns the run
        to pay once it is decided (where each way goes on).  As :meth:`charge_statement`."""
        runs, kinds = _segments(ops)
        if timed and len(self.event_lines) == len(kinds) and self.event_lines:
            for line, run in zip(self.event_lines, runs):
                self.charge(line, "b", run)
            self.note_depths(lines, data)
            return runs[-1]
        if not _one_event(ops) and _calls_only(ops):
            self.charge(first, "b", runs[0])
            self.note_depths(lines, data, [None] + [chain(r) for r in runs[1:-1]], ops)
            return runs[-1]
        self.note_depths(lines, data)
        pre, post = split(ops)
        pre, mid = split_read(pre)
        self.charge(first, "b", pre)
        if mid:
            self.code.charge_mid(first, mid)
        return post

    def charge_statement(self, ops, data, first: int, last: int, timed: bool) -> None:
        """Charge a statement written on lines ``first..last`` (and record where its calls' frames go).

        One timed event (or a register read, then one event): the bytecodes up
        to it before the first line, the rest before the last line stores or
        returns (``post``).  Several calls and no other event: the same, and
        each call after the first pays the bytecodes since the call before it
        as it starts (the weaver wraps it).  Other events: one line per event
        (:meth:`timed_statement`, :meth:`charge_events`).
        """
        lines = range(first, last + 1)
        if timed and self.charge_events(ops, first, last):
            self.note_depths(lines, data)
            return
        runs, kinds = _segments(ops)
        if not _one_event(ops) and _calls_only(ops):
            self.charge(first, "b", runs[0])
            self.note_depths(lines, data, [None] + [chain(r) for r in runs[1:-1]], ops)
            self.charge(last, "p", runs[-1])
            return
        self.note_depths(lines, data)
        pre, post = split(ops)
        pre, mid = split_read(pre)
        self.charge(first, "b", pre)
        if mid:
            self.code.charge_mid(first, mid)
        self.charge(last, "p", post)            # paid between the value and leaving (weave.py)

    def s_Next(self, st) -> tuple:
        loop = self.loop_of(st, "next")
        ops = self.jump_out(st) + loop.next_ops
        if loop.emit_next is not None:          # Spin's next goes to the loop's test: write it here
            first = loop.emit_next(ops)
            line = self.emit("continue", st)
            self.exits.add(line)
            return first, line
        line = self.emit("continue", st)
        self.charge(line, "b", ops)
        self.exits.add(line)
        return line, line

    def s_Quit(self, st) -> tuple:
        self.loop_of(st, "quit")
        ops = self.jump_out(st)
        line = self.emit("break", st)
        self.charge(line, "b", ops)
        self.exits.add(line)
        return line, line

    def loop_of(self, st, word):
        if not self.loops:
            self.unsupported(f"'{word}' outside a repeat loop", st)
        return self.loops[-1]

    def jump_out(self, st) -> list:
        """The ops of a ``next``/``quit``: the enclosing cases' pops and the jump, as the compiler made them.

        The jump's size (one or two offset bytes, 16 cycles apart) depends on
        how far the loop's end or test is, so it comes from the compiled object.
        """
        ops = price(self.T, self.objt.compiled_at(st.pos))
        for i, op in enumerate(ops):
            if op.code in (0x04, 0x0A, 0x0B):       # what follows (a case's CASE_DONE) is another statement's
                return ops[:i + 1]
        return ops

    # ------------------------------------------------------------------ assignments
    def assign(self, node, reuse: bool = False) -> str:
        """Hoist ``target := value`` (or ``target OP= value``) as a statement; the target's text.

        Spin computes the value, then the target's index, then (``OP=``) reads
        the target; the value is saved first where Python's order would differ
        (order.py).  ``reuse``: the target is read again for the expression's value.
        """
        target = node.target
        value = self.expr(node.value)
        mark = len(self.hoisted)
        if node.op == ":=":
            return self.store(target, node.value, value, mark, reuse)
        op = node.op.upper() if node.op.isalpha() else node.op
        return self.store_op(target, op, node.value, value, mark, reuse)

    def is_local(self, target) -> bool:
        """Is ``target`` a Python local (stores must wrap to 32 bits themselves)?"""
        if self.in_frame:
            return False
        if isinstance(target, A.ResultRef):
            return True
        return isinstance(target, A.NameRef) and key(target.name) in self.frame

    def store(self, target, value_node, value: X, mark: int, reuse: bool = False) -> str:
        text = self.place(target, reuse)
        value = self.value_first(value_node, value, target, mark, reuse)
        register = isinstance(target.expr if isinstance(target, A.Paren) else target, (A.RegRef, A.SprRef))
        if self.is_local(target):
            self.hoisted.append(f"{text} = {self.wrapped(value).text}")
        else:
            v = self.wrapped(value).text if value.boolean else value.text
            self.hoisted.append(self.line(f"{text} = {v}", register))
        return text

    def store_op(self, target, op: str, value_node, value: X, mark: int, reuse: bool = False) -> str:
        local = self.is_local(target)
        aug = op in _PY_AUG and not local and not value.boolean
        text = self.place(target, reuse or not aug)
        value = self.value_first(value_node, value, target, mark, reuse or not aug, reads_target=True)
        register = isinstance(target.expr if isinstance(target, A.Paren) else target, (A.RegRef, A.SprRef)) \
            or op in ("/", "//")            # (the line whose helper pays the division is the timed event)
        if aug:
            self.hoisted.append(self.line(f"{text} {op}= {value.text}", register))
            return text
        new = self.binop(op, X(text), value, value_node)
        self.hoisted.append(self.line(f"{text} = {(self.wrapped(new) if local or new.boolean else new).text}", register))
        return text

    def binop(self, op: str, left: X, right: X, right_node=None) -> X:
        """``left OP right`` for already translated operands (assignment operators; ``right_node``: the
        Spin value ``right`` comes from)."""
        return self.x_Binary(A.Binary(None, op, Given(None, left), Given(None, right, right_node)))

    def step(self, target, op: str, post: bool = False, reuse: bool = False, text: str = None,
             timed: bool = None) -> str:
        """Hoist ``++x``/``x++``/``~x``/``x~``/``?x``/``x?`` on ``target`` as a statement; the target's text.

        ``text``: the target placed already (``x++`` read its old value first);
        ``timed``: is this line the timed event (default: if ``target`` is a register).
        """
        local = self.is_local(target)
        if timed is None:
            timed = isinstance(target.expr if isinstance(target, A.Paren) else target, (A.RegRef, A.SprRef))
        if text is None:        # T = f(T) reads the target in the same statement that writes it
            twice = op == "?" or op in ("~", "~~") and not post
            text = self.place(target, reuse or twice)
        mark = len(self.hoisted)
        if op in ("++", "--"):
            sign = "+" if op == "++" else "-"
            self.hoisted.append(f"{text} = wrap({text} {sign} 1)" if local else f"{text} {sign}= 1")
        elif op == "~":
            self.hoisted.append(f"{text} = 0" if post else f"{text} = spin.sign_extend_byte({text})")
        elif op == "~~":
            self.hoisted.append(f"{text} = -1" if post else f"{text} = spin.sign_extend_word({text})")
        elif op == "?":
            fn = "random_reverse" if post else "random_forward"
            self.hoisted.append(f"{text} = spin.{fn}({text})")
        else:
            self.unsupported(f"the operator {op}", target)
        if timed:
            self.hoisted[mark] = self.line(self.hoisted[mark], True)
        return text

    def unary_assign(self, e) -> None:
        """``-x``, ``!x``, ``||x`` ... written as a statement: Spin changes ``x`` in place."""
        text = self.place(e.operand, reuse=True)
        new = self.wrapped(self.x_Unary(A.Unary(e.pos, e.op, Given(e.pos, X(text)))))
        register = isinstance(e.operand.expr if isinstance(e.operand, A.Paren) else e.operand, (A.RegRef, A.SprRef))
        self.hoisted.append(self.line(f"{text} = {new.text}", register))

    # ------------------------------------------------------------------ builtins
    def x_Builtin(self, node) -> X:
        x = self.builtin_x(node)
        name = node.name.lower()
        return self.event(x, node) if name in _EVENT_BUILTINS or name in _PAID_BUILTINS else x

    def builtin_x(self, node) -> X:
        name = node.name.lower()
        args = node.args or []
        if name in ("constant", "float", "round", "trunc"):
            v = self.constant(node, spin_constant=True)
            return X(str(v), 14 if v >= 0 else 11, const=v)
        if name == "string":
            offset = self.objt.string_offset(self.method, node)
            text = "".join(a.text if isinstance(a, A.Str) else "" for a in args)
            return X(f"self.string(0x{offset:04X}, {text!r})" if text else f"self.string(0x{offset:04X})")
        if name in ("cognew", "coginit"):
            return self.cog_start(node, name, args)
        simple = ("waitcnt", "waitpeq", "waitpne", "cogstop", "lockret", "lockset", "lockclr", "strsize",
                  "strcomp", "bytefill", "wordfill", "longfill", "bytemove", "wordmove", "longmove",
                  "clkset", "waitvid")
        if name in simple:
            return X(f"spin.{name}({', '.join(self.wrapped(x).text for x in self.operands(args))})")
        if name in ("locknew", "cogid", "clkfreq", "clkmode", "reboot"):
            return X(f"spin.{name}()")
        if name == "chipver":
            return X("spin.byte[-1]")
        self.unsupported(f"the built-in {node.name}", node)

    def cog_start(self, node, name, args) -> X:
        """``cognew``/``coginit``: Spin evaluates a Spin method's arguments, the stack, then coginit's cog id
        (Python: the id first); an address (PASM) form in the written order."""
        new = name == "cognew"
        first = args[0] if new else args[1]
        rest = args[1] if new else args[2]
        target = first.expr if isinstance(first, A.Paren) else first
        if isinstance(target, (A.Call, A.NameRef)) and self.lookup(target.name, target)[0] == "method":
            call_args = target.args if isinstance(target, A.Call) else []
            nodes = list(call_args) + [rest] + ([] if new else [args[0]])
            xs = [self.wrapped(x).text for x in self.operands(nodes, reorder_after=None if new else len(nodes) - 1)]
            head = "" if new else f"{xs.pop()}, "
            stack = xs.pop()
            params = "".join(f", {x}" for x in xs)
            return X(f"spin.{name}({head}self.{self.names.attr(target.name)}{params}, stack={stack})")
        xs = [self.wrapped(x).text for x in self.operands(([] if new else [args[0]]) + [first, rest])]
        return X(f"spin.{name}({', '.join(xs)}, stack=0)")

    # ------------------------------------------------------------------ if
    def s_If(self, st) -> tuple:
        first = top = None
        last = len(st.branches) - 1
        closers = 0
        for i, br in enumerate(st.branches):
            j = "JNZ" if br.negate else "JZ"
            ops = self.expr_ops(br.cond, br.pos) + [jump_op(self.T, j, self.long_jump(br.pos, "if"), taken=False)]
            data = self.last_data
            with self.timed_statement(ops) as timed:
                c = self.cond(br.cond)
            if br.negate:
                c = f"not ({c})" if " " in c else f"not {c}"
            if self.hoisted and i > 0:
                self.emit("else:", br)
                self.code.indent += 1
                closers += 1
            branch_first, _ = self.emit_hoisted(br)
            word = "if" if i == 0 or branch_first else "elif"
            header = self.emit(f"{word} {c}:", br)
            top = top or header
            branch_first = branch_first or header
            first = first or branch_first
            post = self.charge_decision(ops, data, branch_first, range(branch_first, header + 1), timed)
            body_first, body_last = self.block(br.body)
            self.charge(body_first, "b", post, first=True)
            self.charge(header, "e", post)
            if i < last or st.else_body is not None:
                self.charge(body_last, "a", [jump_op(self.T, "JMP", self.long_jump(br.pos, "to end of if"))])
        if st.else_body is not None:
            self.code.comments_before(st.else_pos.line if st.else_pos else st.pos.line)
            self.code.line("else:", st.else_pos.line if st.else_pos else None)
            self.block(st.else_body)
        self.code.indent -= closers
        return first, top

    # ------------------------------------------------------------------ case
    def s_Case(self, st) -> tuple:
        imm = 1 if self.objt.compiled_at(st.pos)[:1] == b"\x38" else 2     # the end address: PUSH_IMM1 or 2
        head = [Op(0x37 + imm, self.T.push_imm[imm])] + self.expr_ops(st.value)
        data = bytes((0x37 + imm,)) + bytes(imm) + self.last_data   # (calls come after the end address push)
        with self.timed_statement(head) as timed:
            sel_x = self.expr(st.value)
        sel = self.wrapped(sel_x).text
        if not (sel.isidentifier() or sel.startswith("self.") and sel[5:].isidentifier()):
            tmp = self.temp("selector")
            self.hoisted.append(Event(f"{tmp} = {sel}") if timed and self.is_event(st.value) else f"{tmp} = {sel}")
            sel = tmp
        first, ln = self.emit_hoisted(st)
        if first is not None:               # the selector computed on lines of its own: paid there
            head = self.charge_decision(head, data, first, range(first, ln + 1), timed)
        items = [it for it in st.items if it.values is not None]
        other = next((it for it in st.items if it.values is None), None)
        header = top = body_last = None
        tests = []
        for item in items:
            conds, per_value = [], []
            # is each compare's jump to the body the two-byte form? (as the compiler laid it out)
            long_values = list(self.objt.long_jumps_at(item.pos, "case value"))
            long_ranges = list(self.objt.long_jumps_at(item.pos, "case range"))
            for v in item.values:
                ops = []
                if isinstance(v, A.Range):
                    # a value Spin reaches only when the ones before it did not match: lazy()
                    lo, hi = self.wrapped(self.lazy(v.low)).text, self.wrapped(self.lazy(v.high)).text
                    clo, chi = self.constant(v.low), self.constant(v.high)
                    if clo is not None and chi is not None and clo > chi:
                        lo, hi = hi, lo
                    if clo is not None and chi is not None:
                        conds.append(f"{lo} <= {sel} <= {hi}")
                    else:
                        conds.append(f"spin.within({sel}, {lo}, {hi})")
                    ops += self.expr_ops(v.low, item.pos) + self.expr_ops(v.high, item.pos) + \
                        [jump_op(self.T, "CASE_RANGE", long_ranges.pop(0) if long_ranges else False)]
                    per_value.append(ops)
                elif isinstance(v, A.Str) and len(self.obj.char_bytes(v.text)) > 1:
                    for b in self.obj.char_bytes(v.text):   # "abc": one value per character, as compiled
                        conds.append(f"{sel} == {b}")
                        per_value.append(self.expr_ops(A.Number(v.pos, b, str(b)), item.pos) + [
                            jump_op(self.T, "CASE_VALUE", long_values.pop(0) if long_values else False)])
                else:
                    conds.append(f"{sel} == {self.wrapped(self.lazy(v)).text}")
                    ops += self.expr_ops(v, item.pos) + [
                        jump_op(self.T, "CASE_VALUE", long_values.pop(0) if long_values else False)]
                    per_value.append(ops)
            tests.append((conds, per_value))
        for text in self.hoisted:           # local functions of values that assign (lazy())
            ln = self.emit(text, st)
            first = first or ln
        self.hoisted = []
        for n, (item, (conds, per_value)) in enumerate(zip(items, tests)):
            cond = " or ".join(conds)
            self.code.comments_before(item.pos.line)
            header = self.emit(f"{'if' if n == 0 else 'elif'} {cond}:", item)
            top = top or header
            first = first or header
            per_value = [_around_event(ops) for ops in per_value]
            if len(per_value) == 1 and not isinstance(per_value[0], tuple):
                self.charge(header, "b", (head if n == 0 else []) + per_value[0])
            else:                       # each value is compared only if the ones before it failed
                self.charge(header, "b", head if n == 0 else [])
                self.code.charge_each(header, per_value)
            with self.holding(8):
                _, body_last = self.block(item.body)
            self.charge(body_last, "a", [jump_op(self.T, "CASE_DONE")])
        if other is not None:
            self.code.comments_before(other.pos.line)
            if items:
                self.code.line("else:", other.pos.line)
                with self.holding(8):
                    _, body_last = self.block(other.body)
            else:
                self.charge(self.emit("pass", other), "b", head)
                with self.holding(8):
                    body_last = self.statement_list(other.body)
            self.charge(body_last, "a", [jump_op(self.T, "CASE_DONE")])
        elif header is not None:
            self.charge(header, "e", [jump_op(self.T, "CASE_DONE")])
        else:                               # no branch at all: the selector, then CASE_DONE
            body_last = self.emit("pass", st)
            self.charge(body_last, "b", head + [jump_op(self.T, "CASE_DONE")])
            first = first or body_last
        return first, top or body_last

    @contextmanager
    def holding(self, n: int):
        """Translate a body run while the statement around it keeps ``n`` more bytes on the stack."""
        self.held += n
        try:
            yield
        finally:
            self.held -= n

    def statement_list(self, stmts):
        last = None
        for s in stmts:
            _, last = self.statement(s)
        return last

_ITEMS = object()       # the code position of a lookup's items that the runtime pays (see _Compiler)


class _Compiler(cstmts.MethodCompiler):
    """The compiler's method compiler, used to price pieces of a method.

    The items of the lookups in ``lazy`` (ids of nodes) are compiled with the
    code position ``_ITEMS`` (from the end of the lookup's value up to its
    LOOK_DONE, which stays where the lookup is), so that the translator can
    leave them out of a statement's price but still lay them out where they
    are.
    """

    lazy = frozenset()

    def x_Lookup(self, node) -> None:
        if id(node) not in self.lazy:
            return super().x_Lookup(node)
        code, pos = self.code, self.code.pos
        had = "expr" in self.__dict__           # a lookup around this one watches its own value
        inner = self.expr

        def expr(n):
            inner(n)
            if n is node.value:
                code.pos = _ITEMS

        self.expr = expr
        try:
            super().x_Lookup(node)
            # its LOOK_DONE (before the end label) belongs to where the lookup is, not to its items: a
            # lookup that is another lazy lookup's value keeps it (a match gives it back)
            done = next(item for item in reversed(code.items) if item[1])
            if done[1] == b"\x0f":
                done[2] = pos
        finally:
            if had:
                self.expr = inner
            else:
                del self.expr
            code.pos = pos


def _around_event(ops):
    """A case value's compare: its ops, or ``(before, after)`` its last call, register write or read when
    the value has one (paid before the value and once it is computed, before the compare)."""
    for j in range(len(ops) - 1, -1, -1):
        if ops[j].kind in ("call", "write", "read", "look"):
            cut = j + 1 if ops[j].kind in ("call", "write") else j
            return (ops[:cut], ops[cut:])
    return ops


def _events(ops) -> list:
    return [o.kind for o in ops if o.kind]


def _calls_only(ops) -> bool:
    """Are the timed events of ``ops`` all calls of methods or of helpers that pay cycles (the weaver
    pays each one's run as it starts: ``call_at(..., spin_pay=k)``, ``pay_call(k, spin.div, a, b)``)?"""
    return all(k in ("call", "paid") for k in _events(ops))


def _one_event(ops) -> bool:
    """Can one charge before and one after place every timed event of ``ops`` (costs.split, split_read)?

    Yes for one event, and for a register read followed by one other event
    (the read pays from itself up to the other, as in ``waitcnt(cnt + x)``),
    with any bytecodes a helper pays (a division) before the charge's cut.
    """
    j = anchor_at(ops)
    if j is None:
        return True
    if any(o.kind == "paid" for o in ops[j + 1:]):
        return False            # a helper would add its cycles before the charge after the anchor is paid
    kinds = [k for k in _events(ops) if k != "paid"]
    return len(kinds) <= 1 or len(kinds) == 2 and kinds[0] == "read" and kinds[1] != "read"


def _segments(ops) -> tuple:
    """``(runs, kinds)``: ``ops`` cut at each timed event: a call, a register write or a bytecode a helper
    pays (a division) after its bytecode (the callee runs, the pins change, the helper adds its cycles,
    at its end), a register read, a wait, a cog start or stop or a
    lookup paid item by item before it; ``runs`` has one run more than ``kinds``.  Waits are paid by
    their helper."""
    runs, kinds, run = [], [], []
    for o in ops:
        if o.kind in ("call", "write", "paid"):
            run.append(o)
            runs.append(run)
            run = []
        elif o.kind:
            runs.append(run)
            run = [] if o.kind == "wait" else [o]
        else:
            run.append(o)
        if o.kind:
            kinds.append(o.kind)
    runs.append(run)
    return runs, kinds


def _lookup_calls(text: str) -> list:
    """The ``spin.lookup(...)``-like calls in a line of Python, left to right by where they start."""
    opened, calls, quote, i = [], [], None, 0     # opened: (start of a call or None, its paren depth)
    depth = 0
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == "\\":
                i += 1
            elif ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif text.startswith("spin.look", i):
            opened.append((i, depth + 1))
            i = text.index("(", i) - 1
        elif ch == "(":
            depth += 1
        elif ch == ")":
            if opened and opened[-1][1] == depth:
                start, _ = opened.pop()
                calls.append((start, text[start:i + 1]))
            depth -= 1
        i += 1
    return [c for _, c in sorted(calls)]


def needs_hub_frame(method) -> bool:
    """Does ``method`` need its locals in hub RAM (a local array, ``@local``, ``local[i]``, ``local.byte``)?"""
    if any(loc.count is not None for loc in method.locals):
        return True
    names = {key(p) for p, _ in method.params} | {key(loc.name) for loc in method.locals} | {"result"}
    if method.result:
        names.add(key(method.result))

    def local_ref(t):
        return isinstance(t, A.ResultRef) or (isinstance(t, A.NameRef) and key(t.name) in names)

    for n in A.walk(method.body):
        if isinstance(n, A.AddrOf) and local_ref(n.target.expr if isinstance(n.target, A.Paren) else n.target):
            return True
        if isinstance(n, (A.NameRef, A.ResultRef)) and n.index is not None and local_ref(n):
            return True
        if isinstance(n, A.MemberRef) and local_ref(n.base):
            return True
    return False
