"""What each piece of Spin costs in cycles, from the compiler's bytecode and the chip's timing model.

The translator asks for the bytecodes of one statement or expression: the
real compiler (:class:`spinemu.compiler.stmts.MethodCompiler`) compiles that
piece alone, and each bytecode is priced with :class:`spinemu.chip.timing.Timing`
exactly as the interpreter (spinemu/chip/spin.py) prices it: ``rest``, the
cycles from the bytecode's fetch to the start of the next one.

A run of bytecodes started at cycle ``t`` ends at ``align(t + 12) + K`` with
``K = sum(ceil16(rest + 12) for all but the last) + rest of the last``
(docs/timing.md: every bytecode starts with a hub read), so one number per run,
:func:`chain`, is all a translated statement has to pay.

Value-dependent paths (a division's loop, a fill's count, a wait) are priced
at a reference value here; the run-time helpers in :mod:`spinemu.translate.spin`
add the difference.  Ops are classified so that the translator can place a
statement's charge around the one event whose cycle matters most
(:func:`split`): a register write (pins change), a wait, a cog start or stop, a
call, a register read.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..bytecode import TABLE, decode_assign, decode_unsigned, instruction_length
from ..chip.timing import MATH_REF, Timing, access_offsets, wide_offsets

__all__ = ["Op", "price", "chain", "split", "split_read", "anchor_at", "jump_op", "ceil16", "access_at", "access_range",
           "store_at"]


@dataclass(frozen=True)
class Op:
    """One priced bytecode: its byte, ``rest`` cycles and what kind of event it is."""

    code: int
    rest: int
    kind: str = ""        # "", "read", "write", "call", "wait", "cog", "look" (items paid at run time),
    #                       "paid" (a helper adds value-dependent cycles when it runs)
    hub: bool = False     # reads or writes hub RAM other cogs may share (VAR, DAT, memory, locks)
    helper: str = ""      # "paid": the spinemu.translate.spin helper that pays it (div, strsize ...)
    at: int = -1          # cycles from its fetch to its shared access, where a two-byte offset delays it


def ceil16(n: int) -> int:
    return (n + 15) & ~15


def chain(ops) -> int | None:
    """``K`` of a run of ops (see the module docstring); ``None`` for no ops.

    >>> chain([Op(0x36, 108), Op(0x41, 124)])
    252
    """
    ops = list(ops)
    if not ops:
        return None
    return sum(ceil16(o.rest + 12) for o in ops[:-1]) + ops[-1].rest


_PRIORITY = {"write": 0, "wait": 1, "cog": 2, "call": 3, "look": 3, "read": 4}


def anchor_at(ops):
    """The index of the op :func:`split` places a statement's charge around, or None (no timed op).

    The most important event (a write, a wait, a cog start or stop, a call,
    a read); a write after a call or a paid-item lookup gives way to the last
    of those; a bytecode whose helper pays its cycles (``paid``: a division)
    is the anchor only when there is nothing else: its helper must run after
    it is paid, so it goes before the charge's cut (:func:`split`).
    """
    timed = [(i, o) for i, o in enumerate(ops) if o.kind and o.kind != "paid"]
    if not timed:
        paid = [i for i, o in enumerate(ops) if o.kind == "paid"]
        return paid[-1] if paid else None
    j, anchor = min(timed, key=lambda io: (_PRIORITY[io[1].kind], io[0]))
    calls = [i for i, o in timed if o.kind in ("call", "look") and i < j]
    if anchor.kind == "write" and calls:
        # ``outa := f(x)``: the call is paid before it runs, the write after the call returns
        # (the translator pays ``post`` between computing the value and storing it)
        j = calls[-1]
    return j


def split(ops) -> tuple[list, list]:
    """Split a statement's ops into what is paid before it runs and after.

    The anchor is the op whose cycle matters most.  A write is paid before
    (the value lands in its last instruction, 4 cycles before the next
    bytecode); a call too (the callee runs after it); a read, a wait, a cog
    start or stop are paid after (the helper uses the cycle at which they
    start), and so is a lookup whose items the runtime pays (``look``, its
    LOOK_DONE: the items come before it).  Waits are paid by their helper, so
    they are left out.  (:func:`anchor_at` chooses.)
    """
    j = anchor_at(ops)
    if j is None:
        return list(ops), []
    anchor = ops[j]
    cut = j + 1 if anchor.kind in ("write", "call", "paid") else j
    pre, post = list(ops[:cut]), list(ops[cut:])
    post = [o for o in post if o.kind != "wait"]
    pre = [o for o in pre if o.kind != "wait"]
    return pre, post


def split_read(pre) -> tuple[list, list]:
    """Split a pre-paid run at its first register read: ``(before the read, from the read on)``.

    ``waitcnt(cnt + x)`` reads CNT, then computes, then waits: the read must
    see the cycle at which its bytecode starts, so the rest is paid by the
    read itself (``spin._read``).
    """
    for k, o in enumerate(pre):
        if o.kind == "read":
            if k + 1 < len(pre):
                return pre[:k], pre[k:]
            break
    return pre, []


def drop_result_delta(T: Timing) -> int:
    """What a RETURN costs less when the caller's frame drops the result (a call used as a statement)."""
    return T.returns(0x32, 1, False) - T.returns(0x32, 1, True)


