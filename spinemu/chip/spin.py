"""The Spin interpreter: every Spin1 bytecode, executed from hub RAM, with the ROM's timing.

:func:`build_handlers` returns the 256-entry dispatch list the run loop indexes
with the opcode byte (derived from :data:`spinemu.bytecode.TABLE`: the entry's
``handler`` name picks the function; unknown bytes share one handler).  A
handler is called as ``h(cog, op, t)`` after the opcode byte was fetched
(``cog.pc`` already points past it; ``t`` is the cycle the bytecode started
at; the fetch completed at ``tf = fetched(cog, t)``) and returns ``rest``: the
cycles from ``tf`` to the start of the
cog's next bytecode.  Why that one number is enough is explained in
docs/timing.md: every bytecode starts with a hub read, after which the hub
window is known, so the rest of the ROM interpreter's path takes a fixed
number of cycles.  The numbers come from :mod:`spinemu.chip.timing`.

Semantics follow the Propeller Manual v1.2 and were checked against Parallax's
ROM interpreter (tests/chip/test_conformance.py): math in
:mod:`spinemu.chip.mathops`; assignment operators below (:func:`_assign`);
memory accesses use the hub's address rules (16-bit addresses, words and
longs at ``addr & ~1`` / ``addr & ~3``, writes to ROM ignored).

Hot paths: the handlers for constants, variable and memory access, math and
jumps.  Everything else is written for clarity.
"""
from __future__ import annotations

from ..bytecode import TABLE
from .control import CogStopped, RebootRequested, Reschedule
from .mathops import BINARY, MASK32, UNARY
from .timing import Timing, access_offsets, math_param

__all__ = ["build_handlers", "random_forward", "random_reverse"]

def _parity(v: int) -> int:
    return bin(v).count("1") & 1


def random_forward(x: int) -> int:
    """``?x``: 32 steps of the ROM's LFSR (shift right, feedback taps $17); 0 counts as 1.

    >>> hex(random_forward(1)), hex(random_forward(0))
    ('0xd0000001', '0xd0000001')
    """
    x = x or 1
    for _ in range(32):
        x = (x >> 1) | (_parity(x & 0x17) << 31)
    return x


def random_reverse(x: int) -> int:
    """``x?``: the inverse of :func:`random_forward` (32 steps back).

    >>> random_reverse(random_forward(12345))
    12345
    """
    x = x or 1
    for _ in range(32):
        x = ((x << 1) & MASK32) | _parity(x & 0x8000000B)
    return x


def _reverse_bits(v: int, width: int) -> int:
    r = 0
    for _ in range(width):
        r = (r << 1) | (v & 1)
        v >>= 1
    return r


def _signed(v: int) -> int:
    return v - 0x100000000 if v & 0x80000000 else v


