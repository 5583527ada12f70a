"""PBASIC expressions on the BS2: every operator, the left-to-right rule,
16-bit wrap, truncation on store, conditions, and the OPEN corner cases.

Values are from the BS2 semantics reference (README 3.1-3.4) and the
BASIC Stamp manual's operator pages; each test runs a tiny program.
"""
import pytest

from spinemu.diagnostics import SpinError
from spinemu.pbasic.exprs import binary, cos_b, sin_b, unary

from .conftest import bs2, run


def value(expr: str, var_type: str = "Word") -> int:
    res = run(f"x VAR {var_type}\nx = {expr}")
    return res.var("x")


@pytest.mark.parametrize("expr, expected", [
    ("7 + 5", 12), ("5 - 7", 65534), ("65535 + 1", 0),
    ("300 * 300", (300 * 300) & 0xFFFF), ("$FFFF ** $FFFF", 0xFFFE), ("1000 ** 1000", 15),
    ("100 */ $0180", 150), ("$1234 */ $0100", 0x1234),
    ("17 / 5", 3), ("17 // 5", 2), ("-1 / 2", 32767),
    ("3 MIN 10", 10), ("30 MIN 10", 30), ("30 MAX 10", 10), ("3 MAX 10", 3),
    ("-1 MIN 5", 65535),
    ("9742 DIG 0", 2), ("9742 DIG 2", 7), ("9742 DIG 3", 9), ("65535 DIG 4", 6),
    ("1 << 15", 32768), ("$8000 >> 15", 1), ("$FFFF << 4", 0xFFF0),
    ("%10101101 REV 4", 0b1011), ("%1 REV 16", 0x8000), ("$FF00 REV 8", 0),
    ("%1100 & %1010", 0b1000), ("%1100 | %1010", 0b1110), ("%1100 ^ %1010", 0b0110),
    ("%1100 &/ %1010", 0b0100), ("%1100 |/ %1010", 0xFFFD), ("%1100 ^/ %1010", 0xFFF9),
    ("- 5", 65531), ("~ 0", 65535), ("~ $F0F0", 0x0F0F),
    ("ABS -5", 5), ("ABS 5", 5), ("ABS $8000", 0x8000),
    ("SQR 99", 9), ("SQR 100", 10), ("SQR 65535", 255),
    ("DCD 3", 8), ("DCD 15", 32768), ("DCD 17", 2),
    ("NCD 0", 0), ("NCD 1", 1), ("NCD %1101", 4), ("NCD $8000", 16),
    ("SIN 0", 0), ("SIN 32", 90), ("SIN 64", 127), ("SIN 192", 0xFF81),
    ("COS 0", 127), ("COS 64", 0), ("COS 128", 0xFF81),
    ("3 HYP 4", 5), ("0 ATN 10", 64), ("10 ATN 0", 0), ("-10 ATN 0", 128),
    ("\"A\"", 65), ("$7F", 127), ("%1010", 10),
])
def test_operator(expr, expected):
    assert value(expr) == expected


@pytest.mark.parametrize("expr, expected", [
    ("12 + 3 * 2 / 4", 7),             # ((12 + 3) * 2) / 4, not 12 + ((3 * 2) / 4)
    ("2 + 3 * 4", 20),
    ("10 - 2 - 3", 5),
    ("10 - (2 - 3)", 11),
    ("2 + (3 * 4)", 14),
    ("1 + 1 // 4", 2),                 # the demo's stpIdx + 1 // 4 with stpIdx = 1
    ("3 + 1 // 4", 0),
    ("10 - SQR 16", 6),                # a unary binds to the operand right after it
    ("5 - - 3", 8),                    # '-' where an operand is expected is negation
    ("ABS - 3", 3),                    # unaries chain right to left
    ("- ABS - 3", 65533),
    ("SQR 16 + 9", 13),
    ("~ 1 & 3", 2),
    ("2 * 3 MIN 10 MAX 8", 8),
])
def test_binary_operators_apply_strictly_left_to_right(expr, expected):
    assert value(expr) == expected


@pytest.mark.parametrize("var_type, expr, expected", [
    ("Nib", "15 + 1", 0), ("Nib", "%10011", 3), ("Byte", "300", 44),
    ("Byte", "255 + 1", 0), ("Bit", "2", 0), ("Bit", "3", 1), ("Word", "70000 - 70000 + 1", 1),
])
def test_stores_keep_only_the_bits_that_fit(var_type, expr, expected):
    if "70000" in expr:
        with pytest.raises(SpinError, match="exceeds 16 bits"):
            bs2(f"x VAR {var_type}\nx = {expr}")
        return
    assert value(expr, var_type) == expected


