"""PBASIC 2.5 statements on the BS2: control flow, RAM model, EEPROM, tables.

Each test is a small program whose DEBUG output or final RAM says what
happened.  Rules: BS2 semantics reference (README 1, 2, 4) and the BASIC
Stamp manual's command pages.
"""
import pytest

from spinemu.diagnostics import SpinError

from .conftest import bs2, run


def out(body: str, **kw) -> str:
    return run(body, **kw).debug_output


# ------------------------------------------------------------------ RAM model
def test_variables_share_ram_with_fixed_names_and_aliases():
    res = run("w VAR Word\nhi VAR w.HIGHBYTE\nn VAR hi.LOWNIB\n"
              "w = $1234\nn = $F\nB2 = 7")
    assert res.var("w") == 0x1F34
    assert res.ram[6:8] == bytes([0x34, 0x1F])
    assert res.var("B2") == 7 and res.var("W1") == 7


def test_unchecked_index_reaches_the_next_variable():
    res = run("a VAR Byte\nb VAR Byte\na(1) = 99")
    assert res.var("b") == 99


def test_modifier_with_index_counts_in_the_modifier_size():
    res = run("arr VAR Byte(2)\narr.LOWNIB(1) = $A\narr.LOWNIB(2) = 5")
    assert res.var("arr") == 0xA0 and res.ram[7] == 5


def test_index_past_ram_wraps_and_warns():
    res = run("a VAR Word\na(20) = $55")       # word 3 + 20 = word 23 -> word 7
    assert res.ram[14] == 0x55
    assert any("wrapped" in w.message for w in res.warnings)


def test_ins_reads_the_pins_and_ignores_writes():
    res = run("x VAR Word\nHIGH 3\nINS = 0\nx = INS", inputs={5: 1})
    assert res.var("x") == 0b101000
    assert any("INS" in w.message for w in res.warnings)


def test_undriven_inputs_read_the_float_level():
    assert run("x VAR Bit\nx = IN7").var("x") == 0
    assert run("x VAR Bit\nx = IN7", float_level=1).var("x") == 1


def test_setting_a_dir_bit_drives_the_latch():
    res = run("OUT2 = 1\nDIR2 = 1\nDIR3 = 1")
    assert res.trace.changes[-2:] == [(0, 0b0100, 0b0100), (0, 0b1100, 0b0100)]


def test_out_of_variable_space_is_a_compile_error():
    with pytest.raises(SpinError, match="out of variable space"):
        bs2("w VAR Word(13)\nb VAR Bit\nw = 1")


# ------------------------------------------------------------------ IF, SELECT
@pytest.mark.parametrize("x, text", [(0, "a"), (1, "b"), (2, "c"), (3, "d")])
def test_block_if_elseif_else(x, text):
    assert out(f"x VAR Byte\nx = {x}\nIF x = 0 THEN\nDEBUG \"a\"\nELSEIF x = 1 THEN\n"
               f"DEBUG \"b\"\nELSEIF x = 2 THEN\nDEBUG \"c\"\nELSE\nDEBUG \"d\"\nENDIF") == text


@pytest.mark.parametrize("x, text", [(0, "ab!"), (1, "cd!")])
def test_single_line_if_else_owns_the_rest_of_its_line(x, text):
    assert out(f"x VAR Byte\nx = {x}\nIF x = 0 THEN DEBUG \"a\" : DEBUG \"b\" ELSE DEBUG \"c\" : "
               f"DEBUG \"d\"\nDEBUG \"!\"") == text


def test_if_then_label_jumps():
    assert out("x VAR Byte\nIF x = 0 THEN Over\nDEBUG \"no\"\nOver: DEBUG \"yes\"") == "yes"


def test_if_then_goto_colon_statement_runs_when_false():
    # Parallax's tokenizer treats 'IF c THEN GOTO L : s' as the jump form followed by s.
    assert out("x VAR Byte\nx = 1\nIF x = 0 THEN GOTO L : DEBUG \"s\"\nL: DEBUG \"L\"") == "sL"


