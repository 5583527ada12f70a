"""PBASIC programs a new user's editor or typing makes, which used to crash or mislead (found by tests/fuzz/robust)."""
import pytest

from spinemu.diagnostics import SpinError
from spinemu.pbasic import compile_file, compile_source, run_file

HEAD = "' {$STAMP BS2}\n' {$PBASIC 2.5}\n"
PROGRAM = HEAD + "x VAR Byte\nx = 7\nHIGH 3\nPAUSE 1\nEND\n"


def error_of(body: str) -> SpinError:
    with pytest.raises(SpinError) as info:
        compile_source(HEAD + body, "odd.bs2")
    return info.value


@pytest.mark.parametrize("expr", ["-" * 300 + "1", " + ".join(["1"] * 3000), "ABS " * 500 + "1"])
def test_a_very_deep_expression_is_too_complex_not_a_recursion_error(expr):
    err = error_of(f"x VAR Word\nx = {expr}\n")
    assert "too complex" in err.diagnostics[0].message and err.diagnostics[0].line == 4


def test_deep_parentheses_around_a_constant_still_compile():
    prog = compile_source(HEAD + "x VAR Word\nx = " + "(" * 3000 + "5" + ")" * 3000 + "\nEND\n")
    assert run_file(prog).var("x") == 5


def test_a_number_of_five_thousand_digits_exceeds_16_bits():
    err = error_of("x VAR Word\nx = " + "9" * 5000 + "\n")
    assert err.diagnostics[0].message == "constant exceeds 16 bits"


@pytest.mark.parametrize("encoding,bom", [("utf-8", b"\xef\xbb\xbf"), ("utf-16-le", b"\xff\xfe"),
                                          ("utf-16-be", b"\xfe\xff")])
def test_a_source_saved_with_a_byte_order_mark_runs(tmp_path, encoding, bom):
    path = tmp_path / "bom.bs2"
    path.write_bytes(bom + PROGRAM.encode(encoding))
    res = run_file(compile_file(str(path)))
    assert res.reason == "end" and res.var("x") == 7


@pytest.mark.parametrize("separator", ["\x0c", "\u2028", "\x85"])
def test_a_separator_character_in_a_comment_does_not_shift_the_quoted_line(separator):
    err = error_of(f"' note{separator}more\nx VAR Byte\ny = 1\n")
    text = err.render().splitlines()
    assert text[0].startswith("odd.bs2:5:1: error:") and text[1] == "y = 1"
