"""PBASIC syntax tree -> :class:`Program`: a flat list of instructions with
resolved jumps, plus the RAM map and the EEPROM image.

The control structures are paired here, statement by statement, with a stack
of open blocks, as Parallax's tokenizer does; its error messages and limits
are reproduced (``'FOR' without 'NEXT'`` at the FOR, 255 GOSUBs, 16 nested
IFs/FORs/DOs/SELECTs, the per-argument expression-stack limits of
:data:`ARG_DEPTH`).  Command arguments are compiled by :mod:`.cmdcompile`.

Each instruction is an :class:`Instr` whose ``fn(m)`` returns the next
program counter, or None for "the next instruction".  Jumps go through
:class:`Target` objects that are bound once the destination is known.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional

from ..diagnostics import CompileError
from . import access
from . import messages as M
from . import nodes as N
from .exprs import ExprContext, Leaf, as_function, check_depth, compile_expr
from .symbols import SymbolTable, Var
from .words import RESERVED

__all__ = ["Instr", "Target", "Program", "compile_program", "ARG_DEPTH"]

#: Deepest expression each argument accepts (default 8), measured with
#: Parallax's tokenizer (nest 1+(2+(...)) until error 144 "Expression is too
#: complex"); the BS2 evaluates on an 8-entry stack and some arguments are
#: already pending when others are evaluated.
ARG_DEPTH = {
    "index": 7,
    "pulsout.pin": 7, "pulsin.pin": 7, "rctime.pin": 7, "count.pin": 7,
    "write.address": 7, "for.start": 7, "for.step": 5, "for.index": 5,
    "lookup.value": 6, "lookdown.value": 5,
    "case.value": 7, "case.more": 6, "case.high": 6,
    "debug.item": 7, "debug.rep.count": 6, "debug.str.length": 7, "debug.rep.char": 8,
    "serout.pin": 5, "serout.baud": 6, "serout.pace": 7, "serout.item": 7,
    "serout.fpin": 4, "serout.timeout": 7, "serout.rep.count": 6, "serout.str.length": 7,
    "serin.pin": 4, "serin.baud": 5, "serin.fpin": 3, "serin.timeout": 6,
    "serin.str.length": 6, "serin.skip": 7, "serin.wait": 3, "serin.wait.more": 4,
    "serin.waitstr.length": 7, "debugin.str.length": 6,
    "freqout.duration": 7, "freqout.freq1": 6, "freqout.freq2": 5,
    "dtmfout.on": 6, "dtmfout.off": 7, "dtmfout.tone": 5,
    "shiftout.dpin": 7, "shiftout.cpin": 6, "shiftout.value": 4, "shiftout.bits": 5,
    "shiftin.dpin": 7, "shiftin.cpin": 6, "shiftin.index": 3, "shiftin.bits": 5,
    "button.pin": 3, "button.delay": 7, "button.rate": 6, "button.target": 5,
    "button.index": 4, "pwm.pin": 6, "pwm.cycles": 7,
}

#: Statements that exist only in PBASIC 2.5.
ONLY_25 = {"do": "DO", "loop": "LOOP", "exit": "EXIT", "select": "SELECT", "case": "CASE",
           "case_else": "CASE", "endselect": "ENDSELECT", "elseif": "ELSEIF", "else_": "ELSE",
           "endif": "ENDIF", "on_goto": "ON", "on_gosub": "ON", "decl_pin": "PIN",
           "if_block": "IF ... THEN (block)", "if_inline": "IF ... THEN statement"}

_LIMIT_NEST = 16


class Target:
    """A jump destination, bound when its program counter is known."""

    __slots__ = ("pc",)

    def __init__(self, pc: Optional[int] = None):
        self.pc = pc


@dataclass
class Instr:
    """One BS2 instruction: timing ``kind``, body ``fn(m) -> next pc | None``."""

    kind: str
    fn: Callable
    pos: N.Pos
    text: str = ""


@dataclass
class Program:
    """A compiled PBASIC program, ready for :func:`spinemu.pbasic.run_file`.

    Attributes:
        path, source: where it came from.
        language: "2.0" or "2.5".
        code: the instructions; execution starts at ``code[0]``.
        symbols: names, RAM views and constants.
        eeprom: the 2048-byte image DATA defines (zeros elsewhere).
        defined: 2048 flags, 1 where DATA defined a byte.
        returns: GOSUB return points by GOSUB id (id 0 = program start).
        n_gosubs: GOSUB statements in the text (at most 255).
    """

    path: str
    source: str
    language: str
    code: list
    symbols: SymbolTable
    eeprom: bytes
    defined: bytes
    returns: list
    n_selects: int = 0
    n_gosubs: int = 0
    pin_names: dict = field(default_factory=dict)

    @property
    def var_counts(self) -> dict:
        """``{"words": n, "bytes": n, "nibbles": n, "bits": n}`` as the tokenizer reports."""
        return dict(self.symbols.counts)

    def variables(self) -> list:
        """``(name, byte address, bit, width, type)`` of every user variable and alias."""
        out = []
        for name, var, type_name in self.symbols.variables():
            out.append((name, var.bitoff // 8, var.bitoff % 8, var.width, type_name, var.count))
        return out

    def memory_map(self) -> str:
        """A text RAM map like the BASIC Stamp editor's (Ctrl-M)."""
        lines = ["RAM map (byte.bit, width):"]
        for name, byte, bit, width, type_name, count in self.variables():
            arr = f"({count})" if count > 1 else ""
            lines.append(f"  {name:<16} {byte:2d}.{bit:<2d} {width:2d} bits  {type_name}{arr}")
        c = self.var_counts
        lines.append(f"  words {c['words']}, bytes {c['bytes']}, nibbles {c['nibbles']}, bits {c['bits']}")
        data = [i for i in range(2048) if self.defined[i]]
        if data:
            lines.append(f"EEPROM DATA: {len(data)} bytes, {min(data)}..{max(data)}")
        return "\n".join(lines)


