"""Finding OBJ and DAT file names: -L, SPINEMU_PATH, installed libraries, names in another letter case."""
from __future__ import annotations

import io
import os

import pytest

from spinemu.cli import main
from spinemu.compiler import compile_file
from spinemu.diagnostics import CompileError
from spinemu.frontend import search as search_mod
from spinemu.frontend.search import ENV_VAR, SearchPath, standard_library_folders, standard_object

CHILD = "PUB f\n  return 7\n"


def write(folder, name, text):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_text(text)
    return folder / name


@pytest.fixture(autouse=True)
def no_outside_folders(monkeypatch):
    """Tests see only the folders they make: no SPINEMU_PATH, no installed tools."""
    monkeypatch.delenv(ENV_VAR, raising=False)
    monkeypatch.setattr(search_mod, "standard_library_folders", lambda platform=None, environ=None: [])


def test_an_object_named_in_another_letter_case_is_found_with_a_warning(tmp_path):
    write(tmp_path, "TV_Text.spin", CHILD)
    top = write(tmp_path, "top.spin", 'OBJ\n  t : "tv_text"\nPUB main\n  t.f\n')
    prog = compile_file(top)
    assert len(prog.warnings) == 1
    w = prog.warnings[0]
    assert w.severity == "warning" and (w.line, w.column) == (2, 3)
    assert "'tv_text.spin' is spelled 'TV_Text.spin' on disk" in w.message
    # the image is the one the correctly spelled name gives
    fixed = write(tmp_path, "fixed.spin", 'OBJ\n  t : "TV_Text"\nPUB main\n  t.f\n')
    assert compile_file(fixed).binary == prog.binary and compile_file(fixed).warnings == []


def test_the_projects_own_file_in_another_case_wins_over_an_exact_match_in_a_later_folder(tmp_path):
    # as on Windows: the Propeller Tool opens the project's Helper.spin for "helper", not a library's copy
    write(tmp_path / "src", "Helper.spin", "PUB f\n  return 1\n")
    write(tmp_path / "lib", "helper.spin", "PUB f\n  return 2\n")
    top = write(tmp_path / "src", "top.spin", 'OBJ\n  h : "helper"\nPUB main\n  h.f\n')
    prog = compile_file(top, include_dirs=[str(tmp_path / "lib")])
    assert prog.layout.children[0].path.endswith(os.path.join("src", "Helper.spin"))
    assert len(prog.warnings) == 1 and "spelled 'Helper.spin' on disk" in prog.warnings[0].message


def test_an_exact_match_in_a_folder_wins_over_another_case_in_the_same_folder(tmp_path):
    write(tmp_path / "lib", "helper.spin", "PUB f\n  return 2\n")
    write(tmp_path / "lib", "Other.spin", "PUB f\n  return 3\n")
    top = write(tmp_path / "src", "top.spin", 'OBJ\n  h : "helper"\nPUB main\n  h.f\n')
    prog = compile_file(top, include_dirs=[str(tmp_path / "lib")])
    assert prog.warnings == []
    assert prog.layout.children[0].path.endswith(os.path.join("lib", "helper.spin"))


def test_names_that_differ_only_in_case_in_one_folder_are_an_error_naming_them(tmp_path):
    write(tmp_path, "Serial.spin", CHILD)
    write(tmp_path, "SERIAL.spin", CHILD)
    top = write(tmp_path, "top.spin", 'OBJ\n  s : "serial"\nPUB main\n')
    with pytest.raises(CompileError) as info:
        compile_file(top)
    text = info.value.diagnostics[0].message
    assert "matches several files" in text and "SERIAL.spin" in text and "Serial.spin" in text


def test_a_data_file_is_found_in_another_case_and_in_the_L_folders(tmp_path):
    write(tmp_path / "src", "FONT.DAT", "AB")
    write(tmp_path / "lib", "table.dat", "CDE")
    top = write(tmp_path / "src", "top.spin", 'PUB main\nDAT\nf byte\n  file "font.dat"\n  file "table.dat"\n')
    prog = compile_file(top, include_dirs=[str(tmp_path / "lib")])
    assert b"ABCDE" in prog.binary
    assert ["'font.dat' is spelled 'FONT.DAT'" in w.message for w in prog.warnings] == [True]


