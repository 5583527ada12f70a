"""ROM tables and the timing table.

The ROM checksums were measured by running tests/data/chip/programs/rom_tables.spin
on spinsim 0.99 (it sums, weights and rotates every entry of the three tables);
the conformance suite checks the same program end to end.
"""
from __future__ import annotations

from spinemu.bytecode import TABLE
from spinemu.chip.rom import INTERPRETER_ENTRY, RETURN_TO_STOP, build_rom
from spinemu.chip.spin import build_handlers
from spinemu.chip.timing import load_timing, segments_rest

M = 0xFFFFFFFF
SPINSIM_SUMS = [74767448, 364680304, 3724474691, 59384771, 1956624696, 2895021702,
                85477121, 4180522639, 1752756101]


def _checks(words):
    rol = lambda a, i: ((a << (i & 31)) | (a >> (32 - (i & 31)))) & M   # noqa: E731
    x = 0
    for i, a in enumerate(words):
        x ^= rol(a, i)
    return [sum(words) & M, sum(a * (i + 1) for i, a in enumerate(words)) & M, x]


def test_log_antilog_and_sine_tables_match_the_rom():
    rom = build_rom()
    word = lambda addr, i: int.from_bytes(rom[addr - 0x8000 + 2 * i:][:2], "little")  # noqa: E731
    got = (_checks([word(0xC000, i) for i in range(2048)]) + _checks([word(0xD000, i) for i in range(2048)])
           + _checks([word(0xE000, i) for i in range(2049)]))
    assert got == SPINSIM_SUMS


def test_rom_holds_the_cogstop_bytecodes_at_the_boot_frame_return_address():
    rom = build_rom()
    assert rom[RETURN_TO_STOP - 0x8000: RETURN_TO_STOP - 0x8000 + 3] == bytes([0x3F, 0x89, 0x21])
    assert INTERPRETER_ENTRY == 0xF004


def test_timing_table_has_every_path_the_interpreter_asks_for():
    assert load_timing().missing == set()


def test_dispatch_list_covers_all_256_bytecodes_from_the_table():
    class Dummy:                      # build_handlers only needs these attributes
        mem = bytearray(0x10000)
        mem_words = memoryview(mem).cast("H")
        mem_longs = memoryview(mem).cast("I")
        watch = bytearray(0x4000)
        registers = type("R", (), {"read": None, "write": None})()
    handlers = build_handlers(Dummy(), load_timing())
    assert len(handlers) == 256 and all(callable(h) for h in handlers)
    names = {TABLE[i].handler for i in range(256)}
    assert "op_unknown" in names and handlers[0x3C].__name__ == "op_unknown"


def test_a_path_of_plain_and_hub_instructions_rounds_hub_waits_to_the_window():
    # ADD: 14 plain, pop, 1 plain, pop, 21 plain, push, 3 plain (measured on spinsim)
    assert segments_rest([14, "H", 1, "H", 21, "H", 3], phase=8, t=8) == 188 == load_timing().math(0x0C, 1, 2)


def test_access_offsets_lie_inside_the_shortest_path_of_their_bytecode():
    """Otherwise a cog's next bytecode could be ordered before its previous one."""
    from spinemu.chip.timing import access_offsets
    t = load_timing()
    acc = access_offsets()
    for op in range(0x40, 0x80):
        shortest = t.var_using[bool(op & 0x20)] if op & 3 == 2 else t.var[op]
        assert acc[op] <= shortest, hex(op)
    for op in range(0x80, 0xE0):
        table = t.mem_using if op & 3 == 2 else t.mem
        assert acc[op] <= table[(op, False)] + (min(t.assign_mem) if op & 3 == 2 else 0), hex(op)
    assert acc[0x3F] <= t.reg[(0x3F, 0)] and acc[0x3D] <= t.reg[(0x3D, 0)] and acc[0x3E] <= t.reg[(0x3E, 0)]


def test_rom_ends_with_the_chip_version_chipver_reads():
    from spinemu.chip.rom import CHIP_VERSION

    assert CHIP_VERSION == 1 and build_rom()[0xFFFF - 0x8000] == 1      # the P8X32A
