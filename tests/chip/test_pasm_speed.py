"""PASM speed-ups change nothing a program can see: idle-loop skipping (pasm_idle.py) and blocks (pasm_blocks.py).

Every program here runs with the speed-ups on and off (``Chip(fast_forward=,
compile_blocks=)``: off, every PASM instruction goes through its handler):
the pin trace, hub RAM, end cycle, reason and instruction counts must be
identical.  A seeded sample of tests/chip/tools/pasm_idle_random.py's
programs (polling loops on hub mailboxes, CNT deadlines, pins from a stimulus
and from other cogs; pasm_random.py's programs, straight and run round a
loop) runs here; the tool compares any number more.
"""
from __future__ import annotations

import os
import random
import sys

import pytest

from spinemu.chip import Chip
from spinemu.chip.inputs import PinStimulus
from spinemu.chip.pasm_affine import N, Aff, Predicates, Unsupported, first_change
from spinemu.compiler import compile_source

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "tools"))
from pasm_idle_random import CASES, run_both  # noqa: E402

HEAD = "CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"
SECOND = 80_000_000


def _speedups_change_nothing(src: str, cycles, inputs=None, compat="spinsim"):
    bad = run_both(compile_source(src).binary, inputs=inputs, compat=compat, cycles=cycles)
    assert not bad, "\n".join(bad) + "\n" + src


# ----------------------------------------------------------------------------- random programs
# (polling programs 1008 and 1011 run a counter edge while a loop is parked on the pins: the scheduler
# once spun forever on such an edge between a cog's start and its next shared access)
@pytest.mark.parametrize("kind, seed", [("polling", s) for s in range(1001, 1013)]
                         + [("loops", s) for s in range(2001, 2005)] + [("random", s) for s in range(3001, 3004)])
def test_random_programs_run_the_same_with_and_without_the_speedups(kind, seed):
    src, inputs, compat, cycles = CASES[kind](seed)
    if kind != "polling":
        cycles = min(cycles, 600_000)
    _speedups_change_nothing(src, cycles, inputs, compat)


# ----------------------------------------------------------------------------- idle loops
SERIAL_TX = HEAD + """VAR
  long box
PUB main | p
  cognew(@tx, @box)
  p := string("Hi!", 13)
  repeat strsize(p)
    repeat while box
    box := byte[p++] | $100
DAT
        org 0
tx      or      outa, pin
        or      dira, pin
wait    rdlong  data, par wz            ' a mailbox poll: parked until Spin writes it
  if_z  jmp     #wait
        shl     data, #1
        mov     bits, #10
        mov     t, cnt
        add     t, period
bit     shr     data, #1 wc
        muxc    outa, pin
        mov     x, t                    ' a CNT deadline polled: skipped pass by pass
:w      mov     y, t
        sub     y, cnt
        cmps    y, #0 wc
  if_nc jmp     #:w
        add     t, period
        djnz    bits, #bit
        wrlong  zero, par
        jmp     #wait
pin     long    1 << 30
period  long    80_000_000 / 9_600
zero    long    0
data    long    0
bits    long    0
t       long    0
x       long    0
y       long    0
"""


