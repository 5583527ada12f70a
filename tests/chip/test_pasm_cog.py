"""The PASM cog (spinemu/chip/pasm_cog.py): instruction semantics, the chip mode, counters, limits, tools.

Behaviour spinsim shows is checked against its recordings in
test_pasm_probes.py and test_pasm_random.py; this file holds what needs no
simulator: the ALU table against the measured vectors, what the silicon
does where spinsim differs (``compat="chip"``), the counters (spinsim has
none; the datasheet's formulas), bad programs, the cycle limit, and the
tracing and reporting tools.
"""
from __future__ import annotations

import io
import random
import struct

import pytest

from spinemu import pasm
from spinemu.chip import Chip
from spinemu.chip.pasm_cog import PasmEngine
from spinemu.chip.pasm_ops import ALU, COG, FAMILIES, FLAGS, HUB_PHASE, RAM_SLOTS
from spinemu.cli import main
from spinemu.compiler import compile_source

from chip_helpers import ROOT

VECTORS = f"{ROOT}/tests/data/pasm/alu_vectors.txt"
NEVER = 1 << 62


def pasm_program(body: str, *, par: str = "@buf", data: str = "", longs: int = 16) -> bytes:
    """An image whose main method starts ``body`` (PASM, ``org 0``) in cog 1 and returns."""
    src = (f"CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\nVAR\n  long buf[{longs}]\n"
           f"PUB main\n  cognew(@entry, {par})\nDAT\n        org 0\nentry\n{body}\n{data}")
    return compile_source(src).binary


def buf_longs(result, image: bytes, n: int = 16) -> list:
    vbase = struct.unpack_from("<H", image, 8)[0]
    return list(struct.unpack_from(f"<{n}I", result.hub, vbase))


# ----------------------------------------------------------------------------- the ALU table
def _vectors():
    with open(VECTORS) as f:
        for line in f:
            if not line.startswith("#"):
                mn, d, s, c, z, _, r, c_out, z_out = line.split()
                yield mn, int(d, 16), int(s, 16), int(c), int(z), None if r.startswith("-") else int(r, 16), \
                    int(c_out), int(z_out)


@pytest.fixture(scope="module")
def engine():
    eng = PasmEngine(Chip(pasm_program("        jmp #entry")))
    eng.until[0] = NEVER
    return eng


def test_every_measured_alu_vector_through_the_generated_handlers(engine):
    R = [0] * RAM_SLOTS
    R[COG], R[HUB_PHASE] = engine.chip.cogs[1], 8
    bad = []
    for mn, d, s, c, z, result, c_out, z_out in _vectors():
        word = pasm.encode(mn, dest=18, src=19, effects=["wz", "wc"])
        R[18], R[19], R[FLAGS] = d, s, (c << 1) | z
        assert engine.handlers[word](R, 0, 1000) is None       # 4 cycles, next instruction
        got = (R[18] if result is not None else None, R[FLAGS] >> 1, R[FLAGS] & 1)
        if got != (result, c_out, z_out):
            bad.append(f"{mn} {d:08X} {s:08X} c={c} z={z}: spinemu {got}, spinsim {(result, c_out, z_out)}")
    assert not bad, f"{len(bad)} differences, first: " + "; ".join(bad[:5])


def test_the_alu_table_covers_exactly_the_alu_opcodes_of_the_instruction_table():
    alu_opcodes = {ins.opcode for ins in pasm.INSTRUCTIONS.values() if ins.kind == "alu"}
    assert {op for op, (family, _) in enumerate(FAMILIES) if family == "alu"} == alu_opcodes
    assert {detail for family, detail in FAMILIES if family == "alu"} <= set(ALU)
    assert [op for op, (family, _) in enumerate(FAMILIES) if family == "undefined"] == [4, 5, 6, 7]


@pytest.mark.parametrize("cond", range(16))
def test_each_condition_runs_the_instruction_for_exactly_its_flag_states(engine, cond):
    word = pasm.encode("add", dest=18, src=1, immediate=True) & ~(0xF << 18) | (cond << 18)
    R = [0] * RAM_SLOTS
    R[COG], R[HUB_PHASE] = engine.chip.cogs[1], 8
    ran = []
    for c in (0, 1):
        for z in (0, 1):
            R[18], R[FLAGS] = 0, (c << 1) | z
            engine.handlers[word](R, 0, 0)
            ran.append(R[18] == 1)
    # cccc bits select: 0 = !C & !Z, 1 = !C & Z, 2 = C & !Z, 3 = C & Z (Propeller Manual, "Conditions")
    assert ran == [bool(cond & 1), bool(cond & 2), bool(cond & 4), bool(cond & 8)]


