"""Sources a new user's editor or typing makes, which used to crash or mislead (found by tests/fuzz/robust)."""
import os

import pytest

from spinemu.compiler import compile_file, compile_source
from spinemu.diagnostics import Diagnostic, SpinError, split_lines


def error_of(src: str, name: str = "odd.spin") -> SpinError:
    with pytest.raises(SpinError) as info:
        compile_source(src, name)
    return info.value


def test_a_number_of_five_thousand_digits_is_too_big_not_a_crash():
    err = error_of("CON\n  K = " + "9" * 5000 + "\nPUB main\n")
    d = err.diagnostics[0]
    assert (d.line, d.column) == (2, 7) and d.message.endswith("does not fit in 32 bits")
    assert len(d.message) < 80                       # the number is shortened in the message


@pytest.mark.parametrize("separator", ["\x0c", "\u2028", "\x0b", "\x85", "\x1c"])
def test_a_separator_character_in_a_comment_does_not_shift_the_quoted_line(separator):
    err = error_of(f"' a comment{separator}with a separator\nPUB main\n  x := 1\n")
    lines = err.render().splitlines()
    assert lines[0] == "odd.spin:3:3: error: unknown symbol 'x'"
    assert lines[1] == "  x := 1" and lines[2] == "  ^"


def test_split_lines_counts_only_cr_and_lf():
    assert split_lines("a\x0cb\u2028c\r\nd\re\n") == ["a\x0cb\u2028c", "d", "e"]


def test_an_unprintable_character_is_named_by_its_code():
    err = error_of("PUB main\n  outa := 1\x1a\n")
    assert err.diagnostics[0].message == "unexpected character U+001A"


def test_control_characters_of_a_quoted_line_cannot_reach_the_terminal():
    d = Diagnostic("bad", "x.log", 1, 3, "ab\x1b[2Jcd")
    assert d.render().splitlines()[1] == "ab\ufffd[2Jcd"


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_a_data_file_that_is_a_device_is_not_read():
    err = error_of('DAT\n  file "/dev/zero"\nPUB main\n')
    assert err.diagnostics[0].line == 2 and "'/dev/zero'" in err.diagnostics[0].message


def test_a_data_file_larger_than_the_hub_is_refused(tmp_path):
    (tmp_path / "big.dat").write_bytes(bytes(40_000))
    (tmp_path / "top.spin").write_text('DAT\n  file "big.dat"\nPUB main\n')
    with pytest.raises(SpinError, match="larger than the 32768-byte hub RAM"):
        compile_file(str(tmp_path / "top.spin"))


def test_utf16_without_a_byte_order_mark_is_an_error_with_a_position():
    data = "PUB main\n  outa := 1\n".encode("utf-16-le")
    err = error_of(data.decode("utf-8"))
    assert err.diagnostics[0].line == 1 and err.diagnostics[0].column is not None


@pytest.mark.parametrize("src", ["PUB main | x\n  repeat\n    case x\n", "PUB main | x\n  case x\n  x := 1\n"])
def test_a_case_without_match_lines_is_an_error(src):
    """OpenSpin: "No cases encountered" (at the statement after the case); spinemu points at the case."""
    err = error_of(src)
    assert err.diagnostics[0].message == "case needs at least one match line"


def test_an_object_array_past_255_table_entries_is_reported_at_its_line_and_calls_do_not_crash():
    """OpenSpin: "Limit of 256 subroutines + objects exceeded" on the OBJ line that crosses it."""
    src = 'OBJ\n  a : "kid"\n  b[255] : "kid"\n  c : "kid"\nPUB main\n  c.f\n  b[1].f\n'
    with pytest.raises(SpinError) as info:
        compile_source(src, "top.spin", files={"kid.spin": "PUB f\n"})
    d = info.value.diagnostics[0]
    assert d.line == 3 and "at most 255 methods and object instances" in d.message


def test_a_huge_line_full_of_errors_is_reported_quickly_and_shown_around_the_column():
    """A file whose line ends are U+2028 is one line for Spin: every separator is an error, and
    each used to quote the whole line (seconds per hundred errors)."""
    import time

    src = "DAT\n" + "\u2028".join(["        long $0A5, $15A"] * 4000) + "\nPUB main\n"
    t0 = time.perf_counter()
    err = error_of(src)
    text = err.render()
    assert time.perf_counter() - t0 < 10
    assert len(err.diagnostics) >= 3999
    first = text.splitlines()[:3]
    assert first[0].startswith("odd.spin:2:") and len(first[1]) <= 170
    assert first[1][len(first[2]) - 1] == "\ufffd"          # the caret is under the separator