def jump_op(T: Timing, mnemonic: str, long: bool = False, taken: bool = True) -> Op:
    """A control-flow bytecode the translator turns into Python's own ``if``/``while``."""
    code = {"JMP": 0x04, "TJZ": 0x08, "DJNZ": 0x09, "JZ": 0x0A, "JNZ": 0x0B, "CASE_DONE": 0x0C,
            "CASE_VALUE": 0x0D, "CASE_RANGE": 0x0E}[mnemonic]
    if mnemonic == "JMP":
        return Op(code, T.jmp[long])
    if mnemonic == "CASE_DONE":
        return Op(code, T.case_done)
    table = {"TJZ": T.tjz, "DJNZ": T.djnz, "JZ": T.jz, "JNZ": T.jnz, "CASE_VALUE": T.case_value,
             "CASE_RANGE": T.case_range}[mnemonic]
    return Op(code, table[(long, taken)])


def _assign_rest(T: Timing, a: int, reg: bool, jump_long: bool = False, inside: bool = True) -> int:
    aop = decode_assign(a)
    tab = T.assign_reg if reg else T.assign_mem
    if aop is None:
        return 0
    if aop.math is not None:
        f = aop.math.code & 0x1F
        ref = MATH_REF.get(aop.math.code, 0)
        return T._math_assign[(reg, f, aop.push)] + T._math[f][ref] - T._math[f][ref]
    if aop.has_jump:        # REPEAT: looping back (``inside``) or leaving
        return T.repeat[(reg, aop.mnemonic == "REPEAT_STEP", inside, jump_long)]
    return tab[a]


def price(T: Timing, data: bytes, run_params: int = 0, inside: bool = True) -> list:
    """The priced ops of a run of compiled bytecode (no jumps out of it).

    Args:
        run_params: parameters of the method a RUN bytecode starts.
        inside: price a REPEAT operator as looping back (else as leaving).
    """
    ops = []
    i = 0
    n = len(data)
    while i < n:
        op = data[i]
        length = instruction_length(data, i)
        kind = _kind(data, i, op)
        if op == 0x0F and not (ops and 0x10 <= ops[-1].code <= 0x13):
            kind = "look"       # LOOK_DONE right after the value: a lookup whose items the runtime pays
        helper = paid_helper(data, i) if kind == "paid" else ""
        at = _ACCESS[op] + (_WIDE[op] & (data[i + 1] >> 3)) if _WIDE[op] and i + 1 < n else -1
        ops.append(Op(op, _rest(T, data, i, op, run_params, inside), kind, _hub(op, data, i), helper or "", at))
        i += length
    return ops


