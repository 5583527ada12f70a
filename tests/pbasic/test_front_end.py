"""The PBASIC front end: grammar health, directives, positions and error rendering."""
import io
import logging

import pytest
from lark import Lark, logger

from spinemu.diagnostics import CompileError, ParseError, SpinError
from spinemu.pbasic import compile_file, compile_source
from spinemu.pbasic.syntax import grammar_path, parse_source

from .conftest import HEADER, bs2


def test_grammar_is_lalr_without_conflicts():
    buf = io.StringIO()
    handler = logging.StreamHandler(buf)
    logger.addHandler(handler)
    old = logger.level
    logger.setLevel(logging.DEBUG)
    try:
        Lark(grammar_path().read_text(), parser="lalr", lexer="contextual",
             start=["start", "cond"], debug=True)
    finally:
        logger.removeHandler(handler)
        logger.setLevel(old)
    assert "conflict" not in buf.getvalue().lower()


def test_grammar_file_names_its_reference_and_start_rules():
    head = grammar_path().read_text().splitlines()[:12]
    assert any("Reference Manual" in line for line in head)
    assert any("Start rule" in line for line in head)


def test_keywords_are_case_insensitive_and_source_keeps_its_case():
    res = compile_source("' {$stamp bs2}\n' {$pbasic 2.5}\nmyVar var byte\n"
                         "for myvar = 1 to 3 : next\nHigh 1\n", "x.bs2")
    assert res.symbols.lookup("MYVAR").name == "myVar"


def test_nodes_carry_positions():
    prog = parse_source(HEADER + "x VAR Byte\n  x = 1 + 2\n", "p.bs2")
    assign = [s for s in prog.items if getattr(s, "kind", "") == "assign"][0]
    assert (assign.pos.line, assign.pos.column) == (4, 3)
    assert assign.text == "x = 1 + 2"


def test_missing_stamp_directive_is_an_error_at_the_top():
    with pytest.raises(ParseError) as info:
        compile_source("x VAR Byte\nx = 1\n", "nostamp.bs2")
    assert (info.value.line, info.value.column) == (1, 1)
    assert "$STAMP" in info.value.message


def test_other_stamps_are_refused_with_the_reason():
    with pytest.raises(ParseError, match="BS2SX"):
        compile_source("' {$STAMP BS2sx}\n' {$PBASIC 2.5}\nHIGH 1\n")


def test_unknown_pbasic_version():
    with pytest.raises(ParseError, match="2.0 and 2.5"):
        compile_source("' {$STAMP BS2}\n' {$PBASIC 3.0}\nHIGH 1\n")


@pytest.mark.parametrize("body, line, col, words", [
    ("x VAR Byte\nx = y + 1", 4, 5, "undefined symbol 'y'"),
    ("x VAR Byte\nGOTO Nowhere", 4, 6, "undefined label"),
    ("x VAR Byte\nx = \"AB\"", 4, 5, "2 characters"),
    ("Loop VAR Byte\nEND", 3, 1, "reserved word"),
    ("x VAR Byte\nFOR x = 1 TO 3", 4, 1, "'FOR' without 'NEXT'"),
    ("HIGH 1 LOW 2", 3, 8, "expected ':' or end of line, found 'LOW'"),
    ("I2COUT 0, $A0, [1]", 3, 1, "BS2p"),
    ("x VAR Byte\nx = Main\nMain:", 4, 5, "is a label"),
    ("c CON 5\nc = 1", 4, 1, "expected a variable"),
    ("x VAR Byte\nx = 5 ! 3", 4, 7, "unrecognized character '!'"),
    ("LOW 3\nDEBUG CR(1)", 4, 7, "not a variable and cannot be indexed"),
])
def test_bad_pbasic_gets_file_line_col_errors(body, line, col, words):
    with pytest.raises(SpinError) as info:
        bs2(body, "bad.bs2")
    err = info.value
    assert (err.path, err.line, err.column) == ("bad.bs2", line, col), err.render()
    assert words in err.message
    text = err.render()
    first, src, caret = text.split("\n")[:3]
    assert first.startswith(f"bad.bs2:{line}:{col}: error: ")
    assert caret.index("^") == col - 1
    assert "__ANON" not in text and "_NL" not in text


def test_compile_file_reads_a_path(tmp_path):
    p = tmp_path / "blink.bs2"
    p.write_bytes(HEADER.encode() + b"DO\r\n  TOGGLE 1\r\n  PAUSE 100\r\nLOOP")
    prog = compile_file(p)
    assert prog.path == str(p) and len(prog.code) >= 3


def test_errors_are_spin_error_subclasses():
    assert issubclass(ParseError, SpinError) and issubclass(CompileError, SpinError)


def test_a_missing_file_is_a_spin_error_not_a_traceback(tmp_path):
    with pytest.raises(SpinError) as info:
        compile_file(tmp_path / "nope.bs2")
    assert info.value.path.endswith("nope.bs2") and "cannot read" in info.value.message