def test_a_polling_transmitter_costs_nothing_while_it_waits():
    _speedups_change_nothing(SERIAL_TX, SECOND // 4)
    chip = Chip(compile_source(SERIAL_TX).binary)
    result = chip.run(max_cycles=SECOND)
    idle = chip.pasm.idle
    assert idle.instructions_skipped > 0.99 * result.stats["pasm_instructions"]
    from spinemu.bench.uart import UartFormat, decode_uart
    assert bytes(f.value for f in decode_uart(result.trace, 30, UartFormat(9600))) == b"Hi!\r"


def test_a_program_whose_only_cog_left_polls_hub_ram_stalls():
    src = HEAD + "VAR\n  long box\nPUB main\n  cognew(@poll, @box)\nDAT\n        org 0\n" \
                 "poll    rdlong  x, par wz\n  if_z  jmp     #poll\n        cogid   x\n        cogstop x\nx       long 0\n"
    result = Chip(compile_source(src).binary).run()
    assert result.reason == "stalled"
    assert result.end_cycle < 20_000           # when the last thing happened, not at some limit


def test_a_pasm_loop_polling_a_pin_nothing_drives_stalls_and_one_a_stimulus_drives_wakes():
    src = HEAD + """PUB main
  cognew(@poll, 0)
DAT
        org 0
poll    mov     dira, #1
:w      test    mask, ina wz
  if_z  jmp     #:w
        mov     outa, #1
:h      jmp     #:h
mask    long    1 << 7
"""
    image = compile_source(src).binary
    assert Chip(image, inputs="pulldown").run().reason == "stalled"
    stimulus = PinStimulus([(3_000_000, 1 << 7, 1 << 7)])
    result = Chip(image, inputs=stimulus).run(max_cycles=SECOND)
    rise = [t for t, d, o in result.trace.changes if o & 1]
    assert result.reason == "cycle limit" and 3_000_000 < rise[0] < 3_000_100
    _speedups_change_nothing(src, 5_000_000, stimulus)


def test_a_loop_woken_by_another_cogs_pin_and_hub_writes_runs_as_without_skipping():
    src = HEAD + """VAR
  long box
PUB main | t
  cognew(@poll, @box)
  dira[5] := 1
  t := cnt
  repeat 6
    waitcnt(t += 7_777)
    !outa[5]
    waitcnt(t += 3_333)
    box++
  cogstop(1)
DAT
        org 0
poll    mov     dira, #%11
:w      rdlong  x, par
        cmp     x, last wz
  if_z  test    mask, ina wc
  if_z_and_nc jmp #:w
        mov     last, x
        xor     outa, #1
        muxc    outa, #2
        jmp     #:w
mask    long    1 << 5
x       long    0
last    long    0
"""
    _speedups_change_nothing(src, None)


def test_a_driver_stopped_while_a_loop_polls_its_pin_wakes_the_loop():
    """A cog's pins float when it stops (spinsim reads them as 1): a loop, or WAITPEQ, on one sees it."""
    src = HEAD + """PUB main
  cognew(@poll, 0)
  dira[3] := 1
  waitcnt(cnt + 50_000)
DAT
        org 0
poll    mov     dira, #1
:w      test    mask, ina wz
  if_z  jmp     #:w
        mov     outa, #1
        waitcnt x, #0
mask    long    1 << 3
x       long    0
"""
    result = Chip(compile_source(src).binary).run(max_cycles=200_000)
    assert [o & 1 for _, _, o in result.trace.changes][-1] == 1
    _speedups_change_nothing(src, 200_000)


# ----------------------------------------------------------------------------- blocks
def test_blocks_keep_self_modifying_code_calls_and_register_jumps_exact():
    src = HEAD + """VAR
  long buf[8]
PUB main
  cognew(@go, @buf)
DAT
        org 0
go      mov     n, #200
loop    movs    rd, ptr                 ' a patched source: the block is recompiled or left alone
        add     ptr, #1
        and     ptr, #7
rd      mov     v, 0-0
        add     acc, v
        call    #sub1                   ' call/ret from two places: ret's S changes every call
        rol     acc, #3 wc
  if_c  call    #sub1
        movd    wrt, #acc               ' patches the very next instruction (the pipeline runs it old)
wrt     mov     tmp, acc
        jmpret  back, #sub2
        mov     tgt, #here              ' a register jump
        jmp     tgt
here    djnz    n, #loop
        wrlong  acc, par
        cogid   n
        cogstop n
sub1    xor     acc, #$55 wz
  if_z  add     acc, #1
sub1_ret ret
sub2    sumc    acc, tmp
        jmp     back
n       long    0
ptr     long    0
v       long    0
acc     long    1
tmp     long    0
tgt     long    0
back    long    0
"""
    _speedups_change_nothing(src, None)
    chip = Chip(compile_source(src).binary)
    chip.run()
    assert chip.pasm.compiler.count > 0


# ----------------------------------------------------------------------------- the arithmetic
def test_first_change_is_exact_or_early_never_late():
    rng = random.Random(5)
    for _ in range(400):
        step = rng.choice([1, 3, 16, 64, 1000, N - 4, N - 64, N - 999])
        a = rng.randrange(N)
        lo = rng.randrange(N)
        hi = min(N, lo + rng.choice([1, 10, 5000, 1 << 20, 1 << 31]))
        if rng.random() < 0.5:                  # start near an edge, so that it comes within reach
            a = (rng.choice([lo, hi]) + rng.randrange(-3000, 3000)) % N
        k = first_change(a, step, lo, hi)
        inside = lo <= a < hi
        for j in range(min(k, 3000)):
            assert (lo <= (a + j * step) % N < hi) == inside
        if k < 3000 and min(step, N - step) < hi - lo and min(step, N - step) < N - (hi - lo):
            assert (lo <= (a + k * step) % N < hi) != inside     # small steps: exact


def test_cnt_values_follow_only_what_keeps_them_affine():
    log = Predicates()
    cnt = Aff.make(1000, 1, 0, True, log)
    left = (5000 - cnt) & 0xFFFFFFFF                   # sub x, cnt
    assert left.v == 4000 and left.b == -1
    assert ((left ^ 0x80000000) < (0 ^ 0x80000000)) is False     # cmps x, #0 wc
    assert log == [((4000 + (1 << 31)) % N, -1, 0, 1 << 31)]
    for op in (lambda v: v & 0xFF, lambda v: v << 1, lambda v: v | 1, lambda v: v * 3, lambda v: {v: 0},
               lambda v: v.bit_count(), lambda v: v >> 5, lambda v: cnt + cnt > 3):
        with pytest.raises(Unsupported):
            op(left)