def test_nested_blocks():
    src = ("i VAR Byte\nj VAR Byte\nFOR i = 1 TO 3\nIF i = 2 THEN\nFOR j = 1 TO 2\n"
           "DEBUG DEC i, DEC j, \" \"\nNEXT\nELSE\nDEBUG DEC i, \" \"\nENDIF\nNEXT")
    assert out(src) == "1 21 22 3 "


@pytest.mark.parametrize("x, text", [(0, "zero"), (3, "low"), (9, "low"), (7, "big"),
                                     (200, ""), (6, "else")])
def test_select_case(x, text):
    src = (f"x VAR Byte\nx = {x}\nSELECT x\nCASE 0\nDEBUG \"zero\"\nCASE 1 TO 5, 9\n"
           f"DEBUG \"low\"\nCASE > 6, = 100\nIF x < 100 THEN DEBUG \"big\"\nCASE ELSE\n"
           f"DEBUG \"else\"\nENDSELECT")
    assert out(src) == text


def test_select_evaluates_its_expression_once():
    assert out("x VAR Byte\nSELECT x\nCASE 0\nx = 1\nDEBUG \"a\"\nCASE 1\nDEBUG \"b\"\n"
               "ENDSELECT") == "a"


# ------------------------------------------------------------------ loops
def test_do_loop_forms():
    assert out("x VAR Byte\nDO WHILE x < 5\nx = x + 1\nLOOP\nDEBUG DEC x") == "5"
    assert out("x VAR Byte\nDO UNTIL x = 3\nx = x + 1\nLOOP\nDEBUG DEC x") == "3"
    assert out("x VAR Byte\nDO\nx = x + 1\nLOOP WHILE x < 7\nDEBUG DEC x") == "7"
    assert out("x VAR Byte\nDO\nx = x + 1\nLOOP UNTIL x = 9\nDEBUG DEC x") == "9"
    assert out("x VAR Byte\nx = 50\nDO\nx = x + 1\nLOOP UNTIL 1\nDEBUG DEC x") == "51"


def test_exit_leaves_the_innermost_loop():
    src = ("i VAR Byte\nj VAR Byte\nFOR i = 1 TO 3\nDO\nj = j + 1\nIF j // 2 = 0 THEN EXIT\n"
           "LOOP\nIF i = 2 THEN EXIT\nNEXT\nDEBUG DEC i, \",\", DEC j")
    assert out(src) == "2,4"


def test_for_leaves_the_first_out_of_range_value():
    assert out("x VAR Byte\nFOR x = 1 TO 48\nNEXT\nDEBUG DEC x") == "49"


def test_for_body_runs_once_even_when_the_range_is_empty_for_the_step():
    assert out("x VAR Word\nFOR x = 1 TO 10 STEP -1\nDEBUG DEC x, \" \"\nNEXT") == "1 "


def test_for_counts_down_when_start_is_above_end():
    assert out("x VAR Byte\nFOR x = 10 TO 1 STEP 3\nDEBUG DEC x, \" \"\nNEXT") == "10 7 4 1 "


def test_for_byte_counter_from_10_to_300_stops_when_it_wraps_to_0():
    res = run("x VAR Byte\nn VAR Word\nFOR x = 10 TO 300\nn = n + 1\nNEXT\nDEBUG DEC x")
    assert res.debug_output == "0" and res.var("n") == 246 and res.reason == "end"


def test_for_byte_counter_from_0_to_300_never_stops():
    res = run("x VAR Byte\nFOR x = 0 TO 300\nNEXT", max_instructions=3000)
    assert res.reason == "instructions"


def test_for_word_counter_wraps_back_into_range_with_step_3000():
    res = run("x VAR Word\nn VAR Word\nFOR x = 0 TO 65535 STEP 3000\nn = n + 1\n"
              "IF x = 464 THEN EXIT\nNEXT\nDEBUG DEC n")
    assert res.debug_output == "23"       # 0, 3000, ..., 63000 (22 values), then 464