def _hub(op: int, data=b"", i: int = 0) -> bool:
    """Does the bytecode touch state other cogs share (hub variables and memory, pins, locks, cogs)?"""
    if 0x40 <= op < 0x80:
        return not op & 0x20 and op & 3 != 3
    if 0x80 <= op < 0xE0:
        return (op >> 2) & 3 != 3 and op & 3 != 3
    if op in (0x3D, 0x3E, 0x3F):
        return bool(data[i + 1] & 0x10) if len(data) > i + 1 else True
    return 0x16 <= op <= 0x1E or 0x21 <= op <= 0x2F


_ACCESS = access_offsets()
_WIDE = wide_offsets()


def access_at(ops):
    """Cycles from a run's first fetch to its first shared access (``None``: it has none).

    The bytecode engine orders cogs by the moment each bytecode touches shared
    state (spinemu.chip.timing.access_offsets); a run waits for the other
    cogs until the first such moment.
    """
    found = access_range(ops)
    return found[0] if found else None


def access_range(ops):
    """``(first, last)``: cycles from a run's first fetch to its first and its last shared access, or None.

    An update of a hub variable (``x++``, ``x += n``: a USING access) reads it
    at its access moment and writes it back with its last instruction, 4 cycles
    before the next bytecode starts: that write-back is its last access (unless
    its cycles depend on values, which a helper pays when it runs).
    """
    before = 0
    first = last = None
    for o in ops:
        if o.hub:
            at = before + (o.at if o.at >= 0 else _ACCESS[o.code])
            first = at if first is None else first
            last = at
            if 0x40 <= o.code < 0xE0 and o.code & 3 == 2 and o.kind != "paid":
                last = before + o.rest - 4
        before += ceil16(o.rest + 12)
    return None if first is None else (first, last)


def store_at(ops):
    """Cycles from a run's first fetch to its store, if the run ends storing a hub variable after its
    first shared access: a POP (``x := a + b``) at its access, an update (``x++``, ``x += n``) at its
    write-back (unless its cycles depend on values); else None."""
    if not ops or not ops[-1].hub:
        return None
    o = ops[-1]
    if not (0x40 <= o.code < 0xE0 and o.code & 3 in (1, 2)) or o.kind == "paid":
        return None
    before = sum(ceil16(x.rest + 12) for x in ops[:-1])
    at = before + (o.rest - 4 if o.code & 3 == 2 else o.at if o.at >= 0 else _ACCESS[o.code])
    first = access_range(ops)[0]
    return at if at > first else None


#: bytecodes whose cycles depend on values: a helper of spinemu.translate.spin adds the difference when
#: it runs (``paid``), so the run with the bytecode must be paid before it: the Python name of each
PAID_HELPERS = {0xF6: "div", 0xF7: "mod", 0xF1: "encode", 0x16: "strsize", 0x17: "strcomp", 0x18: "bytefill",
                0x19: "wordfill", 0x1A: "longfill", 0x1C: "bytemove", 0x1D: "wordmove", 0x1E: "longmove"}


def paid_helper(data, i: int):
    """The helper that pays the bytecode at ``data[i]`` its value-dependent cycles, or None."""
    op = data[i]
    if op in PAID_HELPERS:
        return PAID_HELPERS[op]
    p = _assign_at(data, i)
    if p is not None:
        aop = decode_assign(data[p])
        if aop is not None and aop.math is not None and aop.math.code in (0xF6, 0xF7):
            return PAID_HELPERS[aop.math.code]      # x /= y
    return None


def _assign_at(data, i: int):
    """Where the assignment-operator byte of a USING bytecode at ``i`` is, or None."""
    op = data[i]
    if op in (0x3D, 0x3E, 0x3F):
        return i + 2 if (data[i + 1] >> 5) & 3 == 2 else None
    if op == 0x26:
        return i + 1
    if 0x40 <= op < 0x80:
        return i + 1 if op & 3 == 2 else None
    if 0x80 <= op < 0xE0 and op & 3 == 2:
        p = i + 1
        if (op >> 2) & 3:
            _, p = decode_unsigned(data, p)
        return p
    return None


