"""Errors: where OpenSpin rejects a file, spinemu rejects it too, on the same line, in plain words.

``tests/data/compiler/errors/*.spin`` hold one mistake each; ``openspin.json``
records OpenSpin 1.00.81's verdict (line, column, message) for each.
"""
import json
import os
import re

import pytest

from spinemu.compiler import compile_file, compile_source
from spinemu.diagnostics import CompileError, ParseError, SpinError
from spinemu.frontend.lalr import load_tables
from spinemu.frontend.lexer import KEYWORDS

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ERRORS = os.path.join(ROOT, "tests", "data", "compiler", "errors")
with open(os.path.join(ERRORS, "openspin.json")) as _fh:
    OPENSPIN = json.load(_fh)

#: Where OpenSpin names no real place, spinemu points at the line responsible.
DEVIATIONS = {
    "bad_clock_mode.spin": "OpenSpin reports line 1; spinemu the _clkmode line",
}
#: the words spinemu uses for each mistake
EXPECTED_WORDS = {
    "bad_clock_mode.spin": "invalid clock setting",
    "bad_number.spin": "unexpected '2'",
    "cascade_once.spin": "unknown symbol 'y'",
    "object_without_pub.spin": "no PUB method",
    "con_divide_by_zero.spin": "division by zero",
    "con_float_and_integer.spin": "cannot mix integer and floating-point",
    "dat_label_twice.spin": "'l1' is already defined (line 3)",
    "dat_override_smaller.spin": "a 'byte' override in a 'long' line",
    "con_forward_twice.spin": "'B' is not known yet here",
    "con_forward_to_child_constant.spin": "'B' is not known yet here",
    "constant_group_not_constant.spin": "'x' is not a constant: in a method, 'round(' starts a constant expression",
    "designator_not_in_first_column.spin": "'PRI' starts a section and must be in the first column",
    "duplicate_symbol.spin": "'count' is already defined",
    "else_not_aligned.spin": "unexpected 'else'; expected a statement",
    "float_in_byte_data.spin": "cannot mix integer and floating-point",
    "method_as_variable.spin": "'main' is not a variable",
    "missing_assignment_operator.spin": "use ':=' to assign or '==' to compare",
    "missing_object.spin": "cannot find object file 'no_such_object'",
    "mov_as_label_target.spin": "unknown symbol 'nosuch'",
    "next_outside_repeat.spin": "'next' is only allowed inside a repeat loop",
    "no_pub_method.spin": "no PUB method",
    "obj_array_bad_count.spin": "unknown symbol 'x'",
    "other_not_last.spin": "'other' must be the last case",
    "quit_in_method_without_loop.spin": "'quit' is only allowed inside a repeat loop",
    "reserved_word_as_name.spin": "unexpected 'mov'; expected a name",
    "size_override_too_big.spin": "size override cannot be larger",
    "string_in_repeat_from.spin": "string() is not allowed here",
    "string_with_zero.spin": "string() characters must be 1 to 255",
    "syntax_missing_operand.spin": "unexpected end of line; expected an expression",
    "undefined_in_dat.spin": "unknown symbol 'missing_label'",
    "undefined_symbol.spin": "unknown symbol 'y'",
    "unknown_object_constant.spin": "object 'c' has no constant 'NOPE'",
    "unknown_object_method.spin": "object 'c' has no public method 'nosuch'",
    "unterminated_comment.spin": "never closed",
    "unterminated_string.spin": "this string has no closing '\"'",
    "wrong_argument_count.spin": "'f' takes 1 parameter, not 2",
}
# token kinds that are not also Spin words the user writes (PUB, IF...)
_TOKEN_KINDS = {t for t in load_tables().terminals if t.lower() not in KEYWORDS} | {"__ANON"}


def _internal_names(message: str) -> set:
    """Parser token kinds (NAME, LPAR, _NL...) showing through a message, outside quotes."""
    unquoted = re.sub(r"'[^']*'", "", message)
    return {w for w in re.findall(r"[A-Za-z_$]+", unquoted) if w in _TOKEN_KINDS}


def test_every_error_file_has_expected_words():
    assert sorted(EXPECTED_WORDS) == sorted(OPENSPIN)


@pytest.mark.parametrize("name", sorted(OPENSPIN))
def test_rejected_like_openspin_on_the_same_line(name):
    with pytest.raises(SpinError) as info:
        compile_file(os.path.join(ERRORS, name))
    err = info.value
    ref = OPENSPIN[name]
    assert ref["message"] != "accepted"
    lines = [d.line for d in err.diagnostics]
    if ref["line"] is not None and name not in DEVIATIONS:
        assert ref["line"] in lines, f"OpenSpin: line {ref['line']} ({ref['message']}); spinemu: {err}"
        assert ref["file"] in {os.path.basename(d.path) for d in err.diagnostics if d.line == ref["line"]}
    assert EXPECTED_WORDS[name] in err.diagnostics[0].message
    for d in err.diagnostics:
        assert not _internal_names(d.message), d.message


@pytest.mark.parametrize("name", sorted(OPENSPIN))
def test_error_renders_as_file_line_column_with_a_caret(name):
    with pytest.raises(SpinError) as info:
        compile_file(os.path.join(ERRORS, name))
    first = info.value.render().splitlines()
    assert re.match(r".*\.spin:\d+(:\d+)?: error: ", first[0])
    if len(first) > 2 and not first[1].endswith("error"):
        assert first[2].strip().startswith("^")


def test_an_unknown_name_is_reported_once_however_often_it_is_used():
    with pytest.raises(CompileError) as info:
        compile_source("PUB main | x\n  x := y\n  x := y + 1\n  x := y * 2\n  z := 3\n")
    messages = [d.message for d in info.value.diagnostics]
    assert messages == ["unknown symbol 'y'", "unknown symbol 'z'"]


def test_syntax_errors_in_several_methods_are_all_reported():
    src = "PUB a | x\n  x := 3 +\nPUB b | x\n  x := (1\nCON\n  K = = 2\n"
    with pytest.raises(ParseError) as info:
        compile_source(src)
    assert [d.line for d in info.value.diagnostics] == [2, 4, 6]


def test_a_lexical_error_hides_the_syntax_error_it_causes():
    with pytest.raises(ParseError) as info:
        compile_source('PUB main | x\n  x := string("abc)\n')
    assert len(info.value.diagnostics) == 1


def test_errors_in_child_objects_name_the_child_file(tmp_path):
    (tmp_path / "kid.spin").write_text("PUB f\n  return nosuch\n")
    (tmp_path / "top.spin").write_text('OBJ\n  k : "kid"\nPUB main\n  k.f\n')
    with pytest.raises(CompileError) as info:
        compile_file(str(tmp_path / "top.spin"))
    d = info.value.diagnostics[0]
    assert os.path.basename(d.path) == "kid.spin" and d.line == 2 and d.column == 10


def test_a_missing_top_file_is_an_error_not_a_traceback(tmp_path):
    with pytest.raises(SpinError, match="cannot read the file"):
        compile_file(str(tmp_path / "nothing.spin"))
