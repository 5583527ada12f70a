"""Compiled blocks (spinemu/chip/blocks.py) change nothing: the same runs with and without them.

Every comparison runs a program twice, with ``compile_blocks=False`` (the
interpreter alone, the reference) and with blocks compiled at the first visit
of an address (``block_threshold = 0``), and requires everything a run
produces to be identical: pin trace, hub RAM, end cycle and reason, bytecodes
per cog, cog events, or the fault's message.
"""
from __future__ import annotations

import glob
import os
import random

import pytest

from spinemu.chip import Chip

from chip_helpers import ARTICLE, PROGRAMS, ROOT, make_image, read_bytes

M = 0xFFFFFFFF


def outcome(image: bytes, blocks: bool, cycles: int, compat: str = "chip", prepare=None, **kw):
    chip = Chip(image, compat=compat, compile_blocks=blocks, **kw)
    chip.block_threshold = 0
    if prepare is not None:
        prepare(chip)
    try:
        r = chip.run(max_cycles=cycles)
    except Exception as e:          # a fault must be the same fault
        return (type(e).__name__, str(e)), chip
    return (r.trace.changes, r.hub, r.end_cycle, r.reason, r.stats["bytecodes_per_cog"], r.cog_events), chip


def assert_same(image: bytes, cycles: int, compat: str = "chip", prepare=None, **kw):
    want, _ = outcome(image, False, cycles, compat, prepare, **kw)
    got, chip = outcome(image, True, cycles, compat, prepare, **kw)
    assert got == want
    return chip


# ---------------------------------------------------------------------- whole programs
PROGRAM_FILES = sorted(glob.glob(os.path.join(PROGRAMS, "*.binary"))
                       + glob.glob(os.path.join(ROOT, "tests", "data", "chip", "behaviour", "*.binary")))


@pytest.mark.parametrize("path", PROGRAM_FILES, ids=lambda p: os.path.basename(p)[:-7])
def test_every_test_program_runs_the_same_with_compiled_blocks(path):
    for compat in ("chip", "spinsim"):
        assert_same(read_bytes(path), 30_000_000, compat)


@pytest.mark.parametrize("name", ["corrected_stepper_demo", "as_printed_simple_stepper"])
def test_the_article_programs_run_the_same_with_compiled_blocks(name):
    chip = assert_same(read_bytes(os.path.join(ARTICLE, name + ".binary")), 120_000_000, "spinsim")
    assert chip._compiler.count > 5


def test_a_busy_loop_woken_by_a_write_inside_a_block_is_exact():
    img = read_bytes(os.path.join(PROGRAMS, "cogs_share_variable.binary"))
    for compat in ("chip", "spinsim"):
        chip = assert_same(img, None, compat)
        assert chip._ff_loops > 0 and chip._ff_skipped > 1000


