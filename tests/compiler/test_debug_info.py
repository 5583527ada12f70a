"""Debug information (CompiledProgram.debug_info): names and places, with the image untouched."""
from pathlib import Path

from spinemu.compiler import compile_file, compile_source

ROOT = Path(__file__).parent.parent.parent
DEMO = ROOT / "spin_src" / "corrected" / "stepper_demo.spin"
ARTICLE = ROOT / "tests" / "data" / "article"


def test_debug_info_leaves_the_image_byte_identical():
    prog = compile_file(str(DEMO))
    before = prog.binary
    prog.debug_info()
    assert prog.binary == before == (ARTICLE / "corrected_stepper_demo.binary").read_bytes()


def test_every_method_has_its_frame_slots_by_name_and_offset():
    info = compile_file(str(DEMO)).debug_info()
    by_name = {m.name: m for m in info.methods}
    run = by_name["runStepper"]
    assert [(s.name, s.offset, s.kind) for s in run.slots] == [
        ("result", 0, "result"), ("m1", 4, "param"), ("m4", 8, "local"), ("c", 12, "local")]
    start = by_name["start"]
    assert [(s.name, s.kind) for s in start.slots] == [("okay", "result"), ("ePin", "param"), ("mnTime", "param")]
    assert start.nparams == 2 and run.first_local == 8


def test_method_at_finds_the_method_of_any_code_address():
    info = compile_file(str(DEMO)).debug_info()
    for m in info.methods:
        assert info.method_at(m.start) is m and info.method_at(m.end - 1) is m
    assert info.method_at(0x0004) is None


def test_var_and_dat_are_found_by_name_and_by_address():
    info = compile_file(str(DEMO)).debug_info()
    inst, stack = info.find_variable("motor.stack")
    assert inst.name == "motor" and stack.count == 64 and stack.size == 4 and stack.section == "VAR"
    assert info.variable_at(stack.addr + 100)[1] is stack
    inst, steps = info.find_variable("motor.Steps")
    assert steps.section == "DAT" and steps.size == 1 and steps.count == 4
    assert info.find_variable("idx")[1].name == "idx"               # the top object's VAR
    assert info.find_variable("nosuch") is None


def test_positions_carry_the_statement_column():
    prog = compile_source("PUB main | x\n  x := 1\n  if x\n    outa[0]~~\n")
    info = prog.debug_info()
    cols = {(line, col) for _s, _e, _p, line, col in prog.line_table.items(columns=True)}
    assert {(2, 3), (3, 3), (4, 5)} <= cols
    start = info.methods[0].start
    assert info.position(start)[1:] == (2, 3) and prog.line_table.position(start)[1:] == (2, 3)


def test_code_ranges_cover_tables_and_code_but_not_dat():
    info = compile_file(str(DEMO)).debug_info()
    ranges = info.code_ranges()
    steps = info.find_variable("motor.Steps")[1]
    assert not any(a <= steps.addr < b for a, b in ranges)
    for m in info.methods:
        assert any(a <= m.start and m.end <= b for a, b in ranges)