def test_spinemu_path_folders_are_searched_after_the_L_folders(tmp_path, monkeypatch):
    write(tmp_path / "env1", "a.spin", "PUB f\n  return 1\n")
    write(tmp_path / "env2", "b.spin", "PUB f\n  return 2\n")
    write(tmp_path / "lib", "b.spin", "PUB f\n  return 3\n")
    monkeypatch.setenv(ENV_VAR, os.pathsep.join([str(tmp_path / "env1"), str(tmp_path / "env2")]))
    top = write(tmp_path / "src", "top.spin", 'OBJ\n  a : "a"\n  b : "b"\nPUB main\n  a.f\n  b.f\n')
    prog = compile_file(top, include_dirs=[str(tmp_path / "lib")])
    paths = [c.path for c in prog.layout.children]
    assert paths[0].endswith(os.path.join("env1", "a.spin"))
    assert paths[1].endswith(os.path.join("lib", "b.spin"))


def test_a_missing_library_object_says_where_it_looked_and_which_library_it_comes_from(tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(tmp_path / "mylib"))
    top = write(tmp_path / "src", "top.spin", 'OBJ\n  pst : "parallax serial terminal"\nPUB main\n')
    with pytest.raises(CompileError) as info:
        compile_file(top, include_dirs=[str(tmp_path / "inc")])
    text = info.value.diagnostics[0].message
    assert f"{tmp_path / 'src'} (the source's folder)" in text
    assert f"{tmp_path / 'inc'} (-L)" in text and f"{tmp_path / 'mylib'} ({ENV_VAR})" in text
    assert "'Parallax Serial Terminal' is an object of the Propeller Tool's library" in text
    assert ENV_VAR in text.split("library")[-1] and "-L DIR" in text


def test_a_missing_object_of_ones_own_gets_no_library_hint(tmp_path):
    top = write(tmp_path, "top.spin", 'OBJ\n  m : "my_driver"\nPUB main\n')
    with pytest.raises(CompileError, match="cannot find object file 'my_driver'") as info:
        compile_file(top)
    assert "Propeller Tool" not in info.value.diagnostics[0].message


@pytest.mark.parametrize("name,spelled", [("fullduplexserial", "FullDuplexSerial"),
                                          ("TV_TEXT.spin", "TV_Text"), ("Servo32v9", "Servo32v9"),
                                          ("my_driver", None)])
def test_the_propeller_tool_objects_are_known_by_name(name, spelled):
    assert standard_object(name) == spelled


def test_installed_libraries_are_found_where_the_windows_installers_put_them(tmp_path, monkeypatch):
    monkeypatch.undo()      # the real function, on a fake Program Files
    pf, pf86 = tmp_path / "Program Files", tmp_path / "Program Files (x86)"
    (pf86 / "Parallax Inc" / "Propeller Tool v1.3.2" / "Library").mkdir(parents=True)
    (pf / "PropellerIDE" / "library").mkdir(parents=True)
    (pf86 / "SimpleIDE" / "propeller-gcc" / "spin").mkdir(parents=True)
    environ = {"ProgramFiles": str(pf), "ProgramFiles(x86)": str(pf86)}
    found = standard_library_folders("win32", environ)
    assert [f.why for f in found] == ["the Propeller Tool's library", "PropellerIDE's library",
                                      "SimpleIDE's library"]
    assert found[0].path == os.path.join(str(pf86), "Parallax Inc", "Propeller Tool v1.3.2", "Library")


def test_only_existing_library_folders_are_searched(monkeypatch):
    monkeypatch.undo()
    monkeypatch.setattr(search_mod.os.path, "isdir", lambda p: p == "/opt/parallax/spin")
    assert [f.path for f in standard_library_folders("linux", {})] == ["/opt/parallax/spin"]
    assert [f.path for f in standard_library_folders("darwin", {})] == ["/opt/parallax/spin"]


def test_installed_libraries_come_last(tmp_path):
    lib = tmp_path / "ptool"
    lib.mkdir()
    sp = SearchPath(["inc"], environ={ENV_VAR: "env"}, standard=False)
    sp._extra.append(search_mod.Folder(str(lib), "the Propeller Tool's library"))
    assert [f.why for f in sp.folders("src")] == ["the source's folder", "-L", ENV_VAR,
                                                   "the Propeller Tool's library"]


def test_the_cli_prints_the_warning_and_compiles(tmp_path):
    write(tmp_path, "Numbers.spin", CHILD)
    top = write(tmp_path, "top.spin", 'OBJ\n  n : "NUMBERS"\nPUB main\n  n.f\n')
    out, err = io.StringIO(), io.StringIO()
    assert main(["compile", str(top), "-o", str(tmp_path / "top.binary")], stdout=out, stderr=err) == 0
    assert f"{top}:2:3: warning: 'NUMBERS.spin' is spelled 'Numbers.spin'" in err.getvalue()
    assert (tmp_path / "top.binary").exists()