# ---------------------------------------------------------------------- code that changes
def test_a_program_rewriting_its_own_code_runs_its_new_bytes():
    # loop: PUSH_IMM1 k; POP_VAR_0 (var0 := k); var1 += var0;
    #       byte[@k] := k + 1  (the operand of the PUSH_IMM1 above); JMP loop
    code = bytearray([0x38, 0x05,                 # $0: PUSH_IMM1 5   (operand at code+1)
                      0x41,                       # POP_VAR_0
                      0x40, 0x46, 0x4C,           # PUSH_VAR_0; USING_VAR_4 ADD (var1 += var0)
                      0x40, 0x36, 0xEC,           # PUSH_VAR_0 + 1
                      0x39, 0x00, 0x00,           # PUSH_IMM2 (address of the operand, patched below)
                      0x81,                       # POP_BYTE_MEM
                      0x04, 0x00])                # JMP loop (patched)
    code[-1] = (-len(code)) & 0x7F
    img = bytearray(make_image(bytes(code)))
    start = int.from_bytes(img[0x0C:0x0E], "little")     # pcurr: the first bytecode
    operand = start + 1
    img[start + 10], img[start + 11] = operand >> 8, operand & 0xFF
    from spinemu.image import image_checksum
    img[5] = 0
    img[5] = image_checksum(bytes(img))
    chip = assert_same(bytes(img), 3_000_000)
    vbase = chip.cogs[0].vbase
    assert chip.mem_longs[vbase // 4] > 5 + 100       # the operand really changed every time


def test_a_block_runs_the_bytes_it_wrote_into_itself_a_moment_before():
    # byte[@operand] := var0; var1 += <operand>; var0++  -- the write comes first in the same block
    code = bytearray([0x40,                       # $0: PUSH_VAR_0
                      0x39, 0x00, 0x00,           # $1: PUSH_IMM2 address of the operand at $6 (patched)
                      0x81,                       # $4: POP_BYTE_MEM
                      0x38, 0x00,                 # $5: PUSH_IMM1 <operand>
                      0x46, 0x4C,                 # $7: USING_VAR_4 MATH_ADD
                      0x42, 0x2E,                 # $9: USING_VAR_0 POST_INC_LONG
                      0x04, 0x73])                # $B: JMP $0
    img = bytearray(make_image(bytes(code)))
    start = int.from_bytes(img[0x0C:0x0E], "little")
    img[start + 2], img[start + 3] = (start + 6) >> 8, (start + 6) & 0xFF
    from spinemu.image import image_checksum
    img[5] = 0
    img[5] = image_checksum(bytes(img))
    chip = assert_same(bytes(img), 1_000_000)
    var0, var1 = chip.mem_longs[chip.cogs[0].vbase // 4: chip.cogs[0].vbase // 4 + 2]
    # (at the cycle limit, var0++ may have read var0 and not written it back yet)
    assert var0 > 100 and var1 in (sum(k & 0xFF for k in range(n)) for n in (var0, var0 + 1))


def test_a_write_that_wakes_a_parked_loop_from_inside_a_block_keeps_the_timing():
    # cog 0 spins on var0 (parked by the fast-forward); cog 1, every 100_000 cycles,
    # increments var0 from the middle of a block and records CNT in var3
    main = bytes([0x39, 0x00, 0x02, 0xCB, 0x40, 0x15, 0x2C,   # cognew(method2, @var[16])
                  0x40, 0x34, 0xFC, 0x0A, 0x7B])               # repeat until var0 == -1
    worker = bytes([0x3F, 0x91, 0x3A, 0x01, 0x86, 0xA0,        # waitcnt(cnt + 100_000)
                    0xEC, 0x23,
                    0x36, 0x36, 0xEC, 0x49,                    # var2 := 1 + 1
                    0x42, 0x26,                                # ++var0 (the watched write)
                    0x3F, 0x91, 0x4D,                          # var3 := cnt
                    0x04, 0x6D])                               # repeat
    img = make_image(main, var_longs=48, methods=[(worker, 0)])
    for compat in ("chip", "spinsim"):
        chip = assert_same(img, 20_000_000, compat)
        assert chip._ff_loops > 0 and chip._ff_skipped > 10_000
        assert chip.mem_longs[chip.cogs[0].vbase // 4] > 150


def test_a_write_to_a_live_stack_slot_is_seen_by_the_next_pop():
    # a method without locals: LOC +4 is the first long of its own operand stack
    code = bytes([0x36,                           # PUSH_1           (stack slot 0)
                  0x38, 0x07,                     # PUSH_IMM1 7      (slot 1)
                  0x65,                           # POP_LOC_4: slot 0 := 7
                  0x41,                           # POP_VAR_0: var0 := slot 0
                  0x04, 0x79])                    # JMP $0
    chip = assert_same(make_image(code), 200_000)
    assert chip.mem_longs[chip.cogs[0].vbase // 4] == 7


def test_a_stack_growing_into_the_code_is_run_as_the_chip_would():
    # the stack starts 64 bytes below the loop and grows by 12 bytes an iteration,
    # until the pushes overwrite the loop itself (the code is in a DAT-like gap)
    code = bytes([0x35, 0x35, 0x35, 0x36, 0xEC, 0x04, 0x7A])     # PUSH_0 x3, PUSH_1, ADD, JMP -6
    img = make_image(code, dat=bytes(128))
    pcurr = int.from_bytes(img[0x0C:0x0E], "little")

    def prepare(chip):
        chip.mem[0x0E:0x10] = (pcurr - 64).to_bytes(2, "little")   # dcurr

    chip = assert_same(img, 2_000_000, prepare=prepare)
    assert chip.mem[pcurr] != 0x35                  # the loop was overwritten


# ---------------------------------------------------------------------- random bytecode
# Structured random programs: expressions push one value, statements leave the
# stack as they found it, so the programs run long; every compiled bytecode
# family appears, mixed with ones the interpreter keeps (CNT, OUTA, DIRA, POP).
_UNARY_OPS = [0xE6, 0xE7, 0xE9, 0xF1, 0xF3, 0xF8, 0xFF]
_BINARY_OPS = [op for op in range(0xE0, 0x100) if op not in _UNARY_OPS]
_SOLO_ASSIGN = [0x08, 0x0C, 0x10, 0x14, 0x18, 0x1C] + list(range(0x20, 0x40, 2)) + [0x40 | (u & 0x1F) for u in _UNARY_OPS]
_VAR_LONGS, _LOCAL_LONGS = 16, 8


def _short_or_long(rng, off: int, long_: bool) -> list:
    if not long_ and -64 <= off < 64:
        return [off & 0x7F]
    v = off & 0x7FFF
    return [0x80 | (v >> 8), v & 0xFF]


class _Generator:
    def __init__(self, rng, vbase: int, main: bool):
        self.rng, self.vbase, self.main = rng, vbase, main

    def var(self, access: int) -> list:
        rng = self.rng
        if rng.random() < 0.5:
            return [0x40 | (rng.randrange(8) << 2) | access]
        return [0x60 | (rng.randrange(1, 8) << 2) | access]

    def mem(self, access: int) -> list:
        rng = self.rng
        size = rng.choice([0, 1, 2])
        base = rng.choice([2, 3, 2, 3, 1])
        span = {1: 48, 2: 4 * _VAR_LONGS, 3: 4 * _LOCAL_LONGS}[base]
        if base == 1 and access in (1, 2) and rng.random() < 0.97:
            base, span = 2, 4 * _VAR_LONGS             # writes into the code only now and then
        out = []
        indexed = rng.random() < 0.3
        off = rng.randrange(0, span // 2) & ~((1 << size) - 1)
        if indexed:
            out += [0x38, rng.randrange(0, (span - off) >> size)]
        op = 0x80 | (size << 5) | (0x10 if indexed else 0) | (base << 2) | access
        return out + [op] + _short_or_long(rng, off, rng.random() < 0.2)

    def expr(self, depth: int = 0) -> list:
        rng = self.rng
        r = rng.random() if depth < 3 else rng.random() * 0.45
        if r < 0.12:
            return [rng.choice([0x34, 0x35, 0x36])]
        if r < 0.18:
            return [0x37, rng.randrange(0x80)]
        if r < 0.25:
            n = rng.randint(1, 4)
            return [0x37 + n] + [rng.randrange(256) for _ in range(n)]
        if r < 0.36:
            return self.var(0)
        if r < 0.45:
            return self.mem(0)
        if r < 0.52:
            return self.expr(depth + 1) + [rng.choice(_UNARY_OPS)]
        if r < 0.72:
            return self.expr(depth + 1) + self.expr(depth + 1) + [rng.choice(_BINARY_OPS)]
        if r < 0.80:                                    # an assignment that pushes its result
            target = self.var(2) if rng.random() < 0.6 else self.mem(2)
            if rng.random() < 0.5:
                return target + [0x80 | rng.choice(_SOLO_ASSIGN)]
            return self.expr(depth + 1) + target + [0xC0 | (rng.choice(_BINARY_OPS) & 0x1F)]
        if r < 0.84:
            return [0x3F, 0x91]                         # CNT
        if r < 0.88:
            return rng.choice([self.var(3), self.mem(3)])  # an address
        if r < 0.93 and self.main:
            return [0x00] + self.expr(depth + 1) + [0x05, 0x02]     # a call of method 2
        return self.expr(depth + 1) + self.expr(depth + 1) + [0xFC]

    def stmt(self, depth: int = 0) -> list:
        rng = self.rng
        r = rng.random() if depth < 3 else rng.random() * 0.45
        if r < 0.18:
            return self.expr() + self.var(1)
        if r < 0.30:
            return self.expr() + self.mem(1)
        if r < 0.36:                                    # a write through a pushed address
            size = rng.choice([0, 1, 2])
            a = self.vbase + (rng.randrange(_VAR_LONGS) << 2)
            return self.expr() + [0x39, a >> 8, a & 0xFF, 0x81 | (size << 5)]
        if r < 0.45:
            target = self.var(2) if rng.random() < 0.6 else self.mem(2)
            if rng.random() < 0.5:
                return target + [rng.choice(_SOLO_ASSIGN + [0x00 | 0x80, 0x00][:0])]
            return self.expr() + target + [0x40 | (rng.choice(_BINARY_OPS) & 0x1F)]
        if r < 0.48:
            return self.expr() + [0x3F, 0xB4] if rng.random() < 0.7 else self.expr() + [0x3F, 0xB6]
        if r < 0.50:
            return [0x3F, 0x91, 0x39, rng.randint(3, 6), rng.randrange(256), 0xEC, 0x23]  # waitcnt(cnt + 768..1791)
        if r < 0.53 and self.main:
            return [0x01] + self.expr() + [0x05, 0x02]          # call, result dropped
        if r < 0.62:                                    # if / if-else
            cond = self.expr()
            yes = self.block(depth + 1)
            if rng.random() < 0.5:
                return cond + [rng.choice([0x0A, 0x0B])] + _short_or_long(rng, len(yes), False) + yes
            no = self.block(depth + 1)
            jmp_end = [0x04] + _short_or_long(rng, len(no), True)
            yes = yes + jmp_end
            return cond + [0x0A] + _short_or_long(rng, len(yes), True) + yes + no
        if r < 0.70:                                    # repeat n: TJZ over a DJNZ loop
            body = self.block(depth + 1)
            back = [0x09] + _short_or_long(rng, -(len(body) + 3), True)
            return [0x38, rng.randint(0, 3), 0x08] + _short_or_long(rng, len(body) + 3, True) + body + back
        if r < 0.78:                                    # repeat local from a to b [step s]
            k = rng.randrange(1, 8)
            frm, to = rng.randint(0, 3), rng.randint(0, 3)
            body = self.block(depth + 1)
            step = rng.random() < 0.3
            tail = ([0x38, rng.randint(1, 2)] if step else []) + [0x38, frm, 0x38, to, 0x62 | (k << 2),
                                                                   0x06 if step else 0x02]
            tail += _short_or_long(rng, -(len(body) + len(tail) + 2), True)
            return [0x38, frm, 0x61 | (k << 2)] + body + tail
        if r < 0.84:                                    # case value / range test, then drop the subject
            yes = self.block(depth + 1)
            test = (self.expr() + [0x0D]) if rng.random() < 0.5 else (self.expr() + self.expr() + [0x0E])
            return (self.expr() + test + _short_or_long(rng, len(yes), False) + yes
                    + [0x38, 4, 0x14])
        return self.expr() + self.var(1)

    def block(self, depth: int = 0) -> list:
        out = []
        for _ in range(self.rng.randint(1, 4)):
            out += self.stmt(depth)
        if len(out) > 60:                               # keep short jumps short
            out = out[:0] + self.expr() + self.var(1)
        return out


def _structured_program(seed: int, cogs: int = 1):
    """A random program; with ``cogs=2`` method 1 first starts method 3 (a loop) in a second cog."""
    rng = random.Random(seed)
    var_longs = _VAR_LONGS + 64                         # the second cog's stack follows the variables
    layout = dict(var_longs=var_longs, locals_bytes=4 * _LOCAL_LONGS)
    probe = make_image(b"\x32", **layout)
    vbase_guess = int.from_bytes(probe[0x08:0x0A], "little")
    for _ in range(4):                                  # the layout settles (vbase depends on the sizes)
        gen = _Generator(random.Random(seed), vbase_guess, True)
        start = []
        if cogs == 2:                                   # cognew(method3(x), @var[16])
            start = gen.expr() + [0x39, 0x01, 0x03, 0xCB, 0x40] + [0x15, 0x2C]
        main = []
        while len(main) < 160:
            main += gen.stmt()
        main = start + main + [0x04] + _short_or_long(rng, -(len(main) + 3), True)
        sub_gen = _Generator(random.Random(seed + 1), vbase_guess, False)
        sub = sub_gen.block() + sub_gen.expr() + [0x33]
        loop_gen = _Generator(random.Random(seed + 2), vbase_guess, False)
        loop = []
        while len(loop) < 100:
            loop += loop_gen.stmt()
        loop += [0x04] + _short_or_long(rng, -(len(loop) + 3), True)
        image = make_image(bytes(main), methods=[(bytes(sub), 4 * _LOCAL_LONGS), (bytes(loop), 4 * _LOCAL_LONGS)],
                           **layout)
        vbase = int.from_bytes(image[0x08:0x0A], "little")
        if vbase == vbase_guess:
            break
        vbase_guess = vbase
    fill = [rng.choice([0, 1, 2, 3, 5, 255, 0x7FFFFFFF, 0x80000000, M, rng.randrange(1 << 32)])
            for _ in range(_VAR_LONGS)]

    def prepare(chip):
        for i, v in enumerate(fill):
            chip.mem_longs[(vbase >> 2) + i] = v
    return image, prepare


@pytest.mark.parametrize("seed", range(40))
def test_random_programs_run_the_same_with_compiled_blocks(seed):
    image, prepare = _structured_program(seed)
    assert_same(image, 3_000_000, "chip" if seed % 2 else "spinsim", prepare=prepare)


@pytest.mark.parametrize("seed", range(40))
def test_random_two_cog_programs_run_the_same_with_compiled_blocks(seed):
    image, prepare = _structured_program(seed, cogs=2)
    chip = assert_same(image, 3_000_000, "chip" if seed % 2 else "spinsim", prepare=prepare)
    assert chip.cogs[1].bytecodes > 0


def _chaos_op(rng):
    """Anything, operands included: jumps land inside instructions, pointers anywhere."""
    r = rng.random()
    if r < 0.5:
        return [rng.randrange(0x34, 0x3C)] + [rng.randrange(256) for _ in range(2)]
    if r < 0.8:
        return [rng.randrange(0x40, 0x100), rng.randrange(256)]
    return [rng.choice([0x04, 0x08, 0x09, 0x0A, 0x0B, 0x0D, 0x0E, 0x32, 0x33, 0x05, 0x00]), rng.randrange(256)]


@pytest.mark.parametrize("seed", range(24))
def test_random_bytes_fail_or_run_the_same_with_compiled_blocks(seed):
    rng = random.Random(1000 + seed)
    code = []
    while len(code) < 120:
        code += _chaos_op(rng)
    image = make_image(bytes(code), var_longs=16, locals_bytes=32, methods=[(bytes([0x36, 0x33]), 0)])
    assert_same(image, 1_000_000, "chip" if seed % 2 else "spinsim")


# ---------------------------------------------------------------------- division inline
DIVMOD_EDGES = [0, 1, 2, 3, 7, 1000, 0x7FFFFFFF, 0x80000000, 0x80000001, 0xFFFFFFFF, 0xFFFFFFFE,
                0xFFFFFC18, 123_456_789, 0xF0000000]


@pytest.mark.parametrize("f", [0x16, 0x17], ids=["div", "mod"])
def test_inline_division_and_modulus_give_the_interpreters_results(f):
    from spinemu.chip import mathops
    from spinemu.chip.blockops import _binary_expr

    fn = mathops.BINARY[f]
    rng = random.Random(f)
    values = DIVMOD_EDGES + [rng.getrandbits(32) for _ in range(200)] + [rng.getrandbits(8) for _ in range(50)]
    env = {f"B{f:02X}": fn}
    by_name = eval(f"lambda x, y: {_binary_expr(f, 'x', 'y')}", env)
    for y in values:
        by_literal = eval(f"lambda x: {_binary_expr(f, 'x', str(y))}", env)
        for x in values:
            assert by_name(x, y) == fn(x, y), (hex(x), hex(y))
            assert by_literal(x) == fn(x, y), (hex(x), hex(y))


def test_a_hot_loop_dividing_negative_and_positive_values_runs_the_same_with_compiled_blocks():
    from spinemu.compiler import compile_source

    src = """
VAR
  long results[8]

PUB main | i, x, d
  x := -1_000_003
  d := 7
  repeat i from 0 to 400
    results[0] += x / 1000
    results[1] += x // 1000
    results[2] += x / d
    results[3] += x // d
    results[4] += i / -3
    results[5] += i // -3
    x += 4_999
    d := d * 3 // 101 - 50
"""
    assert_same(compile_source(src, "divmod.spin").binary, 4_000_000)