# ----------------------------------------------------------------------------- the chip mode
def test_chip_mode_par_as_source_is_the_register_and_inb_reads_zero():
    body = """        mov     par, #5         ' lands in shadow RAM
        mov     x, par          ' the register: the buffer's address
        mov     inb, #7
        mov     y, inb
        cmp     par, #5 wz      ' destination: the shadow
        muxz    flag, #1
        mov     p, x
        wrlong  x, p
        add     p, #4
        wrlong  y, p
        add     p, #4
        wrlong  flag, p
        cogid   x
        cogstop x
x       long 0
y       long 0
p       long 0
flag    long 0"""
    image = pasm_program(body)
    vbase = struct.unpack_from("<H", image, 8)[0]
    chip_mode = buf_longs(Chip(image, compat="chip").run(), image)
    assert chip_mode[:3] == [vbase, 0, 1]
    spinsim_mode = buf_longs(Chip(image).run(), image)      # spinsim: PAR and INB are plain RAM
    assert spinsim_mode[:2] == [0, 0]                       # (x = 5 was written to hub long 5 ...)


def test_chip_mode_cog_loads_for_7952_cycles_and_each_cog_has_its_own_hub_window():
    body = """        mov     t, cnt
        rdlong  x, #0
        mov     u, cnt
        wrlong  t, par
        mov     p, par
        add     p, #4
        wrlong  u, p
        cogid   x
        cogstop x
t       long 0
u       long 0
x       long 0
p       long 0"""
    image = pasm_program(body)
    for compat, phase in (("chip", (8 + 2) & 15), ("spinsim", 8)):
        result = Chip(image, compat=compat).run()
        start = next(e[0] for e in result.cog_events if e[1] == 1 and e[2] == "start")
        t, u = buf_longs(result, image)[:2]
        assert t == start + 4                               # the first instruction reads CNT
        assert u % 16 == phase                              # the rdlong ended on cog 1's window
        spin_done = [e for e in result.cog_events if e[1] == 1][0][0]
        if compat == "chip":
            assert spin_done > 7_952


# ----------------------------------------------------------------------------- counters (no spinsim oracle)
def test_phs_counts_frq_per_clock_from_the_write_and_a_destination_read_sees_the_shadow():
    body = """        movi    ctra, #%0_11111_000    ' LOGIC always: PHS += FRQ every clock
        mov     frqa, #3
        mov     phsa, #5        ' PHS = 5 from here
        mov     a, phsa         ' 4 cycles later
        mov     b, phsa
        add     phsa, #1        ' reads the shadow (5), writes 6
        mov     c, phsa
        mov     p, par
        wrlong  a, p
        add     p, #4
        wrlong  b, p
        add     p, #4
        wrlong  c, p
        cogid   a
        cogstop a
a       long 0
b       long 0
c       long 0
p       long 0"""
    image = pasm_program(body)
    a, b, c = buf_longs(Chip(image).run(), image)[:3]
    assert (a, b - a, c) == (5, 12, 6)


def test_an_nco_counter_started_from_pasm_toggles_its_pin_every_half_period():
    body = """        mov     ctra, ctr
        mov     frqa, frq
        mov     dira, #1
        mov     t, cnt
        add     t, delay
        waitcnt t, #0
        mov     dira, #0
        cogid   t
        cogstop t
ctr     long    %00100 << 26 | 0        ' NCO single-ended on P0
frq     long    $0100_0000              ' PHS[31] toggles every 2^31 / 2^24 = 128 clocks
delay   long    2000
t       long    0"""
    result = Chip(pasm_program(body)).run()
    changes = result.trace.changes
    edges = [t for (t, d, o), (_, d0, o0) in zip(changes[2:], changes[1:]) if d == d0 == 1 and o != o0]
    assert len(edges) > 10
    assert {b - a for a, b in zip(edges, edges[1:])} == {128}


# ----------------------------------------------------------------------------- bad programs, limits
@pytest.mark.parametrize("seed", range(6))
def test_a_cog_running_random_longs_never_raises(seed):
    rng = random.Random(seed)
    longs = ", ".join(f"${rng.getrandbits(32):08X}" for _ in range(400))
    image = pasm_program(f"        long    {longs}")
    for compat in ("spinsim", "chip"):
        result = Chip(image, compat=compat).run(max_cycles=400_000)
        assert result.reason in ("cycle limit", "all cogs stopped", "deadlock", "reboot")


def test_hub_writes_past_ram_are_ignored_and_reads_wrap_at_64k():
    body = """        wrlong  minus, rom      ' ROM: ignored
        rdlong  x, rom
        rdlong  y, wrap         ' $1_0004 reads hub long 1
        mov     p, par
        wrlong  x, p
        add     p, #4
        wrlong  y, p
        cogid   x
        cogstop x
minus   long    -1
rom     long    $E000
wrap    long    $1_0004
x       long    0
y       long    0
p       long    0"""
    image = pasm_program(body)
    result = Chip(image).run()
    x, y = buf_longs(result, image)[:2]
    assert x != 0xFFFFFFFF and x == struct.unpack_from("<I", Chip(image).mem, 0xE000)[0]
    assert y == struct.unpack_from("<I", result.hub, 4)[0]


def test_the_cycle_limit_ends_a_pasm_loop_exactly():
    image = pasm_program("loop    add     x, #1\n        jmp     #loop\nx long 0")
    result = Chip(image).run(max_cycles=1_000_003)
    assert (result.reason, result.end_cycle) == ("cycle limit", 1_000_003)
    assert 240_000 < result.stats["pasm_instructions"] <= 1_000_003 // 4