def _kind(data, i, op) -> str:
    if op in (0x05, 0x06, 0x07):
        return "call"
    if op in (0x1B, 0x1F, 0x23, 0x27):
        return "wait"
    if op in (0x20, 0x21, 0x28, 0x2C):        # CLKSET, COGSTOP, COGINIT
        return "cog"
    if op in (0x3D, 0x3E, 0x3F):
        if not data[i + 1] & 0x10:
            return ""               # $1E0-$1EF: the interpreter's own registers (COGID, the stack pointer)
        access = (data[i + 1] >> 5) & 3
        if access == 2 and data[i + 1] & 0x1F in (0x11, 0x12, 0x13, 0x1C, 0x1D):
            return "read"           # cnt?, ina++, phsa += x: what matters is when the value is read
        return "read" if access == 0 else "write"
    if op == 0x24:
        return "read"
    if op in (0x25, 0x26):
        return "write"
    return "paid" if paid_helper(data, i) else ""


def _rest(T: Timing, data, i: int, op: int, run_params: int, inside: bool) -> int:
    name = TABLE[op].mnemonic
    if op <= 0x03:
        return T.frame
    if op == 0x04:
        return T.jmp[bool(data[i + 1] & 0x80)]
    if op == 0x05:
        return T.call
    if op == 0x06:
        return T.call_obj
    if op == 0x07:
        return T.call_obj_x
    if 0x08 <= op <= 0x0B:
        tab = (T.tjz, T.djnz, T.jz, T.jnz)[op - 0x08]
        return tab[(bool(data[i + 1] & 0x80), True)]
    if op == 0x0C:
        return T.case_done
    if op in (0x0D, 0x0E):
        tab = T.case_value if op == 0x0D else T.case_range
        return tab[(bool(data[i + 1] & 0x80), False)]
    if op == 0x0F:
        return T.look_done
    if 0x10 <= op <= 0x13:
        tab = (T.lookup_value, T.lookdown_value, T.lookup_range, T.lookdown_range)[op - 0x10]
        return tab[False]
    simple = {
        0x14: T.pop_bytes, 0x16: T.strsize(0), 0x17: T.strcomp(1, False), 0x20: T.clkset,
        0x21: T.cogstop, 0x22: T.lockret, 0x24: T.spr_push, 0x25: T.spr_pop,
        0x28: T.coginit[True], 0x2C: T.coginit[False], 0x29: T.locknew[True], 0x2D: T.locknew[False],
        0x2A: T.lockset[("lockset", True)], 0x2B: T.lockset[("lockclr", True)],
        0x2E: T.lockset[("lockset", False)], 0x2F: T.lockset[("lockclr", False)],
        0x34: T.push_const, 0x35: T.push_const, 0x36: T.push_const, 0x37: T.push_mask,
    }
    if op in simple:
        return simple[op]
    if op == 0x15:
        return T.run(run_params)
    if op in (0x18, 0x19, 0x1A):
        return T.fill(op - 0x18, 0)
    if op in (0x1C, 0x1D, 0x1E):
        return T.move(op - 0x1C, 0)
    if op in (0x1B, 0x1F, 0x23, 0x27):
        return 0            # waits: their helper pays them
    if op == 0x26:
        return T.spr_using + _assign_rest(T, data[i + 1], True)
    if 0x30 <= op <= 0x33:
        return T.returns(op, 1, True)    # the caller pays the difference when it drops the result
    if 0x38 <= op <= 0x3B:
        return T.push_imm[op - 0x37]
    if op in (0x3D, 0x3E, 0x3F):
        access = (data[i + 1] >> 5) & 3
        rest = T.reg[(op, min(access, 2))]
        if access == 2:
            rest += _assign_rest(T, data[i + 2], True, _jl(data, i + 3), inside)
        return rest
    if 0x40 <= op < 0x80:
        if op & 3 == 2:
            return T.var_using[op & 0x20 != 0] + _assign_rest(T, data[i + 1], False, _jl(data, i + 2), inside)
        return T.var[op]
    if 0x80 <= op < 0xE0:
        long_off = False
        p = i + 1
        if (op >> 2) & 3:
            long_off = bool(data[p] & 0x80)
            _, p = decode_unsigned(data, p)
        if op & 3 == 2:
            return T.mem_using[(op, long_off)] + _assign_rest(T, data[p], False, _jl(data, p + 1), inside)
        return T.mem[(op, long_off)]
    if op >= 0xE0:
        ref = MATH_REF.get(op, 0)
        return T._math[op & 0x1F][ref]
    raise ValueError(f"cannot price bytecode {name}")