@dataclass
class _Frame:
    kind: str                  # IF, INLINE, SELECT, DO, FOR
    pos: N.Pos
    end: Target = field(default_factory=Target)
    false: Optional[Target] = None       # IF: where the failing test goes
    else_seen: bool = False
    count: int = 0                       # ELSEIFs / CASEs / EXITs
    top: Optional[Target] = None         # DO: the loop top; FOR: the body
    slot: int = 0                        # SELECT: m.sel index
    case_stmt: int = -1                  # SELECT: statement counter at the last CASE
    case_pos: Optional[N.Pos] = None
    next: Optional[Callable] = None      # FOR: the NEXT body factory


class Compiler(ExprContext):
    """Turns a parsed program into a :class:`Program`."""

    def __init__(self, tree: N.Program):
        self.tree = tree
        self.syms = SymbolTable(tree.path, tree.source)
        self.code: list[Instr] = []
        self.frames: list[_Frame] = []
        self.labels: dict[str, Target] = {}
        self.returns: list[Target] = [Target(0)]
        self.n_selects = 0
        self.stmt_count = 0
        self._pin_ctx = False

    # ------------------------------------------------------------ errors
    def error(self, message: str, pos: Optional[N.Pos]) -> CompileError:
        return self.syms.error(message, pos)

    def warner(self, pos: N.Pos) -> Callable:
        return lambda m, msg: m.warn(pos, msg)

    # ------------------------------------------------------------ names
    def leaf(self, ref: N.Ref) -> Leaf:
        sym = self.syms.lookup(ref.name)
        if sym is None:
            if ref.key in RESERVED:
                raise self.error(M.RESERVED_AS_VALUE.format(ref.key, RESERVED[ref.key]), ref.pos)
            raise self.error(M.UNDEFINED.format(ref.name), ref.pos)
        if sym.kind == "label":
            raise self.error(M.LABEL_AS_VALUE.format(ref.name), ref.pos)
        if sym.kind in ("const", "data") or (sym.kind == "pin" and self._pin_ctx):
            if ref.mods:
                raise self.error(M.MODIFIER_ON_CONSTANT.format(ref.name), ref.mods[0][1])
            if ref.index is not None:
                raise self.error(M.INDEX_ON_CONSTANT.format(ref.name), ref.pos)
            return Leaf(const=self.syms.const_value(ref.name))
        var = self._view(sym, ref, value=True)
        index = as_function(compile_expr(ref.index, self)) if ref.index is not None else None
        return Leaf(read=access.reader(var.bitoff, var.width, index, self.warner(ref.pos)))

    def _view(self, sym, ref: N.Ref, value: bool) -> Var:
        if sym.kind == "pin":
            pin = self.syms.const_value(ref.name)
            base = Var(pin if value else 16 + pin, 1)          # INx to read, OUTx to write
        else:
            base = sym.var
        return base.modified(ref.mods, self.error)

    def target(self, ref: N.Ref, slot: str = "index") -> tuple[Callable, Callable, int]:
        """An assignable view: ``(write(m, v), read(m), width)``."""
        sym = self.syms.lookup(ref.name)
        if sym is None:
            raise self.error(M.UNDEFINED.format(ref.name), ref.pos)
        if sym.kind not in ("var", "pin"):
            raise self.error(M.EXPECTED_VARIABLE, ref.pos)
        var = self._view(sym, ref, value=False)
        index = None
        if ref.index is not None:
            self.check(ref.index, ARG_DEPTH.get(slot, ARG_DEPTH["index"]))
            index = as_function(compile_expr(ref.index, self))
        warn = self.warner(ref.pos)
        return (access.writer(var.bitoff, var.width, index, warn),
                access.reader(var.bitoff, var.width, index, warn), var.width)

    def array_view(self, name_tok) -> Var:
        sym = self.syms.lookup(str(name_tok))
        pos = N.Pos(name_tok.line, name_tok.column, len(str(name_tok)))
        if sym is None:
            raise self.error(M.UNDEFINED.format(str(name_tok)), pos)
        if sym.kind != "var":
            raise self.error(M.EXPECTED_VARIABLE, pos)
        return sym.var

    def label_target(self, tok) -> Target:
        """The jump target of a label name (a token, or a bare Ref)."""
        if isinstance(tok, N.Ref):
            name, pos = tok.name, tok.pos
        else:
            name = str(tok)
            pos = N.Pos(tok.line, tok.column, len(name))
        sym = self.syms.lookup(name)
        if sym is None:
            raise self.error(M.UNDEFINED_LABEL.format(name), pos)
        if sym.kind != "label":
            raise self.error(M.EXPECTED_LABEL, pos)
        return self.labels[name.upper()]

    # ------------------------------------------------------------ expressions
    def check(self, e, limit: int = 8) -> None:
        def fail(pos):
            raise self.error(M.EXPRESSION_TOO_COMPLEX, pos)
        check_depth(e, 8 - limit, fail)

    def expr(self, e, slot: Optional[str] = None) -> Callable:
        """Compile an argument expression (depth-checked) to ``f(m)``."""
        self.check(e, ARG_DEPTH.get(slot, 8) if slot else 8)
        return as_function(compile_expr(e, self))

    def const_or_fn(self, e, slot: Optional[str] = None):
        self.check(e, ARG_DEPTH.get(slot, 8) if slot else 8)
        return compile_expr(e, self)

    def pin(self, e, slot: Optional[str] = None, highest: int = 15) -> Callable:
        """A pin argument: PIN names are their numbers here."""
        from .commands import pin_arg
        self._pin_ctx = True
        try:
            f = self.expr(e, slot)
        finally:
            self._pin_ctx = False
        return pin_arg(f, self.warner(_pos_of(e)), highest)

    # ------------------------------------------------------------ emitting
    def emit(self, kind: str, fn: Callable, st) -> int:
        self.code.append(Instr(kind, fn, st.pos, getattr(st, "text", "")))
        return len(self.code) - 1

    def bind(self, t: Target) -> None:
        t.pc = len(self.code)

    def jump(self, t: Target, st, kind: str = "goto") -> None:
        self.emit(kind, lambda m: t.pc, st)

    # ------------------------------------------------------------ driver
    def compile(self) -> Program:
        items = self.tree.items
        self.syms.build(items)
        for it in items:
            if isinstance(it, N.Label):
                self.labels[it.name.upper()] = Target()
        for it in items:
            self.statement(it)
        if self.frames:
            f = self.frames[-1]
            raise self.error(M.WITHOUT.format(*_OPEN_CLOSE[f.kind]), f.pos)
        if not self.code:
            raise self.error(M.NOTHING_TO_TOKENIZE, N.Pos(1, 1))
        self.emit("end", _fall_off_end, N.Stmt("end", self.tree.items[-1].pos if items else N.Pos(1, 1)))
        gosubs = len(self.returns) - 1
        return Program(self.tree.path, self.tree.source, self.tree.language, self.code, self.syms,
                       bytes(self.syms.eeprom), bytes(self.syms.defined), self.returns,
                       self.n_selects, gosubs, self._pin_names())

    def _pin_names(self) -> dict:
        out = {}
        for sym in self.syms.symbols.values():
            if sym.kind == "pin" and sym.pos is not None:
                out[sym.value] = sym.name
        return out

    def statement(self, st) -> None:
        if isinstance(st, N.Label):
            self._select_needs_case(st)
            self.bind(self.labels[st.name.upper()])
            return
        if st.kind.startswith("decl_"):
            if st.kind == "decl_pin" and self.tree.language != "2.5":
                raise self.error(M.NEEDS_25.format("PIN"), st.pos)
            return
        if self.tree.language != "2.5" and st.kind in ONLY_25:
            raise self.error(M.NEEDS_25.format(ONLY_25[st.kind]), st.pos)
        if st.kind not in ("case", "case_else", "endselect"):
            self._select_needs_case(st)
        self.stmt_count += 1
        handler = getattr(self, "s_" + st.kind, None)
        if handler is None:
            from . import cmdcompile
            handler = cmdcompile.HANDLERS.get(st.kind)
            if handler is None:
                raise self.error(M.NOT_SUPPORTED.format(st.kind.upper()), st.pos)
            handler(self, st)
            return
        handler(st)

    def _select_needs_case(self, st) -> None:
        if self.frames and self.frames[-1].kind == "SELECT" and self.frames[-1].count == 0:
            raise self.error(M.EXPECTED_CASE, st.pos)

    # ------------------------------------------------------------ frames
    def push(self, frame: _Frame) -> _Frame:
        same = sum(1 for f in self.frames if f.kind == frame.kind)
        if same >= _LIMIT_NEST:
            raise self.error(M.TOO_MANY_NESTED[frame.kind], frame.pos)
        self.frames.append(frame)
        return frame

    def top(self, kinds: tuple, st, word: str, opener: str) -> _Frame:
        """The innermost open block, which must be one of ``kinds``."""
        if not self.frames or self.frames[-1].kind not in kinds:
            if any(f.kind in kinds for f in self.frames):
                f = self.frames[-1]
                raise self.error(M.WITHOUT.format(*_OPEN_CLOSE[f.kind]), f.pos)
            raise self.error(M.MUST_FOLLOW.format(word, opener), _word_pos(st, word))
        return self.frames[-1]

    # ------------------------------------------------------------ assignment, jumps
    def s_assign(self, st) -> None:
        ref, e = st.args
        write, _, _ = self.target(ref)
        f = self.expr(e)
        self.emit("assign", lambda m: write(m, f(m)), st)

    def s_goto(self, st) -> None:
        self.jump(self.label_target(st.args[0]), st)

    def _gosub_id(self, st) -> tuple[int, Target]:
        if len(self.returns) > 255:
            raise self.error(M.TOO_MANY_GOSUBS, st.pos)
        ret = Target()
        self.returns.append(ret)
        return len(self.returns) - 1, ret

    def s_gosub(self, st) -> None:
        tgt = self.label_target(st.args[0])
        gid, ret = self._gosub_id(st)
        push = _gosub_push(self.warner(st.pos))

        def run(m):
            push(m, gid)
            return tgt.pc
        self.emit("gosub", run, st)
        self.bind(ret)

    def s_return(self, st) -> None:
        returns = self.returns
        warn = self.warner(st.pos)

        def run(m):
            m.gosub_ptr = (m.gosub_ptr - 1) & 3
            gid = m.gosub_slots[m.gosub_ptr]
            if m.gosub_depth == 0:
                if m.gosub_model == "restart" or gid == 0:
                    warn(m, M.W_RETURN_UNDERFLOW.format(M.W_RETURN_RESTART))
                    return 0
                warn(m, M.W_RETURN_UNDERFLOW.format(M.W_RETURN_STALE))
            else:
                m.gosub_depth -= 1
            return returns[gid].pc
        self.emit("return", run, st)

    def s_on_goto(self, st) -> None:
        f = self.expr(st.args[0])
        targets = [self.label_target(t) for t in st.args[1:]]
        n = len(targets)
        self.emit("on", lambda m: targets[i].pc if (i := f(m)) < n else None, st)

    s_branch = s_on_goto

    def s_on_gosub(self, st) -> None:
        f = self.expr(st.args[0])
        targets = [self.label_target(t) for t in st.args[1:]]
        n = len(targets)
        gid, ret = self._gosub_id(st)
        push = _gosub_push(self.warner(st.pos))

        def run(m):
            i = f(m)
            if i >= n:
                return None
            push(m, gid)
            return targets[i].pc
        self.emit("on", run, st)
        self.bind(ret)

    # ------------------------------------------------------------ IF
    def _test(self, cond, jump_if: bool, t: Target, st, kind: str = "if") -> None:
        self.check(cond)
        c, f = compile_expr(cond, self)
        if f is None:
            taken = bool(c) == jump_if
            self.emit(kind, (lambda m: t.pc) if taken else (lambda m: None), st)
        elif jump_if:
            self.emit(kind, lambda m: t.pc if f(m) else None, st)
        else:
            self.emit(kind, lambda m: None if f(m) else t.pc, st)

    def s_if_goto(self, st) -> None:
        self._test(st.args[0], True, self.label_target(st.args[-1]), st)

    def s_if_block(self, st) -> None:
        fr = self.push(_Frame("IF", _word_pos(st, "IF"), false=Target()))
        self._test(st.args[0], False, fr.false, st)

    def s_elseif(self, st) -> None:
        fr = self.top(("IF",), st, "ELSEIF", "IF")
        if fr.else_seen:
            raise self.error(M.EXPECTED_ENDIF, st.pos)
        fr.count += 1
        if fr.count > 16:
            raise self.error(M.TOO_MANY_ELSEIF, st.pos)
        self.jump(fr.end, st)
        self.bind(fr.false)
        fr.false = Target()
        self._test(st.args[0], False, fr.false, st)

    def s_else_(self, st) -> None:
        if not self.frames or self.frames[-1].kind != "IF":
            if not any(f.kind == "IF" for f in self.frames):
                raise self.error(M.ELSE_WITHOUT_IF, st.pos)
        fr = self.top(("IF",), st, "ELSE", "IF")
        if fr.else_seen:
            raise self.error(M.EXPECTED_ENDIF, st.pos)
        fr.else_seen = True
        self.jump(fr.end, st)
        self.bind(fr.false)
        fr.false = None

    def s_endif(self, st) -> None:
        fr = self.top(("IF",), st, "ENDIF", "IF")
        if fr.false is not None:
            self.bind(fr.false)
        self.bind(fr.end)
        self.frames.pop()

    def s_if_inline(self, st) -> None:
        cond, then_part, else_part = st.args
        depth = len(self.frames)
        fr = self.push(_Frame("INLINE", _word_pos(st, "IF"), false=Target()))
        self._test(cond, False, fr.false, st)
        for s in then_part:
            self.statement(s)
        self._close_inline(depth + 1)
        if else_part:
            self.jump(fr.end, st)
            self.bind(fr.false)
            fr.false = None
            for s in else_part:
                self.statement(s)
            self._close_inline(depth + 1)
        if fr.false is not None:
            self.bind(fr.false)
        self.bind(fr.end)
        self.frames.pop()

    def _close_inline(self, depth: int) -> None:
        if len(self.frames) > depth:
            f = self.frames[-1]
            raise self.error(M.WITHOUT.format(*_OPEN_CLOSE[f.kind]), f.pos)

    # ------------------------------------------------------------ SELECT
    def s_select(self, st) -> None:
        f = self.expr(st.args[0])
        slot = self.n_selects
        self.n_selects += 1
        self.push(_Frame("SELECT", _word_pos(st, "SELECT"), slot=slot))

        def run(m):
            m.sel[slot] = f(m)
        self.emit("select", run, st)

    def _case_prologue(self, st, word: str) -> _Frame:
        fr = self.top(("SELECT",), st, word, "SELECT")
        if fr.count:
            if fr.case_stmt == self.stmt_count - 1:
                raise self.error(M.STATEMENTS_AFTER_CASE, _word_pos(st, word))
            self.jump(fr.end, st)
        if fr.false is not None:
            self.bind(fr.false)
            fr.false = None
        fr.count += 1
        if fr.count > 16:
            raise self.error(M.TOO_MANY_CASES, st.pos)
        fr.case_stmt = self.stmt_count
        return fr

    def s_case(self, st) -> None:
        fr = self._case_prologue(st, "CASE")
        slot = fr.slot
        tests = []
        for i, item in enumerate(st.args):
            tests.append(self._case_test(item, first=(i == 0)))
        fr.false = Target()
        miss = fr.false

        def run(m):
            v = m.sel[slot]
            for t in tests:
                if t(m, v):
                    return None
            return miss.pc
        self.emit("case", run, st)

    def _case_test(self, item, first: bool) -> Callable:
        from .exprs import _COMPARE
        slot = "case.value" if first else "case.more"
        if item.kind == "case_eq":
            f = self.expr(item.args[0], slot)
            return lambda m, v: v == f(m)
        if item.kind == "case_cmp":
            op = {"=<": "<=", "=>": ">=", "><": "<>"}.get(str(item.args[0]), str(item.args[0]))
            cmp = _COMPARE[op]
            f = self.expr(item.args[1], slot)
            return lambda m, v: cmp(v, f(m)) != 0
        lo = self.expr(item.args[0], slot)
        hi = self.expr(item.args[1], "case.high")
        return lambda m, v: lo(m) <= v <= hi(m)

    def s_case_else(self, st) -> None:
        self._case_prologue(st, "CASE")

    def s_endselect(self, st) -> None:
        fr = self.top(("SELECT",), st, "ENDSELECT", "SELECT")
        if fr.count == 0 or fr.case_stmt == self.stmt_count - 1:
            msg = M.EXPECTED_CASE if fr.count == 0 else M.STATEMENTS_AFTER_CASE
            raise self.error(msg, st.pos)
        if fr.false is not None:
            self.bind(fr.false)
        self.bind(fr.end)
        self.frames.pop()

    # ------------------------------------------------------------ DO / LOOP / EXIT
    def s_do(self, st) -> None:
        fr = self.push(_Frame("DO", _word_pos(st, "DO"), top=Target()))
        self.bind(fr.top)
        test, cond = st.args
        if test is None:
            self.emit("do", lambda m: None, st)
        else:
            self._test(cond, str(test).upper() == "UNTIL", fr.end, st)

    def s_loop(self, st) -> None:
        fr = self.top(("DO",), st, "LOOP", "DO")
        test, cond = st.args
        if test is None:
            self.jump(fr.top, st)
        else:
            self._test(cond, str(test).upper() == "WHILE", fr.top, st)
        self.bind(fr.end)
        self.frames.pop()

    def s_exit(self, st) -> None:
        loops = [f for f in self.frames if f.kind in ("DO", "FOR")]
        if not loops:
            raise self.error(M.EXIT_OUTSIDE_LOOP, st.pos)
        fr = loops[-1]
        fr.count += 1
        if fr.count > 16:
            raise self.error(M.TOO_MANY_EXITS, st.pos)
        self.jump(fr.end, st)

    # ------------------------------------------------------------ FOR / NEXT
    def s_for(self, st) -> None:
        ref, start_e, end_e, step_e = st.args
        write, read, _ = self.target(ref, "for.index")
        start = self.expr(start_e, "for.start")
        end = self.expr(end_e)
        step = self.expr(step_e, "for.step") if step_e is not None else (lambda m: 1)
        fr = self.push(_Frame("FOR", _word_pos(st, "FOR"), top=Target()))
        self.emit("for", lambda m: write(m, start(m)), st)
        self.bind(fr.top)
        body = fr.top
        warn = self.warner(st.pos)

        def next_(m):
            # README 4.2: NEXT re-evaluates start, end and step every time.
            s, e, d = start(m), end(m), step(m)
            up = s <= e
            n = (read(m) + d) & 0xFFFF if up else (read(m) - d) & 0xFFFF
            write(m, n)
            v = read(m)
            lo, hi = (s, e) if up else (e, s)
            if v != n and (lo <= v <= hi) != (lo <= n <= hi):
                warn(m, M.W_FOR_WRAP)
            return body.pc if lo <= v <= hi else None
        fr.next = next_

    def s_next(self, st) -> None:
        if st.args and st.args[0] is not None:
            tok = st.args[0]
            raise self.error(M.NEXT_WITH_NAME, N.Pos(tok.line, tok.column, len(str(tok))))
        fr = self.top(("FOR",), st, "NEXT", "FOR")
        self.emit("next", fr.next, st)
        self.bind(fr.end)
        self.frames.pop()

    # ------------------------------------------------------------ END, STOP
    def s_end(self, st) -> None:
        from .commands import make_end
        self.emit("end", make_end("end"), st)

    def s_stop(self, st) -> None:
        from .commands import make_end
        self.emit("stop", make_end("stop"), st)


_OPEN_CLOSE = {"IF": ("IF", "ENDIF"), "INLINE": ("IF", "ENDIF"), "SELECT": ("SELECT", "ENDSELECT"),
               "DO": ("DO", "LOOP"), "FOR": ("FOR", "NEXT")}


def _fall_off_end(m):
    """Running past the last statement behaves like END."""
    from .commands import make_end
    return make_end("end")(m)


def _gosub_push(warn: Callable) -> Callable:
    """GOSUB's return stack: a ring of 4 ids (README 4.3 default model)."""
    def push(m, gid):
        if m.gosub_depth >= 4:
            warn(m, M.W_GOSUB_OVERFLOW)
        else:
            m.gosub_depth += 1
        m.gosub_slots[m.gosub_ptr] = gid
        m.gosub_ptr = (m.gosub_ptr + 1) & 3
    return push


def _word_pos(st, word: str) -> N.Pos:
    return N.Pos(st.pos.line, st.pos.column, len(word))


def _pos_of(e) -> N.Pos:
    from .exprs import leftmost_leaf
    return leftmost_leaf(e).pos


def compile_program(tree: N.Program) -> Program:
    """Compile a parsed program.  Raises CompileError with file:line:col."""
    return Compiler(tree).compile()