def test_a_clkset_with_the_reset_bit_reboots():
    result = Chip(pasm_program("        clkset  m\nm long $80")).run(max_cycles=1_000_000)
    assert result.reason == "reboot"


# ----------------------------------------------------------------------------- tools
def test_trace_cog_reports_every_instruction_with_flags_and_value():
    image = pasm_program("        mov     x, #5 wz\n        add     x, #3 wc\n        cogid   x\n"
                         "        cogstop x\nx long 0")
    chip = Chip(image)
    steps = []
    chip.trace_cog(1, steps.append)
    chip.run()
    assert [(s.pc, s.result, s.z, s.c) for s in steps] == [(0, 5, 0, 0), (1, 8, 0, 0), (2, 1, 0, 0), (3, None, 0, 0)]
    assert steps[1].cycle == steps[0].cycle + 4
    assert "add $004, #$003 wc" in steps[1].text() and "-> $00000008" in steps[1].text()


def test_pasm_start_is_named_by_its_dat_label_and_counted_in_stats():
    prog = compile_source("PUB main\n  cognew(@blinker, 0)\nDAT\n        org 0\nblinker jmp #blinker\n")
    result = Chip(prog.binary, labels=prog.dat_labels()).run(max_cycles=100_000)
    start = [e for e in result.cog_events if e[1] == 1][0]
    assert "PASM at $" in start[3] and "'blinker' in main.spin" in start[3]
    assert result.stats["pasm_instructions_per_cog"][1] > 10_000


def test_run_command_traces_a_cog_and_lists_pasm_cogs(tmp_path):
    src = tmp_path / "p.spin"
    src.write_text("PUB main\n  cognew(@entry, 0)\nDAT\n        org 0\nentry   add x, #1\n"
                   "        jmp #entry\nx long 0\n")
    log = tmp_path / "cog1.log"
    out = io.StringIO()
    assert main(["run", str(src), "--cycles", "3000", "--trace-cog", "1", "--trace-cog-file", str(log),
                 "--no-progress"], stdout=out) == 0
    lines = log.read_text().splitlines()
    assert lines and "cog 1 $000 entry" in lines[0] and "add x, #$001" in lines[0]   # DAT labels name it
    assert "jmp #entry" in lines[1]
    assert "'entry' in p.spin" in out.getvalue() and "instructions" in out.getvalue()


def test_the_python_engine_runs_pasm_cogs_as_the_bytecode_engine(tmp_path):
    from spinemu.translate import run_translated
    src = tmp_path / "p.spin"
    src.write_text("VAR\n  long flag\nPUB main\n  cognew(@entry, @flag)\n  repeat until flag\n"
                   "  dira[3] := outa[3] := 1\nDAT\n        org 0\nentry   mov t, cnt\n"
                   "        add t, #400\n        waitcnt t, #0\n        wrlong one, par\n        mov dira, #1\n"
                   "        cogid t\n        cogstop t\none long 1\nt long 0\n")
    a = run_translated(str(src), max_cycles=100_000)
    b = Chip(compile_source(src.read_text()).binary).run(max_cycles=100_000)
    assert a.trace.changes == b.trace.changes and len(a.trace.changes) == 5


def test_a_pasm_hub_write_wakes_a_parked_spin_loop_at_the_right_cycle():
    src = ("VAR\n  long flag\nPUB main\n  cognew(@entry, @flag)\n  repeat until flag\n  dira[0] := 1\n"
           "  repeat until flag == 2\n  dira[1] := 1\nDAT\n        org 0\nentry   mov t, cnt\n"
           "        add t, delay\n        waitcnt t, delay\n        wrlong one, par\n        waitcnt t, #0\n"
           "        wrlong two, par\n        cogid t\n        cogstop t\none long 1\ntwo long 2\n"
           "delay long 200_000\nt long 0\n")
    image = compile_source(src).binary
    fast = Chip(image).run()
    slow = Chip(image, fast_forward=False, compile_blocks=False).run()
    assert fast.stats["bytecodes_skipped"] > 0              # the Spin loops were parked
    assert fast.trace.changes == slow.trace.changes and fast.end_cycle == slow.end_cycle
    assert len(fast.trace.changes) == 4


def test_waitpeq_on_an_input_stimulus_ends_at_the_first_poll_after_the_edge():
    from spinemu.chip.inputs import PinStimulus
    image = pasm_program("        waitpeq bit, bit\n        mov     x, cnt\n        cogid   x\n        cogstop x\n"
                         "bit long 1 << 7\nx long 0")
    for edge in (1_000_001, 1_000_002, 1_000_003, 1_000_004):
        chip = Chip(image, inputs=PinStimulus([(edge, 1 << 7, 1 << 7)]))
        steps = []
        chip.trace_cog(1, steps.append)
        chip.run()
        wait, after = steps[0], steps[1]
        poll = edge + ((wait.cycle - edge) & 3)         # polls fall on the cog's 4-cycle grid
        assert after.cycle == poll + 4 and after.result == poll + 4