def call_depths(data: bytes, callee) -> list:
    """``(depth, name)`` of each call in ``data``, in the order the calls run: the stack bytes in use when its FRAME started (where the called method's frame goes) and the method's name.

    ``callee(code_bytes, i)`` gives ``(parameter count, name)`` of the call at
    ``i``.  Depth is counted in longs from the statement's start; a FRAME takes
    three (return frame and result), a CALL drops the parameters and the frame
    and leaves the result if the frame kept it.  A call runs after the calls
    in its arguments (``f(g(x))``: g first), though its FRAME came first.
    """
    calls, depth, frames = [], 0, []
    i = 0
    while i < len(data):
        op = data[i]
        length = instruction_length(data, i)
        entry = TABLE[op]
        if op <= 0x03:
            frames.append((op, 4 * depth))
            depth += 3
        elif op in (0x05, 0x06, 0x07):
            nparams, name = callee(data, i)
            depth -= nparams + 3 + (1 if op == 0x07 else 0)
            frame, at = frames.pop() if frames else (1, 4 * depth)
            calls.append((at, name))
            depth += 1 if frame & 1 == 0 else 0
        elif 0x40 <= op < 0xE0 or op in (0x3D, 0x3E, 0x3F, 0x26):
            depth += _access_effect(data, i, op)
        elif 0x10 <= op <= 0x13:            # a lookup item compared: popped (a match ends where LOOK_DONE does)
            depth -= entry.pops
        elif entry.pops is not None and entry.pushes is not None:
            depth += entry.pushes - entry.pops
        i += length
    return calls


def _access_effect(data, i: int, op: int) -> int:
    """Stack effect of a variable, memory or register access (the USING operator's push bit included)."""
    if op in (0x3D, 0x3E, 0x3F):
        access = (data[i + 1] >> 5) & 3
        index = {0x3D: 1, 0x3E: 2, 0x3F: 0}[op]
        using_at = i + 2
    elif op == 0x26:
        access, index, using_at = 2, 1, i + 1
    else:
        access = op & 3
        index = 0
        using_at = i + 1
        if op >= 0x80:
            base = (op >> 2) & 3
            index = (1 if op & 0x10 else 0) + (1 if base == 0 else 0)
            if base:
                _, using_at = decode_unsigned(data, i + 1)
    if access == 0 or access == 3:
        return 1 - index
    if access == 1:
        return -1 - index
    aop = decode_assign(data[using_at])
    if aop is None:
        return -index
    pushed = 1 if aop.push else 0
    if aop.mnemonic == "WRITE":
        return -1 + pushed - index
    if aop.math is not None and not aop.math.unary:
        return -1 + pushed - index
    if aop.has_jump:
        return -index - (3 if aop.mnemonic == "REPEAT_STEP" else 2)
    return pushed - index


def _jl(data, p: int) -> bool:
    """Is the jump operand at ``p`` (if any) the two-byte form?"""
    return p < len(data) and bool(data[p] & 0x80)
