"""Spin's ``repeat`` loops as Python loops, and what each pass costs (a mix-in of stmts.MethodTranslator).

==========================  ==============================================  ==============================
Spin                        Python                                          charged
==========================  ==============================================  ==============================
``repeat``                  ``while True:``                                 JMP after the body
``repeat n``                ``for _ in range(n):``                          n + TJZ; DJNZ per pass
``repeat while c``          ``while c:`` (``while True: ... break`` when    c + JZ per evaluation; JMP
                            the test has side effects or calls)
``repeat ... until c``      ``while True: ...; if c: break``                c + JZ per pass
``repeat x from a to b``    ``for x in range(a, b + 1):`` (constant         REPEAT per pass, the exit in
                            bounds) or ``while True`` + ``spin.repeat_step`` the loop's ``else:``
==========================  ==============================================  ==============================

Jumps are priced short or long as the compiler laid them out (the compiled object says).
"""
from __future__ import annotations

from ..compiler.code import Label
from ..compiler.exprs import USING
from ..frontend import ast as A
from ..frontend.ast import key
from .costs import Op, jump_op, split
from .exprs import X


def assigns(stmts, name: str) -> bool:
    """Does any statement in ``stmts`` assign the variable ``name`` (lower case)?"""
    for n in A.walk(stmts):
        t = getattr(n, "target", None) if isinstance(n, (A.Assign, A.PreOp, A.PostOp)) else \
            n.var if isinstance(n, A.RepeatFrom) else None
        if isinstance(t, A.NameRef) and key(t.name) == name:
            return True
    return False

__all__ = ["LoopTranslator"]


class _LoopInfo:
    """An open loop: what a ``next`` costs after its jump, and for loops whose test Python's
    ``continue`` would skip, ``emit_next(lead_ops)`` writes that test before the ``continue``."""

    def __init__(self, kind, next_ops=()):
        self.kind = kind
        self.next_ops = list(next_ops)
        self.emit_next = None