def test_next_reevaluates_start_end_and_step():
    # Parallax manual: changing the loop's limits inside reverses it: 1 2 3 2 1
    src = ("x VAR Byte\na VAR Byte\nb VAR Byte\na = 1\nb = 3\nFOR x = a TO b\n"
           "DEBUG DEC x, \" \"\nIF x = 3 THEN a = 3 : b = 1\nNEXT")
    assert out(src) == "1 2 3 2 1 "
    assert out("x VAR Byte\ns VAR Byte\ns = 1\nFOR x = 1 TO 20 STEP s\nDEBUG DEC x, \" \"\n"
               "s = s * 2\nNEXT") == "1 3 7 15 "


# ------------------------------------------------------------------ jumps, subroutines
def test_gosub_return_nests():
    assert out("GOSUB A\nDEBUG \"3\"\nEND\nA: DEBUG \"1\"\nGOSUB B\nRETURN\nB: DEBUG \"2\"\n"
               "RETURN") == "123"


def test_fifth_nested_gosub_overwrites_the_oldest_return_point():
    src = ("n VAR Byte\nGOSUB A\nDEBUG \"top\"\nEND\nA: GOSUB B\nRETURN\nB: GOSUB C\nRETURN\n"
           "C: GOSUB D\nRETURN\nD: GOSUB E\nRETURN\nE: n = n + 1\nIF n < 3 THEN RETURN\nSTOP")
    res = run(src, max_instructions=500)
    assert "top" not in res.debug_output
    assert any("deeper than 4" in w.message for w in res.warnings)


def test_return_without_gosub_restarts_without_clearing_ram():
    res = run("x VAR Byte\nx = x + 1\nIF x = 3 THEN STOP\nRETURN")
    assert res.reason == "stop" and res.var("x") == 3
    assert any("RETURN without a pending GOSUB" in w.message for w in res.warnings)


def test_gosub_model_restart_always_starts_over():
    src = ("x VAR Byte\nx = x + 1\nIF x = 3 THEN STOP\nGOSUB S\nRETURN\nS: RETURN")
    assert run(src, gosub_model="restart").var("x") == 3


def test_on_goto_on_gosub_and_branch():
    assert out("x VAR Byte\nx = 2\nON x GOTO A, B, C\nEND\nA: DEBUG \"A\"\nEND\n"
               "B: DEBUG \"B\"\nEND\nC: DEBUG \"C\"") == "C"
    assert out("x VAR Byte\nx = 5\nBRANCH x, [A, B]\nDEBUG \"fell\"\nEND\nA: DEBUG \"A\"\n"
               "END\nB: DEBUG \"B\"") == "fell"
    assert out("x VAR Byte\nx = 1\nON x GOSUB A, B\nDEBUG \"!\"\nEND\nA: DEBUG \"A\"\nRETURN\n"
               "B: DEBUG \"B\"\nRETURN") == "B!"


def test_end_stop_and_falling_off_the_end():
    assert run("HIGH 1\nEND\nLOW 1").reason == "end"
    assert run("STOP").reason == "stop"
    res = run("HIGH 1")
    assert res.reason == "end" and res.trace.changes[-1] == (0, 2, 2)


def test_end_glitch_releases_outputs_every_2304_ms():
    res = run("HIGH 1\nEND", seconds=5, end_glitch=True)
    assert res.trace.changes[1:] == [(0, 2, 2), (2_304_000, 0, 0), (2_322_000, 2, 2),
                                     (4_608_000, 0, 0), (4_626_000, 2, 2)]


# ------------------------------------------------------------------ EEPROM, tables
def test_read_data_with_word_and_lists():
    src = ("T DATA Word 1000, \"hi\", 7(2)\nw VAR Word\na VAR Byte\nb VAR Byte\nc VAR Byte\n"
           "READ T, Word w, a, b\nREAD T + 4, c\nDEBUG DEC w, \" \", a, b, \" \", DEC c")
    assert out(src) == "1000 hi 7"


