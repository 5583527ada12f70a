"""Compiled images are byte-identical with OpenSpin's (reference images in tests/data)."""
import os

import pytest

from spinemu.compiler import compile_file
from spinemu.diagnostics import CompileError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARTICLE = os.path.join(ROOT, "tests", "data", "article")
PROBES = os.path.join(ROOT, "tests", "data", "compiler", "probes")

ARTICLE_PROGRAMS = [
    ("spin_src/simple_stepper.spin", "as_printed_simple_stepper.binary"),
    ("spin_src/stepper_demo.spin", "as_printed_stepper_demo.binary"),
    ("spin_src/corrected/stepper_demo.spin", "corrected_stepper_demo.binary"),
]


def _read(path):
    with open(path, "rb") as fh:
        return fh.read()


@pytest.mark.parametrize("source,image", ARTICLE_PROGRAMS)
def test_column_programs_compile_to_openspins_images(source, image):
    prog = compile_file(os.path.join(ROOT, source))
    assert prog.binary == _read(os.path.join(ARTICLE, image))


def _probes():
    names = []
    for fname in sorted(os.listdir(PROBES)):
        if fname.endswith(".binary"):
            names.append(fname[:-len(".binary")])
    return names


@pytest.mark.parametrize("name", _probes())
def test_probe_compiles_to_openspins_image(name):
    if name == "pasm":
        pytest.importorskip("spinemu.pasm")
    prog = compile_file(os.path.join(PROBES, name + ".spin"))
    expected = _read(os.path.join(PROBES, name + ".binary"))
    if prog.binary != expected:
        first = next(i for i in range(min(len(prog.binary), len(expected)))
                     if prog.binary[i] != expected[i]) if len(prog.binary) == len(expected) else "size"
        pytest.fail(f"{name}: image differs from OpenSpin's (first difference at {first})")


def test_eeprom_form_matches_openspin():
    prog = compile_file(os.path.join(PROBES, "header.spin"))
    assert prog.eeprom() == _read(os.path.join(PROBES, "header.eeprom"))


def test_include_dirs_are_searched_after_the_source_folder(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "helper.spin").write_text("PUB twice(x)\n  return x * 2\n")
    top = tmp_path / "top.spin"
    top.write_text('OBJ\n  h : "helper"\nPUB main\n  result := h.twice(21)\n')
    with pytest.raises(CompileError, match="cannot find object file 'helper'"):
        compile_file(str(top))
    prog = compile_file(str(top), include_dirs=[str(lib)])
    assert [os.path.basename(c.unit.path) for c in prog.objects] == ["top.spin", "helper.spin"]