class LoopTranslator:
    """The ``s_Repeat*`` statement handlers (needs the MethodTranslator around it)."""

    def loop_block(self, body, info):
        self.loops.append(info)
        try:
            return self.block(body)
        finally:
            self.loops.pop()

    def s_RepeatForever(self, st) -> tuple:
        line = self.emit("while True:", st)
        _, last = self.loop_block(st.body, _LoopInfo("forever"))
        self.charge(last, "a", [jump_op(self.T, "JMP", self.long_jump(st.pos, "repeat"))])
        return line, line

    def s_RepeatCount(self, st) -> tuple:
        T = self.T
        c = self.constant(st.count)
        ops = self.expr_ops(st.count) + [jump_op(T, "TJZ", self.long_jump(st.pos, "repeat n"), False)]
        data = self.last_data
        with self.timed_statement(ops) as timed:
            n = self.expr(st.count)
            if self.effects(st.count).events and not n.saved:
                # a call (a register read ...) on a line of its own: paid before it, the rest before the loop
                tmp = self.temp("count")
                self.hoisted.append(self.line(f"{tmp} = {n.text}", self.is_event(st.count)))
                n = X(tmp, wrapped=n.wrapped, boolean=n.boolean, truthy=n.truthy, saved=True)
        count = n.text if c is not None and c >= 0 else f"spin.u32({self.wrapped(n).text})"
        first, last = self.emit_hoisted(st)
        line = self.emit(f"for _ in range({count}):", st)
        long_back = self.long_jump(st.pos, "repeat n", 1)
        djnz_t, djnz_n = jump_op(T, "DJNZ", long_back, True), jump_op(T, "DJNZ", long_back, False)
        if first is None:
            self.charge(line, "b", ops)
        else:
            self.charge(line, "b", self.charge_decision(ops, data, first, range(first, last + 1), timed))
        info = _LoopInfo("count", next_ops=[djnz_t])
        with self.holding(4):               # the count stays on the stack while the body runs
            _, last = self.loop_block(st.body, info)
        self.charge(last, "a", [djnz_t])
        self.charge_add(line, "e", djnz_n.rest - djnz_t.rest)
        return first or line, line

    def s_RepeatWhile(self, st) -> tuple:
        T = self.T
        cond_ops = self.expr_ops(st.cond, st.cond.pos if st.post else None)    # (a post test is at the loop's end)
        if st.post:
            long_j = self.long_jump(st.cond.pos, "repeat while")
            line = self.emit("while True:", st)
            info = _LoopInfo("post")
            info.emit_next = lambda lead: self._post_test(st, cond_ops, long_j, lead)
            _, last = self.loop_block(st.body, info)
            self.code.indent += 1
            self._post_test(st, cond_ops, long_j, [])
            self.code.indent -= 1
            return line, line
        j = "JNZ" if st.until else "JZ"
        c = self.cond(st.cond)
        test = (f"not ({c})" if " " in c else f"not {c}") if st.until else c
        long_j = self.long_jump(st.pos, "repeat while")
        jz_not = jump_op(T, j, long_j, False)
        jz_taken = jump_op(T, j, long_j, True)
        back = jump_op(T, "JMP", self.long_jump(st.pos, "repeat"))
        if self.hoisted or any(o.kind for o in cond_ops):
            line = self.emit("while True:", st)
            self.code.indent += 1
            hoisted, self.hoisted = self.hoisted, []
            first = None
            for h in hoisted:
                ln = self.emit(h, st)
                first = first or ln
            leave = c if st.until else (f"not ({c})" if " " in c else f"not {c}")
            iff = self.emit(f"if {leave}:", st)
            self.code.indent += 1
            brk = self.emit("break", st)
            self.code.indent -= 2
            pre, post = split(cond_ops + [jz_not])
            self.charge(first or iff, "b", pre)
            self.charge(brk, "b", post)
            self.charge_add(brk, "b", jz_taken.rest - jz_not.rest)
            if st.body:
                body_first, last = self.loop_block(st.body, _LoopInfo("while"))
                self.charge(body_first, "b", post, first=True)
            else:                       # ``repeat until x``: the loop is just its test
                self.charge(iff, "a", post)
                last = iff
        else:
            line = self.emit(f"while {test}:", st)
            body_first, last = self.loop_block(st.body, _LoopInfo("while"))
            self.charge(line, "t", cond_ops + [jz_not])
            self.charge_add(line, "e", jz_taken.rest - jz_not.rest)
        self.charge(last, "a", [back])
        return line, line

    def s_RepeatFrom(self, st) -> tuple:
        T = self.T
        a, b = self.constant(st.start), self.constant(st.stop)
        s = self.constant(st.step) if st.step is not None else 1
        var = st.var
        count = _from_to_count(a, b, s)
        simple = (count is not None and isinstance(var, A.NameRef)
                  and var.index is None and self.lookup(var.name, var)[0] in ("local", "var", "dat")
                  and not assigns(st.body, key(var.name)))
        init = self.piece(lambda: (self.mc.expr(st.start), self.mc.var(var, 1)))
        step_piece = self.piece(lambda: self._step_code(st), inside=True)
        long_back = self.long_jump(st.pos, "repeat from")
        step_ops = self._fix_repeat(step_piece, st, long_back, True)
        exit_ops = self._fix_repeat(step_piece, st, long_back, False)
        delta = exit_ops[-1].rest - step_ops[-1].rest
        target = self.expr(var).text
        if simple:
            step = s if a <= b else -s
            final = a + count * step
            rng = f"range({a}, {final}" + (f", {step})" if step != 1 else ")")
            line = self.emit(f"for {target} in {rng}:", st)
            self.charge(line, "b", init)
            _, last = self.loop_block(st.body, _LoopInfo("from", next_ops=step_ops))
            self.charge(last, "a", step_ops)
            if not self.is_local(var) or self.objt.read_after(self.method, st, key(var.name)):
                self.code.line("else:", None)
                self.code.indent += 1
                self.code.line(f"{target} = {final}  # Spin leaves the counter one step past the end", None)
                self.code.indent -= 1
            self.charge_add(line, "e", delta)
            return line, line
        start, stop_t = self.value(st.start), self.value(st.stop)
        step_t = self.value(st.step) if st.step is not None else None
        first, _ = self.flush(f"{target} = {start}", st)
        self.charge(first, "b", init)
        line = self.emit("while True:", st)
        info = _LoopInfo("general")
        info.emit_next = lambda lead: self._from_step(st, target, start, stop_t, step_t, step_ops, delta, lead)
        _, last = self.loop_block(st.body, info)
        self.code.indent += 1
        self._from_step(st, target, start, stop_t, step_t, step_ops, delta, [])
        self.code.indent -= 1
        return first, line

    def _post_test(self, st, cond_ops, long_j: bool, lead) -> int:
        """``[hoisted]; if <leave>: break`` of ``repeat ... while/until c``; ``lead``: ops paid first (a ``next``)."""
        T = self.T
        j = "JZ" if st.until else "JNZ"          # jumps back to the top while the loop goes on
        c = self.cond(st.cond)
        test = c if st.until else (f"not ({c})" if " " in c else f"not {c}")
        first, _ = self.flush(None, st.cond) if self.hoisted else (None, None)
        iff = self.emit(f"if {test}:", st.cond)
        pre, post = split(list(lead) + cond_ops + [jump_op(T, j, long_j, True)])
        self.charge(first or iff, "b", pre)
        self.charge(iff, "e", post)
        self.code.indent += 1
        brk = self.emit("break", st.cond)
        self.charge(brk, "b", post)
        self.charge_add(brk, "b", jump_op(T, j, long_j, False).rest - jump_op(T, j, long_j, True).rest)
        self.code.indent -= 1
        return first or iff

    def _from_step(self, st, target, start, stop_t, step_t, step_ops, delta, lead) -> int:
        """``x, again = spin.repeat_step(...); if not again: break`` of a general ``repeat x from``."""
        args = f"{target}, {start}, {stop_t}" + (f", {step_t}" if step_t else "")
        again = self.temp("again")
        ln = self.emit(f"{target}, {again} = spin.repeat_step({args})", st)
        self.charge(ln, "b", list(lead) + step_ops)
        self.emit(f"if not {again}:", st)
        self.code.indent += 1
        brk = self.emit("break", st)
        self.charge_add(brk, "b", delta)
        self.code.indent -= 1
        return ln

    def _step_code(self, st) -> None:
        mc = self.mc
        top = Label("top")
        mc.code.mark(top)
        if st.step is not None:
            mc.expr(st.step)
        mc.expr(st.start)
        mc.expr(st.stop)
        mc.var(st.var, USING)
        mc.code.jump(bytes((0x06 if st.step is not None else 0x02,)), top, "repeat from")

    def _fix_repeat(self, ops, st, long: bool, inside: bool) -> list:
        """The step ops with the REPEAT operator priced as looping back (``inside``) or leaving."""
        reg = isinstance(st.var, A.RegRef)
        stepped = st.step is not None
        last = ops[-1]
        base = last.rest - self.T.repeat[(reg, stepped, True, False)]
        return ops[:-1] + [Op(last.code, base + self.T.repeat[(reg, stepped, inside, long)], last.kind)]



def _from_to_count(a, b, s):
    """How many times ``repeat x from a to b step s`` runs with constant bounds (None: not constant or endless)."""
    if a is None or b is None or s is None:
        return None
    low, high = min(a, b), max(a, b)
    delta = s if a <= b else -s
    if delta == 0:
        return None
    x, n = a, 0
    while low <= x <= high:
        n += 1
        x += delta
        if n > 1 << 20:
            return None
    return n
