"""Odd sources through the translator: the Python it writes must always compile (found by tests/fuzz/robust).

Spin comment text ends up in docstrings and ``#`` comments, file names in
docstrings and module names; none of them may break the generated module.
"""
import os

import pytest

from spinemu import translate
from spinemu.diagnostics import EmulationError, SpinError
from spinemu.translate.program import ModuleText

from tests.translate.crosscheck import crosscheck

ODD_COMMENTS = '''{{ A doc with """ triple quotes, a backslash \\N{x} \\x and a last quote mark"
   and\x00a NUL, a\u2028line separator }}
'' header """ \\
CON
  K = 3   ' trailing """ \\ comment"
VAR
  long v
PUB main
  '' method doc """ with \\ and "
  '' second line ending in a quote mark"
  { block """ comment \\ }
  v := K  { inline """ \\ }
  dira[0] := 1
  outa[0] := v & 1     '' \x0c form feed and "
PUB second : r
  '' "
  r := 1
'''


def compile_modules(folder):
    for name in sorted(os.listdir(folder)):
        if name.endswith(".py"):
            with open(os.path.join(folder, name), "rb") as fh:
                compile(fh.read(), name, "exec")


def test_comments_full_of_quote_marks_backslashes_and_control_characters_translate_to_valid_python(tmp_path):
    src = tmp_path / "odd.spin"
    src.write_text(ODD_COMMENTS)
    files = translate.translate_file(str(src), str(tmp_path / "py"))
    compile_modules(tmp_path / "py")
    text = open(files[0], encoding="utf-8").read()
    assert 'triple quotes, a backslash \\\\N{x}' in text and "\\x00" in text
    agreement = crosscheck(str(src), 20_000)
    assert agreement.ok, agreement.describe()


def test_a_file_name_with_quote_marks_and_a_backslash_translates(tmp_path):
    src = tmp_path / 'say """hi\\ there".spin'
    src.write_text("PUB main\n  outa[0] := 1\n")
    translate.translate_file(str(src), str(tmp_path / "py"))
    compile_modules(tmp_path / "py")


def test_two_objects_that_would_share_a_module_name_are_refused(tmp_path):
    (tmp_path / "my-obj.spin").write_text("PUB f\n  return 1\n")
    (tmp_path / "my_obj.spin").write_text("PUB g\n  return 2\n")
    (tmp_path / "top.spin").write_text('OBJ\n  a : "my-obj"\n  b : "my_obj"\nPUB main\n  a.f\n  b.g\n')
    with pytest.raises(SpinError, match="would both become the Python module 'my_obj.py'"):
        translate.translate_file(str(tmp_path / "top.spin"), str(tmp_path / "py"))


def test_generated_code_that_does_not_compile_is_never_written(tmp_path):
    broken = ModuleText("broken", "Broken", 'x = """\n', [None], "broken.spin")
    with pytest.raises(RuntimeError, match="does not compile"):
        translate._write([broken], None, str(tmp_path / "py"))
    assert not (tmp_path / "py").exists()


def test_an_object_index_outside_the_array_is_a_run_time_fault_naming_the_spin_line(tmp_path):
    (tmp_path / "kid.spin").write_text("PUB work\n  outa[1] := 1\n")
    (tmp_path / "top.spin").write_text('OBJ\n  b[2] : "kid"\nPUB main | i\n  i := 2\n  b[i].work\n')
    with pytest.raises(EmulationError) as info:
        translate.run_translated(str(tmp_path / "top.spin"), max_cycles=100_000)
    d = info.value.diagnostics[0]
    assert (d.path, d.line) == ("top.spin", 5)
    assert "object index 2 is outside b[0..1]" in d.message


def test_a_block_whose_statements_write_no_line_becomes_pass(tmp_path, monkeypatch):
    """A repeat whose only statement translates to nothing (here an empty case, let through the compiler)."""
    from spinemu.compiler import stmts

    original = stmts.MethodCompiler.s_Case
    monkeypatch.setattr(stmts.MethodCompiler, "s_Case",
                        lambda self, node: None if not node.items else original(self, node))
    src = tmp_path / "empty.spin"
    src.write_text("PUB main | x\n  repeat\n    case x\n")
    translate.translate_file(str(src), str(tmp_path / "py"))
    compile_modules(tmp_path / "py")