def build_handlers(chip, timing: Timing):
    """The dispatch list for ``chip`` (a :class:`spinemu.chip.chip.Chip`).

    Handlers close over the chip's memory views; ``timing`` gives the cycle
    counts.
    """
    mem = chip.mem          # 64 KB: hub RAM, then ROM
    L = chip.mem_longs      # the same bytes as longs
    W = chip.mem_words      # ... and as words
    T = timing
    sized_read = (mem.__getitem__,
                  lambda a: W[a >> 1],
                  lambda a: L[a >> 2])
    checks = getattr(chip, "checks", None)      # runtime warnings (spinemu.chip.checks), or None
    outside = checks.write_outside if checks is not None and checks.wants("write-outside-hub") else None

    def sized_write(size, a, v, c, t, op, pc=-1):
        a &= 0xFFFF
        if a < 0x8000:
            if WATCH[a >> 2]:
                chip.watch_hit(c, a, t, op, pc)
            if size == 0:
                mem[a] = v & 0xFF
            elif size == 1:
                W[a >> 1] = v & 0xFFFF
            else:
                L[a >> 2] = v & MASK32
        elif outside is not None:
            outside(c, a, 1 << size, t)

    def write_back(size, a, v, c, t, rest):
        """An update's store of ``v`` (``size`` 0 byte, 1 word, 2 long) to ``a``: with the bytecode's
        last instruction, 4 cycles before the next starts (``rest`` after the fetch), or, when another
        cog's access comes first, at that moment through the scheduler (``Scheduler.defer_write``)."""
        a &= 0xFFFF
        if a < 0x8000:
            tf = t + 12
            w = tf + ((c.hub_phase - tf) & 15) + rest - 4
            if w >= chip.rmw_limit:
                chip.defer_write(c, size, a & (0xFFFF, 0xFFFE, 0xFFFC)[size], v & (0xFF, 0xFFFF, MASK32)[size], t, w)
                return
            if WATCH[a >> 2]:
                chip.watch_hit_w(c, a, 1 << size, t, w)
            if size == 0:
                mem[a] = v & 0xFF
            elif size == 1:
                W[a >> 1] = v & 0xFFFF
            else:
                L[a >> 2] = v & MASK32
        elif outside is not None:
            outside(c, a, 1 << size, t)

    def fetched(c, t):
        """The cycle the opcode fetch of a bytecode started at ``t`` completes."""
        tf = t + 12
        return tf + ((c.hub_phase - tf) & 15)

    WATCH = chip.watch       # per hub long: 1 if a parked busy loop reads it

    def push(c, v):
        sp = c.sp
        L[sp >> 2] = v & MASK32
        c.sp = sp + 4

    def pop(c):
        sp = c.sp - 4
        c.sp = sp
        return L[sp >> 2]

    def jump_operand(c):
        pc = c.pc
        b = mem[pc]
        if b & 0x80:
            v = ((b & 0x7F) << 8) | mem[pc + 1]
            c.pc = pc + 2
            return (v - 0x8000 if v & 0x4000 else v), True
        c.pc = pc + 1
        return (b - 0x80 if b & 0x40 else b), False

    # ------------------------------------------------------------------ registers
    regs = chip.registers   # register access: read(c, r, t), write(c, r, v, t, seen)
    reg_read, reg_write = regs.read, regs.write
    ACC = access_offsets()  # a pin write is seen by other cogs from the bytecode's access on

    # ------------------------------------------------------------------ assignment operators
    def _assign(c, a, v, inc_mask, reg):
        """Apply assignment operator ``a`` to the target value ``v``.

        Like the ROM, every operator but WRITE first leaves the old value at
        the top of the stack, and the result (or the old value, for the post
        operators) ends there; the ``p`` bit decides whether it stays pushed.
        Returns ``(new, rest)``: the value to store and the operator's cycles
        (``reg``: the target is a cog register, whose write-back costs differ).
        """
        tab = T.assign_reg if reg else T.assign_mem
        push_it = a & 0x80
        b = a & 0x7F
        sp = c.sp
        chip.last_target = v
        if b == 0:                                      # WRITE: the value is on the stack
            if not push_it:
                c.sp = sp - 4
            return L[(sp - 4) >> 2], tab[a]
        L[sp >> 2] = v
        if b & 0x40:
            if b & 0x20:
                raise chip.fault(c, c.pc - 1, f"unknown assignment operator ${a:02X}")
            f = b & 0x1F
            u = UNARY[f]
            if u is not None:
                new = u(v)
                L[sp >> 2] = new
                if push_it:
                    c.sp = sp + 4
                return new, T.math_assign(reg, f, v, 0, push_it != 0)
            y = L[(sp - 4) >> 2]
            new = BINARY[f](v, y)
            L[(sp - 4) >> 2] = new
            if not push_it:
                c.sp = sp - 4
            return new, T.math_assign(reg, f, v, y, push_it != 0)
        if b == 0x02 or b == 0x06:                      # REPEAT [STEP]
            to = _signed(L[(sp - 4) >> 2])
            frm = _signed(L[(sp - 8) >> 2])
            if b == 0x06:
                step = _signed(L[(sp - 12) >> 2])
                c.sp = sp - 12
            else:
                step = 1
                c.sp = sp - 8
            off, long_ = jump_operand(c)
            x = _signed(v)
            if frm <= to:
                x += step
                inside = frm <= x <= to
            else:
                x -= step
                inside = to <= x <= frm
            if inside:
                c.pc = (c.pc + off) & 0xFFFF
            return x & MASK32, T.repeat[(reg, b == 0x06, inside, long_)]
        if b == 0x08:
            new = random_forward(v)
        elif b == 0x0C:
            new = random_reverse(v)
        elif b == 0x10:
            new = ((v & 0xFF) - ((v & 0x80) << 1)) & MASK32
        elif b == 0x14:
            new = ((v & 0xFFFF) - ((v & 0x8000) << 1)) & MASK32
        elif b == 0x18:
            new = None
        elif b == 0x1C:
            new = None
        elif 0x20 <= b < 0x40 and not b & 1:
            m = (inc_mask, 0xFF, 0xFFFF, MASK32)[(b >> 1) & 3]
            new = (v + (1 if b < 0x30 else -1)) & m
            if b & 0x08:                                # post: the old value stays on the stack
                if push_it:
                    c.sp = sp + 4
                return new, tab[a]
        else:
            raise chip.fault(c, c.pc - 1, f"unknown assignment operator ${a:02X}")
        if new is None:                                 # x~ / x~~: old value stays on the stack
            new = 0 if b == 0x18 else MASK32
        else:
            L[sp >> 2] = new
        if push_it:
            c.sp = sp + 4
        return new, tab[a]

    # ------------------------------------------------------------------ $00-$3F
    def op_frame(c, op, t):
        sp = c.sp
        W[sp >> 1] = (c.pbase | op) & 0xFFFF
        W[(sp + 2) >> 1] = c.vbase
        W[(sp + 4) >> 1] = c.dbase
        W[(sp + 6) >> 1] = c.dcall & 0xFFFF
        c.dcall = sp + 6
        L[(sp + 8) >> 2] = 0
        c.sp = sp + 12
        return T.frame

    def _enter(c, m):
        """The part of every CALL after the new pbase is known."""
        frame6 = c.dcall
        c.dcall = W[frame6 >> 1]
        W[frame6 >> 1] = c.pc & 0xFFFF
        c.dbase = (frame6 + 2) & 0xFFFF         # a 16-bit register (a corrupt frame chain can carry it past $FFFF)
        ent = L[((c.pbase + 4 * m) & 0xFFFF) >> 2]
        sp = c.sp + (ent >> 16)
        if sp > c.stack_end:
            if sp > 0x8000:
                raise chip.fault(c, c.pc - 2, f"stack overflow: the call needs the stack up to ${sp:04X}, past the end of hub RAM")
            chip.checks.stack_past_array(c, sp, c.pc - 1, (c.pbase + ent) & 0xFFFF)
        c.sp = sp
        full = (c.pbase_hi << 16 | c.pbase) + ent
        c.pc = full & 0xFFFF
        c.pc_hi = (full >> 16) & 0xFFFF

    def op_call(c, op, t):
        m = mem[c.pc]
        c.pc += 1
        _enter(c, m)
        return T.call

    def _enter_object(c, o):
        ent = L[((c.pbase + 4 * o) & 0xFFFF) >> 2]
        full = ((c.pbase_hi << 16 | c.pbase) + ent) & MASK32
        c.pbase = full & 0xFFFF
        c.pbase_hi = full >> 16
        c.vbase = (c.vbase + (ent >> 16)) & 0xFFFF

    def op_call_obj(c, op, t):
        pc = c.pc
        o, m = mem[pc], mem[pc + 1]
        c.pc = pc + 2
        _enter_object(c, o)
        _enter(c, m)
        return T.call_obj

    def op_call_obj_x(c, op, t):
        pc = c.pc
        o, m = mem[pc], mem[pc + 1]
        c.pc = pc + 2
        index = pop(c)
        _enter_object(c, (o + index) & 0xFF)
        _enter(c, m)
        return T.call_obj_x

    def op_jmp(c, op, t):
        off, long_ = jump_operand(c)
        c.pc += off
        return T.jmp[long_]

    def op_tjz(c, op, t):
        off, long_ = jump_operand(c)
        if L[(c.sp - 4) >> 2] == 0:
            c.sp -= 4
            c.pc += off
            return T.tjz[(long_, True)]
        return T.tjz[(long_, False)]

    def op_djnz(c, op, t):
        off, long_ = jump_operand(c)
        i = (c.sp - 4) >> 2
        v = (L[i] - 1) & MASK32
        if v:
            L[i] = v            # the ROM writes the count back only when it loops again
            c.pc += off
            return T.djnz[(long_, True)]
        c.sp -= 4                   # popped: the count's long keeps its last value (1), as on the chip
        return T.djnz[(long_, False)]

    def op_jz(c, op, t):
        off, long_ = jump_operand(c)
        sp = c.sp - 4
        c.sp = sp
        if L[sp >> 2] == 0:
            c.pc += off
            return T.jz[(long_, True)]
        return T.jz[(long_, False)]

    def op_jnz(c, op, t):
        off, long_ = jump_operand(c)
        sp = c.sp - 4
        c.sp = sp
        if L[sp >> 2] != 0:
            c.pc += off
            return T.jnz[(long_, True)]
        return T.jnz[(long_, False)]

    def op_case_done(c, op, t):
        pop(c)
        end = pop(c)
        c.pc = (c.pbase + end) & 0xFFFF
        return T.case_done

    def op_case_value(c, op, t):
        off, long_ = jump_operand(c)
        v = pop(c)
        if v == L[(c.sp - 4) >> 2]:
            c.pc += off
            return T.case_value[(long_, True)]
        return T.case_value[(long_, False)]

    def op_case_range(c, op, t):
        off, long_ = jump_operand(c)
        hi = _signed(pop(c))
        lo = _signed(pop(c))
        x = _signed(L[(c.sp - 4) >> 2])
        if lo > hi:
            lo, hi = hi, lo
        if lo <= x <= hi:
            c.pc += off
            return T.case_range[(long_, True)]
        return T.case_range[(long_, False)]

    def op_look_done(c, op, t):
        c.sp -= 12
        push(c, 0)
        return T.look_done

    def _look_found(c, result):
        sp = c.sp - 12          # drop base, end and index
        end = L[(sp + 4) >> 2]
        L[sp >> 2] = result
        c.sp = sp + 4
        c.pc = (c.pbase + end) & 0xFFFF

    def op_lookup_value(c, op, t):
        v = pop(c)
        sp = c.sp
        base_i = (sp - 12) >> 2
        if L[(sp - 4) >> 2] == L[base_i]:
            _look_found(c, v)
            return T.lookup_value[True]
        L[base_i] = (L[base_i] + 1) & MASK32
        return T.lookup_value[False]

    def op_lookdown_value(c, op, t):
        v = pop(c)
        sp = c.sp
        base_i = (sp - 12) >> 2
        if L[(sp - 4) >> 2] == v:
            _look_found(c, L[base_i])
            return T.lookdown_value[True]
        L[base_i] = (L[base_i] + 1) & MASK32
        return T.lookdown_value[False]

    def op_lookup_range(c, op, t):
        # 32-bit arithmetic as the ROM does it: count = |hi - lo| + 1 (wrapping, so
        # $8000_0000..$7FFF_FFFF counts 0 items), matched when index - base < count unsigned
        hi = pop(c)
        lo = pop(c)
        sp = c.sp
        base_i = (sp - 12) >> 2
        base = L[base_i]
        up = _signed(hi) >= _signed(lo)
        count = ((hi - lo if up else lo - hi) + 1) & MASK32
        k = (L[(sp - 4) >> 2] - base) & MASK32
        if k < count:
            _look_found(c, (lo + k if up else lo - k) & MASK32)
            return T.lookup_range[True]
        L[base_i] = (base + count) & MASK32
        return T.lookup_range[False]

    def op_lookdown_range(c, op, t):
        hi = _signed(pop(c))
        lo = _signed(pop(c))
        sp = c.sp
        base_i = (sp - 12) >> 2
        base = _signed(L[base_i])
        value = _signed(L[(sp - 4) >> 2])
        span = abs(hi - lo)
        if min(lo, hi) <= value <= max(lo, hi):
            _look_found(c, (base + abs(value - lo)) & MASK32)
            return T.lookdown_range[True]
        L[base_i] = (base + span + 1) & MASK32
        return T.lookdown_range[False]

    def op_pop(c, op, t):
        n = pop(c)
        c.sp = (c.sp - n) & 0xFFFF
        return T.pop_bytes

    def op_run(c, op, t):
        tf = fetched(c, t)
        return chip.run_helper(c, t)

    def op_strsize(c, op, t):
        a = pop(c) & 0xFFFF
        n = 0
        while mem[(a + n) & 0xFFFF]:
            n += 1
        push(c, n)
        return T.strsize(n)

    def op_strcomp(c, op, t):
        b = pop(c) & 0xFFFF
        a = pop(c) & 0xFFFF
        n = 0
        while True:
            x, y = mem[(a + n) & 0xFFFF], mem[(b + n) & 0xFFFF]
            n += 1
            if x != y:
                push(c, 0)
                return T.strcomp(n, False)
            if x == 0:
                push(c, MASK32)
                return T.strcomp(n, True)

    def op_fill(c, op, t):
        size = op - 0x18
        count = pop(c)
        value = pop(c)
        a = pop(c)
        step = 1 << size
        for i in range(count if count < 0x10000 else 0x10000):
            sized_write(size, a + i * step, value, c, t, op)
        return T.fill(size, count)

    def op_move(c, op, t):
        size = op - 0x1C
        count = pop(c)
        src = pop(c)
        dst = pop(c)
        step = 1 << size
        read = sized_read[size]
        align = ~(step - 1)
        n = count if count < 0x10000 else 0x10000
        idx = range(n) if ((dst & 0xFFFF) & align) <= ((src & 0xFFFF) & align) else range(n - 1, -1, -1)
        for i in idx:
            sized_write(size, dst + i * step, read(((src + i * step) & 0xFFFF) & align), c, t, op)
        return T.move(size, count)

    def op_waitpeq(c, op, t):
        tf = fetched(c, t)
        pop(c)                  # port: only port A exists
        mask = pop(c)
        state = pop(c)
        return chip.wait_pins(c, mask, state, op == 0x1B, tf)

    def op_clkset(c, op, t):
        freq = pop(c)
        mode = pop(c) & 0xFF
        if WATCH[0] or WATCH[1]:
            chip.watch_hit(c, 0, t, op)
        L[0] = freq
        mem[4] = mode
        rest = T.clkset
        if mode & 0x80:
            raise RebootRequested(rest)
        chip.set_clock(mode, freq)
        return rest

    def op_cogstop(c, op, t):
        tf = fetched(c, t)
        return chip.cogstop(c, pop(c) & 7, tf, T.cogstop)

    def op_lockret(c, op, t):
        chip.lockret(pop(c) & 7)
        return T.lockret

    def op_waitcnt(c, op, t):
        tf = fetched(c, t)
        target = pop(c)
        issue = tf + T.waitcnt_issue
        wait = (target - issue - T.waitcnt_min) & MASK32
        return T.waitcnt_issue + T.waitcnt_min + wait + T.waitcnt_after

    if checks is not None and checks.wants("waitcnt-passed"):
        def op_waitcnt(c, op, t):               # the same, with the runtime check for a count already passed
            tf = fetched(c, t)
            target = pop(c)
            issue = tf + T.waitcnt_issue
            wait = (target - issue - T.waitcnt_min) & MASK32
            if wait & 0x80000000:
                checks.waitcnt(c, target, wait, tf)
            return T.waitcnt_issue + T.waitcnt_min + wait + T.waitcnt_after

    def op_push_spr(c, op, t):
        tf = fetched(c, t)
        r = 0x1F0 + (pop(c) & 0xF)
        push(c, reg_read(c, r, tf + T.spr_read_at))
        return T.spr_push

    def op_pop_spr(c, op, t):
        tf = fetched(c, t)
        r = 0x1F0 + (pop(c) & 0xF)
        reg_write(c, r, pop(c), tf + T.spr_pop - 4, tf + ACC[op], True)     # registers change in the last instruction
        return T.spr_pop

    def op_using_spr(c, op, t):
        tf = fetched(c, t)
        r = 0x1F0 + (pop(c) & 0xF)
        a = mem[c.pc]
        c.pc += 1
        v = reg_read(c, r, tf + T.spr_read_at)
        new, rest = _assign(c, a, v, MASK32, True)
        reg_write(c, r, new, tf + T.spr_using + rest - 4, tf + ACC[op], True)
        return T.spr_using + rest

    def op_waitvid(c, op, t):
        tf = fetched(c, t)
        pixels = pop(c)
        colors = pop(c)
        return chip.waitvid(c, colors, pixels, tf)

    def op_coginit(c, op, t):
        tf = fetched(c, t)
        par = pop(c)
        code = pop(c)
        cog_id = pop(c)
        result = chip.coginit(c, cog_id, code, par, tf)
        if result == c.id:              # it restarted itself: the new program's start time stands
            raise CogStopped(T.coginit[op == 0x28])
        if op == 0x28:
            push(c, result)
        raise Reschedule(T.coginit[op == 0x28])

    def op_locknew(c, op, t):
        n = chip.locknew()
        if op == 0x29:
            push(c, n)
        return T.locknew[op == 0x29]

    def op_lockset(c, op, t):
        setting = op in (0x2A, 0x2E)
        was = chip.lockset(pop(c) & 7, setting)
        if op < 0x2C:
            push(c, MASK32 if was else 0)
        return T.lockset[("lockset" if setting else "lockclr", op < 0x2C)]

    def op_return(c, op, t):
        if op & 1:
            value = pop(c)
        else:
            value = L[c.dbase >> 2]
        abort = op < 0x32
        frames = 0
        at = c.pc - 1
        while True:
            d = c.dbase
            c.pc = W[(d - 2) >> 1]
            c.pc_hi = 0
            c.dbase = W[(d - 4) >> 1]
            c.vbase = W[(d - 6) >> 1]
            flags = W[(d - 8) >> 1]
            c.pbase = flags & 0xFFFC
            c.pbase_hi = 0
            c.sp = d - 8
            frames += 1
            if not abort or flags & 2:
                break
            if frames > 0x2000:     # more frames than 64 KB holds: the chain loops, the ROM would search for ever
                raise chip.fault(c, at, "ABORT found no frame to catch it in a frame chain that loops "
                                          "(a corrupt stack): the interpreter would unwind for ever")
        if not flags & 1:
            push(c, value)
        return T.returns(op, frames, not flags & 1)

    def make_push_const(op):
        value, rest = (MASK32, 0, 1)[op - 0x34], T.push_const

        def op_push_const(c, op, t):
            sp = c.sp
            L[sp >> 2] = value
            c.sp = sp + 4
            return rest
        return op_push_const

    def op_push_mask(c, op, t):
        b = mem[c.pc]
        c.pc += 1
        v = (2 << (b & 0x1F)) & MASK32
        if b & 0x20:
            v = (v - 1) & MASK32
        if b & 0x40:
            v ^= MASK32
        push(c, v)
        return T.push_mask

    def op_push_imm(c, op, t):
        n = op - 0x37
        pc = c.pc
        push(c, int.from_bytes(mem[pc:pc + n], "big"))
        c.pc = pc + n
        return T.push_imm[n]

    def op_reg(c, op, t):
        tf = fetched(c, t)
        b = mem[c.pc]
        c.pc += 1
        r = 0x1E0 + (b & 0x1F)
        access = (b >> 5) & 3
        if op == 0x3F:
            lo, width, rev = 0, 32, False
        else:
            if op == 0x3D:
                lo = pop(c) & 31
                width, rev = 1, False
            else:
                b2 = pop(c) & 31
                a2 = pop(c) & 31
                rev = a2 < b2
                lo, hi = (a2, b2) if rev else (b2, a2)
                width = hi - lo + 1
        field = (1 << width) - 1
        key = (op, access)
        if access == 0:
            v = (reg_read(c, r, tf + T.reg_read_at[key]) >> lo) & field
            push(c, _reverse_bits(v, width) if rev else v)
            return T.reg[key]
        if access == 1:
            v = pop(c) & field
            if rev:
                v = _reverse_bits(v, width)
            if width < 32:
                old = reg_read(c, r, tf + T.reg_read_at[key])
                v = (old & ~(field << lo)) | (v << lo)
            reg_write(c, r, v, tf + T.reg[key] - 4, tf + ACC[op], True)
            return T.reg[key]
        if access == 2:
            a = mem[c.pc]
            c.pc += 1
            old = reg_read(c, r, tf + T.reg_read_at[key])
            v = (old >> lo) & field
            if rev:
                v = _reverse_bits(v, width)
            new, rest = _assign(c, a, v, field, True)
            new &= field
            if rev:
                new = _reverse_bits(new, width)
            reg_write(c, r, (old & ~(field << lo)) | (new << lo), tf + T.reg[key] + rest - 4, tf + ACC[op], True)
            return T.reg[key] + rest
        raise chip.fault(c, c.pc - 2, f"register access ${b:02X} is not a Spin operation")

    def op_unknown(c, op, t):
        raise chip.fault(c, c.pc - 1, f"unknown bytecode ${op:02X}")

    # ------------------------------------------------------------------ $40-$7F variables
    def make_var_long(op):
        """A handler for VAR/LOC long bytecode ``op`` with its fields resolved (hot path)."""
        off = op & 0x1C
        local = bool(op & 0x20)
        access = op & 3
        rest = T.var[op]
        if access == 0:
            if local:
                def h(c, op, t):
                    sp = c.sp
                    L[sp >> 2] = L[((c.dbase + off) & 0xFFFF) >> 2]
                    c.sp = sp + 4
                    return rest
            else:
                def h(c, op, t):
                    sp = c.sp
                    L[sp >> 2] = L[((c.vbase + off) & 0xFFFF) >> 2]
                    c.sp = sp + 4
                    return rest
        elif access == 1:
            def h(c, op, t):
                a = ((c.dbase if local else c.vbase) + off) & 0xFFFF
                sp = c.sp - 4
                c.sp = sp
                if a < 0x8000:
                    if WATCH[a >> 2]:
                        chip.watch_hit(c, a, t, op)
                    L[a >> 2] = L[sp >> 2]
                elif outside is not None:
                    outside(c, a, 4, t)
                return rest
        elif access == 3:
            def h(c, op, t):
                sp = c.sp
                L[sp >> 2] = ((c.dbase if local else c.vbase) + off) & 0xFFFF
                c.sp = sp + 4
                return rest
        else:
            using_rest = T.var_using[local]

            def h(c, op, t):
                a = ((c.dbase if local else c.vbase) + off) & 0xFFFF
                pc = c.pc
                aop = mem[pc]
                c.pc = pc + 1
                new, arest = _assign(c, aop, L[a >> 2], MASK32, False)
                rest = using_rest + arest
                write_back(2, a, new, c, t, rest)
                return rest
        h.__name__ = "op_var_long"
        return h

    # ------------------------------------------------------------------ $80-$DF memory
    def make_mem(op):
        """A handler for memory bytecode ``op`` with its fields resolved (hot path)."""
        size = (op >> 5) & 3
        base = (op >> 2) & 3
        indexed = bool(op & 0x10)
        access = op & 3
        align = (0xFFFF, 0xFFFE, 0xFFFC)[size]
        if access == 2:
            r_short, r_long = T.mem_using[(op, False)], T.mem_using.get((op, True), 0)
        else:
            r_short, r_long = T.mem[(op, False)], T.mem.get((op, True), 0)

        def address(c):
            """Pop index/address operands and decode the offset; returns (address, rest)."""
            rest = r_short
            if base:
                pc = c.pc
                b = mem[pc]
                if b & 0x80:
                    a = ((b & 0x7F) << 8) | mem[pc + 1]
                    c.pc = pc + 2
                    rest = r_long
                else:
                    a = b
                    c.pc = pc + 1
                a += c.vbase if base == 2 else c.dbase if base == 3 else c.pbase
                if indexed:
                    sp = c.sp - 4
                    c.sp = sp
                    a += L[sp >> 2] << size
            else:
                sp = c.sp - 4
                if indexed:
                    a = L[(sp - 4) >> 2] + (L[sp >> 2] << size)
                    sp -= 4
                else:
                    a = L[sp >> 2]
                c.sp = sp
            return a & MASK32, rest

        if access == 0:
            if size == 2:
                def h(c, op, t):
                    a, rest = address(c)
                    sp = c.sp
                    L[sp >> 2] = L[(a & 0xFFFC) >> 2]
                    c.sp = sp + 4
                    return rest
            else:
                def h(c, op, t):
                    a, rest = address(c)
                    sp = c.sp
                    L[sp >> 2] = mem[a & 0xFFFF] if size == 0 else W[(a & 0xFFFE) >> 1]
                    c.sp = sp + 4
                    return rest
        elif access == 1:
            def h(c, op, t):
                pc = c.pc - 1
                a, rest = address(c)
                sp = c.sp - 4
                c.sp = sp
                sized_write(size, a, L[sp >> 2], c, t, op, pc)
                return rest
        elif access == 3:
            def h(c, op, t):
                a, rest = address(c)
                sp = c.sp
                L[sp >> 2] = a
                c.sp = sp + 4
                return rest
        else:
            read = sized_read[size]

            def h(c, op, t):
                a, rest = address(c)
                pc = c.pc
                aop = mem[pc]
                c.pc = pc + 1
                new, arest = _assign(c, aop, read(a & align), MASK32, False)
                rest += arest
                write_back(size, a, new, c, t, rest)
                return rest
        h.__name__ = "op_mem"
        return h

    # ------------------------------------------------------------------ $E0-$FF math
    def make_math(op):
        """A handler for math bytecode ``op`` (hot path): constant cost unless its loop varies."""
        f = op & 0x1F
        u = UNARY[f]
        table = T._math[f]
        const = table[0] if len(set(table)) == 1 else None
        if u is not None:
            if const is not None:
                def h(c, op, t):
                    i = (c.sp - 4) >> 2
                    L[i] = u(L[i])
                    return const
            else:
                def h(c, op, t):
                    i = (c.sp - 4) >> 2
                    x = L[i]
                    L[i] = u(x)
                    return table[math_param(op, x, 0)]
        else:
            fn = BINARY[f]
            if const is not None:
                def h(c, op, t):
                    sp = c.sp - 4
                    i = (sp - 4) >> 2
                    L[i] = fn(L[i], L[sp >> 2])
                    c.sp = sp
                    return const
            else:
                def h(c, op, t):
                    sp = c.sp - 4
                    i = (sp - 4) >> 2
                    x, y = L[i], L[sp >> 2]
                    L[i] = fn(x, y)
                    c.sp = sp
                    return table[math_param(op, x, y)]
        h.__name__ = "op_math"
        return h

    named = {
        "op_frame_result": op_frame, "op_frame": op_frame, "op_frame_result_trap": op_frame,
        "op_frame_trap": op_frame, "op_jmp": op_jmp, "op_call": op_call, "op_call_obj": op_call_obj,
        "op_call_obj_x": op_call_obj_x, "op_tjz": op_tjz, "op_djnz": op_djnz, "op_jz": op_jz,
        "op_jnz": op_jnz, "op_case_done": op_case_done, "op_case_value": op_case_value,
        "op_case_range": op_case_range, "op_look_done": op_look_done,
        "op_lookup_value": op_lookup_value, "op_lookdown_value": op_lookdown_value,
        "op_lookup_range": op_lookup_range, "op_lookdown_range": op_lookdown_range,
        "op_pop": op_pop, "op_run": op_run, "op_strsize": op_strsize, "op_strcomp": op_strcomp,
        "op_bytefill": op_fill, "op_wordfill": op_fill, "op_longfill": op_fill,
        "op_waitpeq": op_waitpeq, "op_waitpne": op_waitpeq,
        "op_bytemove": op_move, "op_wordmove": op_move, "op_longmove": op_move,
        "op_clkset": op_clkset, "op_cogstop": op_cogstop, "op_lockret": op_lockret,
        "op_waitcnt": op_waitcnt, "op_push_spr": op_push_spr, "op_pop_spr": op_pop_spr,
        "op_using_spr": op_using_spr, "op_waitvid": op_waitvid,
        "op_coginit_result": op_coginit, "op_coginit": op_coginit,
        "op_locknew_result": op_locknew, "op_locknew": op_locknew,
        "op_lockset_result": op_lockset, "op_lockclr_result": op_lockset,
        "op_lockset": op_lockset, "op_lockclr": op_lockset,
        "op_abort": op_return, "op_abort_value": op_return, "op_return": op_return,
        "op_return_value": op_return,
        "op_push_mask": op_push_mask, "op_push_imm1": op_push_imm, "op_push_imm2": op_push_imm,
        "op_push_imm3": op_push_imm, "op_push_imm4": op_push_imm,
        "op_reg_bit": op_reg, "op_reg_range": op_reg, "op_reg": op_reg,
        "op_unknown": op_unknown,
    }
    makers = {"op_mem": make_mem, "op_math": make_math, "op_var_long": make_var_long,
              "op_push_neg1": make_push_const, "op_push_0": make_push_const, "op_push_1": make_push_const}
    return [makers[e.handler](e.code) if e.handler in makers else named[e.handler] for e in TABLE]