def test_read_into_a_nibble_keeps_the_low_bits():
    res = run("T DATA $AB\nREAD T, OUTB\nDIRB = %1111")
    assert res.trace.changes[-1] == (0, 0xF0, 0xB0)


def test_write_then_read_back_and_eeprom_survives():
    res = run("w VAR Word\nWRITE 100, Word 513, 9\nREAD 100, Word w\nDEBUG DEC w")
    assert res.debug_output == "513"
    assert res.eeprom[100:103] == bytes([1, 2, 9])


def test_read_of_an_undefined_address_reads_zero_and_warns():
    res = run("x VAR Byte\nT DATA 5\nREAD 7, x")
    assert res.var("x") == 0
    assert any("no DATA statement defines" in w.message for w in res.warnings)


def test_eeprom_write_takes_time_in_realistic_timing_only():
    assert run("WRITE 0, 1, 2").end_cycle == 0
    assert run("WRITE 0, 1, 2", timing="realistic").end_cycle == 250 + 10_000 + 250


def test_lookup_and_lookdown():
    assert out("x VAR Byte\nLOOKUP 2, [10, 20, 30], x\nDEBUG DEC x, \" \"\n"
               "LOOKUP 3, [10, 20, 30], x\nDEBUG DEC x") == "30 30"
    assert out("x VAR Byte\nx = 9\nLOOKDOWN \"M\", [\"SLMH\"], x\nDEBUG DEC x, \" \"\n"
               "LOOKDOWN 17, > [26, 177, 13, 1, 0, 17, 99], x\nDEBUG DEC x, \" \"\n"
               "LOOKDOWN 500, [1, 2], x\nDEBUG DEC x") == "2 2 2"


def test_random_is_deterministic_and_changes_the_variable():
    a = run("x VAR Word\nRANDOM x\nRANDOM x")
    b = run("x VAR Word\nRANDOM x\nRANDOM x")
    assert a.var("x") == b.var("x") != 0
    assert any("RANDOM" in w.message for w in a.warnings)


# ------------------------------------------------------------------ language level
def test_pbasic_20_rejects_25_statements():
    from spinemu.pbasic import compile_source
    with pytest.raises(SpinError, match="needs PBASIC 2.5"):
        compile_source("' {$STAMP BS2}\nx VAR Byte\nDO\nLOOP\n")
    prog = compile_source("' {$STAMP BS2}\nx VAR Byte\nx = 1\nIF x = 1 THEN Done\nDone:\n")
    assert prog.language == "2.0"


def test_conditional_compilation():
    src = ("#SELECT $STAMP\n#CASE BS2, BS2E\nBaud CON 84\n#CASE #ELSE\nBaud CON 240\n"
           "#ENDSELECT\n#DEFINE Debugging\n#IF Debugging #THEN\nDEBUG DEC Baud\n#ELSE\n"
           "DEBUG \"quiet\"\n#ENDIF")
    assert out(src) == "84"


def test_line_ending_in_a_comma_continues():
    assert out("x VAR Byte\nLOOKUP 1, [5,   ' first\n  6,\n  7], x\nDEBUG DEC x") == "6"


def test_statements_separated_by_colons_and_labels_with_statements():
    assert out("x VAR Byte\nStart: x = 1 : DEBUG DEC x : x = 2 : DEBUG DEC x") == "12"


def test_reading_an_unstimulated_input_warns_once_per_place():
    res = run("x VAR Bit\nFOR B1 = 1 TO 3\nx = IN7\nNEXT\nHIGH 6\nx = IN6")
    (w,) = res.warnings
    assert "P7" in w.message and "[OPEN]" in w.message and w.line == 5 and "3 times" in w.message
    assert run("x VAR Bit\nx = IN7", inputs={7: 0}).warnings == []


def test_for_counter_wrapping_in_a_byte_warns_where_the_open_rule_decides():
    res = run("x VAR Byte\nFOR x = 10 TO 300\nNEXT")
    assert any("wrapped inside its variable" in w.message for w in res.warnings)
    assert run("x VAR Word\nFOR x = 10 TO 300\nNEXT").warnings == []
