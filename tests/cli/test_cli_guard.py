"""The CLI's exit statuses: 0 ok, 1 bad input, 2 usage, 70 internal error (the last-resort guard)."""
import io

import pytest

from spinemu import cli
from spinemu.cli import EXIT_INTERNAL, main
from spinemu.diagnostics import SpinError


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def broken_compile(monkeypatch):
    """``spinemu compile`` hits a bug: its command function raises an unexpected exception."""
    def boom(args, out):
        raise ZeroDivisionError("division by zero")
    monkeypatch.setattr(cli, "cmd_compile", boom)
    monkeypatch.delenv("SPINEMU_TRACEBACK", raising=False)


def test_an_unexpected_exception_is_an_internal_error_with_status_70(broken_compile):
    code, out, err = run("compile", "x.spin")
    assert code == EXIT_INTERNAL == 70
    assert err.startswith("spinemu compile: internal error: ZeroDivisionError: division by zero\n")
    assert "report it" in err and "--traceback" in err
    assert "Traceback" not in err and out == ""


def test_the_traceback_is_shown_with_the_traceback_flag(broken_compile):
    code, _, err = run("--traceback", "compile", "x.spin")
    assert code == 70
    assert err.startswith("Traceback (most recent call last):") and "in boom" in err
    assert "spinemu compile: internal error: ZeroDivisionError" in err


def test_the_traceback_is_shown_with_the_environment_variable(broken_compile, monkeypatch):
    monkeypatch.setenv("SPINEMU_TRACEBACK", "1")
    code, _, err = run("compile", "x.spin")
    assert code == 70 and "Traceback (most recent call last):" in err and "in boom" in err


def test_a_subcommand_is_named_with_its_action(monkeypatch):
    def boom(args, out):
        raise KeyError("oops")
    monkeypatch.setattr(cli, "cmd_trace", boom)
    code, _, err = run("trace", "show", "x.log")
    assert code == 70 and err.startswith("spinemu trace show: internal error: KeyError: 'oops'")


def test_an_exception_before_the_command_is_known_is_still_caught(monkeypatch):
    def boom(*args):
        raise RuntimeError("parser broke")
    monkeypatch.setattr(cli, "build_parser", boom)
    code, _, err = run("run", "x.spin")
    assert code == 70 and err.startswith("spinemu: internal error: RuntimeError: parser broke")


def test_an_exception_type_outside_builtins_is_named_with_its_module(monkeypatch):
    import struct

    def boom(args, out):
        struct.unpack("<I", b"")
    monkeypatch.setattr(cli, "cmd_disasm", boom)
    code, _, err = run("disasm", "x.binary")
    assert code == 70 and "internal error: struct.error: " in err


def test_keyboard_interrupt_is_not_an_internal_error(monkeypatch):
    def stop(args, out):
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "cmd_compile", stop)
    assert run("compile", "x.spin")[0] == 130


def test_an_error_in_the_input_keeps_status_1(tmp_path):
    src = tmp_path / "bad.spin"
    src.write_text("PUB main\n  x := 1\n")
    code, _, err = run("compile", src)
    assert code == 1 and f"{src}:2:3: error: unknown symbol 'x'" in err and "internal" not in err


def test_a_library_error_raised_inside_a_command_keeps_its_status(monkeypatch):
    def bad(args, out):
        raise SpinError("no good", path="a.spin", line=3, column=2, source_line="  xy")
    monkeypatch.setattr(cli, "cmd_compile", bad)
    code, _, err = run("compile", "a.spin")
    assert code == 1 and err == "a.spin:3:2: error: no good\n  xy\n ^\n"


@pytest.mark.parametrize("argv", [["run"], ["run", "x.spin", "--cycles", "0"], ["nosuch"], ["--bogus"],
                                  ["run", "x.spin", "--seconds", "nan"]])
def test_usage_errors_keep_status_2(argv):
    code, _, err = run(*argv)
    assert code == 2 and "error:" in err and "internal" not in err


def test_usage_errors_found_by_a_command_keep_status_2(tmp_path):
    code, _, err = run("run", tmp_path / "x.txt")
    assert code == 2 and err.startswith("spinemu run: cannot tell what")


def test_help_lists_the_exit_statuses():
    code, out, _ = run("--help")
    assert code == 0
    assert "exit status:" in out and "70  an internal error" in out and "--traceback" in out