def test_operands_are_zero_extended_never_sign_extended():
    res = run("b VAR Byte\nw VAR Word\nb = 255\nw = b + 1\nIF b > 5 THEN ok\nw = 0\nok:")
    assert res.var("w") == 256


@pytest.mark.parametrize("cond, taken", [
    ("x = 1", True), ("x <> 1", False), ("x > 0", True), ("x < 0", False),
    ("x >= 1", True), ("x <= 0", False), ("x =< 1", True), ("x => 2", False), ("x >< 1", False),
    ("NOT x", True),                   # NOT 1 = $FFFE, non-zero
    ("x AND y", False),                # 1 AND 2 = 0
    ("x OR y", True), ("x XOR x", False),
    ("NOT x = 1", False),              # NOT applies to the comparison after it
    ("x = 1 OR x = 2 AND x = 3", False),  # (x=1 OR x=2) AND x=3: equal rank, left to right
    ("x = 3 AND x = 2 OR x = 1", True),
    ("(x > 3) + 1", True),             # $0000 + 1: comparisons are values
    ("(x = 1) + 1", False),            # $FFFF + 1 wraps to 0
    ("m > 5", True),                   # unsigned: -1 is 65535
    ("x + 1 > 1", True),               # each side is a left-to-right expression
    ("x", True), ("y - 2", False),
])
def test_conditions(cond, taken):
    res = run(f"x VAR Word\ny VAR Word\nm VAR Word\nr VAR Bit\nx = 1\ny = 2\nm = -1\n"
              f"IF {cond} THEN r = 1")
    assert res.var("r") == (1 if taken else 0)


@pytest.mark.parametrize("expr, expected, warning", [
    ("5 / 0", 65535, "division by zero"),
    ("5 // 0", 5, "division by zero"),
    ("1 << 16", 0, "shift by 16"),
    ("$8000 >> 20", 0, "shift by 20"),
    ("9742 DIG 5", 0, "DIG 5"),
    ("%1011 REV 0", 0, "REV 0"),
    ("3 HYP 4", 5, "ATN/HYP"),
    ("SIN 10", sin_b(10), "SIN/COS"),
])
def test_open_corner_cases_use_the_documented_default_and_warn(expr, expected, warning):
    res = run(f"x VAR Word\ny VAR Word\ny = 0\nx = {expr.replace(' 0', ' y') if '/ 0' in expr else expr}")
    assert res.var("x") == expected
    assert any(warning in w.message and "[OPEN]" in w.message for w in res.warnings)
    assert all(w.severity == "warning" and w.line is not None for w in res.warnings)


def test_documented_sin_points_do_not_warn():
    res = run("x VAR Word\nx = SIN 64 + COS 128")
    assert res.warnings == []


def test_warnings_name_the_line_and_count_repeats():
    res = run("x VAR Word\ny VAR Word\nFOR x = 1 TO 3\ny = x / 0\nNEXT")
    (w,) = res.warnings
    assert w.line == 6 and "3 times" in w.message
    assert w.render().startswith("test.bs2:6:")


def test_depth_nine_expression_is_rejected_at_compile_time():
    bs2("x VAR Word\nx = 1+(2+(3+(4+(5+(6+(7+8))))))")
    with pytest.raises(SpinError) as info:
        bs2("x VAR Word\nx = 1+(2+(3+(4+(5+(6+(7+(8+9)))))))")
    assert info.value.line == 4 and info.value.column == 28
    assert "too complex" in info.value.message


@pytest.mark.parametrize("expr", ["3 > 2", "a AND b", "NOT a", "a = b"])
def test_comparison_and_logic_words_are_errors_outside_conditions(expr):
    with pytest.raises(SpinError) as info:
        bs2(f"x VAR Word\na VAR Word\nb VAR Word\nx = {expr}")
    assert info.value.line == 6


def test_python_helpers_match_the_table():
    assert binary("*/", 100, 0x180) == 150
    assert unary("NOT", 1) == 0xFFFE
    assert sin_b(64) == 127 and cos_b(0) == 127
    assert binary("<>", 1, 2) == 0xFFFF and binary("AND", 1, 2) == 0
