"""Per-bytecode unit tests: set the state, step once, check stack, memory, registers and cycles.

One test class, run for every compat mode (the cycle counts are the same in
both for cog 0; the hub windows of other cogs differ).  Expected values come
from the Propeller Manual's definitions and the measurements behind
spinemu/chip/timing_data.py.
"""
from __future__ import annotations

import pytest

from spinemu.chip import Chip
from spinemu.chip.spin import random_forward, random_reverse
from spinemu.chip.timing import hub_align

from chip_helpers import make_image

M = 0xFFFFFFFF


class Machine:
    """A chip booted on ``code`` (the first method), with cog 0 before its first bytecode."""

    def __init__(self, code: bytes, compat: str, **kw):
        self.chip = Chip(make_image(code, **kw), compat=compat)
        self.chip.step  # noqa: B018 - attribute exists
        self.chip._boot()
        self.cog = self.chip.cogs[0]
        self.timing = self.chip.timing

    def push(self, *values):
        for v in values:
            self.chip.mem_longs[self.cog.sp >> 2] = v & M
            self.cog.sp += 4

    def stack(self, n):
        sp = self.cog.sp
        return [self.chip.mem_longs[(sp - 4 * (n - i)) >> 2] for i in range(n)]

    def var(self, i):
        return self.chip.mem_longs[(self.cog.vbase >> 2) + i]

    def set_var(self, i, v):
        self.chip.mem_longs[(self.cog.vbase >> 2) + i] = v & M

    def step(self):
        """Cycles the bytecode took: the fetch's hub wait plus the measured rest."""
        t = self.cog.t
        cycles = self.chip.step()
        self.fetch_wait = hub_align(t + 12, self.cog.hub_phase) - t
        return cycles


@pytest.fixture(params=["chip", "spinsim"])
def compat(request):
    return request.param


def test_push_imm_pushes_a_big_endian_constant_in_its_measured_time(compat):
    m = Machine(bytes([0x3A, 0x12, 0x34, 0x56]), compat)
    sp = m.cog.sp
    cycles = m.step()
    assert m.stack(1) == [0x123456] and m.cog.sp == sp + 4 and m.cog.pc == 0x18 + 4
    assert cycles == m.fetch_wait + m.timing.push_imm[3] == m.fetch_wait + 188


@pytest.mark.parametrize("op, x, y, want", [
    (0xEC, 5, M, 4), (0xED, 0, 1, M), (0xF4, 0x10000, 0x10000, 0), (0xF5, 0x10000, 0x10000, 1),
    (0xF6, -7, 2, -3), (0xF7, -7, 2, -1), (0xF6, 5, 0, 0), (0xE3, 1, 33, 2), (0xE2, 0x80000000, 31, 1),
    (0xEE, 0x80000000, 4, 0xF8000000), (0xE0, 1, 1, 0x80000000), (0xE1, 0x80000000, 1, 1),
    (0xEF, 0b1011, 4, 0b1101), (0xE4, -5, 3, 3), (0xE5, -5, 3, -5), (0xF9, -1, 0, M), (0xFA, -1, 0, 0),
    (0xF0, 3, 0, 0), (0xF2, 3, 0, M), (0xFC, 7, 7, M), (0xFB, 7, 7, 0),
])
def test_binary_math_pops_two_and_pushes_the_result(compat, op, x, y, want):
    m = Machine(bytes([op]), compat)
    m.push(x, y)
    sp = m.cog.sp
    cycles = m.step()
    assert m.cog.sp == sp - 4 and m.stack(1) == [want & M]
    assert cycles == m.fetch_wait + m.timing.math(op & 0x1F, x & M, y & M)


@pytest.mark.parametrize("op, x, want", [
    (0xE6, 5, -5), (0xE7, 0, M), (0xE9, -9, 9), (0xE9, 0x80000000, 0x80000000), (0xF1, 0, 0),
    (0xF1, 0x80, 8), (0xF3, 33, 2), (0xF8, 99, 9), (0xF8, M, 65535), (0xFF, 0, M),
])
def test_unary_math_replaces_the_top_of_the_stack(compat, op, x, want):
    m = Machine(bytes([op]), compat)
    m.push(x)
    sp = m.cog.sp
    m.step()
    assert m.cog.sp == sp and m.stack(1) == [want & M]


def test_divide_takes_longer_for_small_divisors(compat):
    slow = Machine(bytes([0xF6]), compat)
    slow.push(1000, 3)
    fast = Machine(bytes([0xF6]), compat)
    fast.push(1000, 0x7FFF)
    # measured: 4 cycles less per divisor bit, counted in whole hub windows of 16
    assert slow.step() - fast.step() == 748 - 700


def test_pop_and_push_var_long(compat):
    m = Machine(bytes([0x45, 0x44]), compat)      # POP_VAR_4, PUSH_VAR_4
    m.push(0xCAFE)
    m.step()
    assert m.var(1) == 0xCAFE
    m.step()
    assert m.stack(1) == [0xCAFE]


