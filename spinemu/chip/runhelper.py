"""The RUN bytecode ($15): prepare a Spin method call for a new cog.

``cognew(method(args), @stack)`` compiles to: push the arguments, push the
word ``params << 8 | method_index``, push the stack address, RUN, then
COGINIT.  On the chip RUN hands over to a short Spin routine in ROM; what it
does was established by black-box runs on the ROM interpreter (spinsim 0.99,
comparing hub RAM before and after) and is reproduced here effect by effect:

1. the new stack gets the frame ``$FFFFFFFF, $FFF9FFFF`` (the method's return
   lands on the ROM's COGID/COGSTOP bytecodes), a zero result long and a copy
   of the arguments, which are popped off the caller's stack;
2. ``PAR`` = the first local long of the new frame; the words at ``PAR+2``
   .. ``PAR+10`` get pbase, vbase, dbase, pcurr and dcurr for the new cog's
   interpreter (they are scratch until the method uses its locals);
3. the caller's stack gets the three COGINIT operands: -1 (a free cog),
   ``$F004`` (the interpreter) and ``PAR``;
4. the routine's own working values stay behind on the caller's stack above
   those three longs, and some interpreter scratch registers change; both
   are reproduced so that hub RAM matches the chip byte for byte.

Its cost is one measured number per argument count (``Timing.run``).
"""
from __future__ import annotations

from .rom import INTERPRETER_ENTRY

__all__ = ["run_spin_method"]

_M = 0xFFFFFFFF


def run_spin_method(chip, c, t: int) -> int:
    """Execute RUN for cog ``c`` (bytecode started at ``t``); returns the cycles from its fetch to the next bytecode."""
    L, W, watch = chip.mem_longs, chip.mem_words, chip.watch
    sp = c.sp
    stack = L[(sp - 4) >> 2]
    word = L[(sp - 8) >> 2]
    nbytes = ((word >> 8) << 2) & _M
    params = nbytes >> 2
    method = word & 0xFF
    entry = (c.pbase + 4 * method) & 0xFFFF
    d = (sp - 8 - nbytes) & 0xFFFF            # where the arguments start
    stack16 = stack & 0xFFFF

    def wl(a, v):
        a &= 0xFFFF
        if a < 0x8000:
            if watch[a >> 2]:
                chip.watch_hit(c, a, t, 0x15)
            L[a >> 2] = v & _M

    def ww(a, v):
        a &= 0xFFFF
        if a < 0x8000:
            if watch[a >> 2]:
                chip.watch_hit(c, a, t, 0x15)
            W[a >> 1] = v & 0xFFFF

    # the arguments move to the new stack (as BYTEMOVE would copy them)
    args = bytes(chip.mem[d: d + nbytes]) if nbytes <= 0x8000 else b""
    for i, b in enumerate(args):
        a = (stack16 + 12 + i) & 0xFFFF
        if a < 0x8000:
            if watch[a >> 2]:
                chip.watch_hit(c, a, t, 0x15)
            chip.mem[a] = b
    # the routine's working values left above the operands (slots n, n+1, n+2)
    for slot, value in ((params, nbytes), (params + 1, d), (params + 2, nbytes)):
        if slot >= 5:
            wl(d + 4 * slot, value)
    wl(stack16, _M)
    wl(stack16 + 4, 0xFFF9FFFF)
    wl(stack16 + 8, 0)
    par = (stack + 12 + nbytes) & _M
    pbase_full = (c.pbase_hi << 16) | c.pbase
    ww(par + 2, pbase_full)
    ww(par + 4, c.vbase)
    ww(par + 6, stack + 8)
    ww(par + 8, pbase_full + W[entry >> 1])
    ww(par + 10, par + W[(entry + 2) >> 1])
    ret = (c.pc_hi << 16) | c.pc
    for k, v in enumerate((_M, INTERPRETER_ENTRY, par, ret, 0x00800000)):
        wl(d + 4 * k, v)
    c.sp = (d + 12) & 0xFFFF
    c.scratch[5], c.scratch[6], c.scratch[7], c.scratch[8] = _M, 0x80000000, 0x00800000, ret
    return chip.timing.run(params)