def test_using_post_increment_on_a_byte_var_wraps_at_8_bits_and_pushes_the_old_value(compat):
    m = Machine(bytes([0x8A, 0x00, 0xAA]), compat)  # USING_BYTE_VAR +0, POST_INC byte, push
    m.set_var(0, 0xFF)
    sp = m.cog.sp
    m.step()
    assert m.var(0) & 0xFF == 0 and m.stack(1) == [0xFF] and m.cog.sp == sp + 4


def test_using_math_add_assign_pushes_the_unwrapped_result(compat):
    m = Machine(bytes([0x8A, 0x00, 0xCC]), compat)  # b += y, push
    m.set_var(0, 200)
    m.push(100)
    m.step()
    assert m.var(0) & 0xFF == 44 and m.stack(1) == [300]


@pytest.mark.parametrize("aop, fn", [(0x88, random_forward), (0x8C, random_reverse)])
def test_random_operators_step_the_rom_lfsr(compat, aop, fn):
    m = Machine(bytes([0x42, aop]), compat)       # USING_VAR_0 ?x / x?
    m.set_var(0, 12345)
    m.step()
    assert m.var(0) == fn(12345) and m.stack(1) == [fn(12345)]


def test_random_of_zero_starts_from_one():
    assert random_forward(0) == random_forward(1) == 0xD0000001
    assert random_reverse(random_forward(987654)) == 987654


@pytest.mark.parametrize("value, taken", [(0, True), (5, False)])
def test_jz_pops_and_jumps_only_on_zero(compat, value, taken):
    m = Machine(bytes([0x0A, 0x05]), compat)
    m.push(value)
    sp = m.cog.sp
    m.step()
    assert m.cog.sp == sp - 4
    assert m.cog.pc == 0x18 + 2 + (5 if taken else 0)


def test_djnz_keeps_counting_until_zero(compat):
    m = Machine(bytes([0x09, 0x7E]), compat)       # DJNZ -2 (to itself)
    m.push(3)
    m.step()
    assert m.stack(1) == [2] and m.cog.pc == 0x18
    m.step()
    m.step()
    assert m.cog.pc == 0x18 + 2                   # fell through, count popped
    assert m.chip.mem_longs[m.cog.sp >> 2] == 1   # the popped long keeps 1 (spinsim -p hub dump)


def test_reg_write_of_outa_and_dira_changes_the_pins_in_the_last_instruction(compat):
    m = Machine(bytes([0x3F, 0xB6, 0x3F, 0xB4, 0x32]), compat)   # POP DIRA, POP OUTA, RETURN
    m.push(0xF0, 0x30)                            # OUTA value below, DIRA value on top
    t0 = m.cog.t
    c1 = m.step()
    c2 = m.step()
    assert (m.cog.dira, m.cog.outa) == (0x30, 0xF0)
    events = [(t, d, o) for t, _, _, d, o, _ in m.chip.pin_events]
    assert events == [(t0 + c1 - 4, 0x30, 0), (t0 + c1 + c2 - 4, 0x30, 0xF0)]


def test_reg_bit_range_reversed_writes_the_field_backwards(compat):
    m = Machine(bytes([0x3E, 0xB4]), compat)       # OUTA[a..b] := v with a < b: reversed
    m.push(0b1011, 0, 3)
    m.step()
    assert m.cog.outa == 0b1101


def test_spr_index_uses_the_low_4_bits(compat):
    m = Machine(bytes([0x24]), compat)             # PUSH_SPR
    m.cog.outa = 0x1234
    m.push(20)                                    # 20 & 15 = 4: OUTA
    m.step()
    assert m.stack(1) == [0x1234]


def test_cnt_reads_the_cycle_of_the_reading_instruction(compat):
    m = Machine(bytes([0x3F, 0x91]), compat)       # PUSH CNT
    t = m.cog.t
    m.step()
    tf = hub_align(t + 12, m.cog.hub_phase)
    assert m.stack(1) == [tf + m.timing.reg_read_at[(0x3F, 0)]] == [tf + 144]


def test_waitcnt_finishes_8_cycles_after_cnt_reaches_the_target(compat):
    m = Machine(bytes([0x23]), compat)
    t = m.cog.t
    m.push(t + 5000)
    m.step()
    assert m.cog.t == t + 5000 + 8


def test_frame_and_call_build_the_rom_frame_layout(compat):
    # FRAME_RESULT, CALL method 1 (itself): frame words pbase|flags, vbase, dbase, return pc
    m = Machine(bytes([0x00, 0x05, 0x01]), compat, locals_bytes=8)
    c = m.cog
    sp, pbase, vbase, dbase = c.sp, c.pbase, c.vbase, c.dbase
    m.step()
    assert c.sp == sp + 12 and c.dcall == sp + 6
    m.step()
    w = m.chip.mem_words
    assert [w[(sp >> 1) + i] for i in range(4)] == [pbase, vbase, dbase, 0x18 + 3]
    assert c.dbase == sp + 8 and c.sp == sp + 12 + 8 and c.pc == 0x18


def test_unknown_opcode_raises_an_emulation_error(compat):
    from spinemu.diagnostics import EmulationError
    m = Machine(bytes([0x3C]), compat)
    with pytest.raises(EmulationError, match=r"unknown bytecode \$3C"):
        m.step()
