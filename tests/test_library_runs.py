"""tests/benchmarks/library_runs.py on a small library of our own: the standard folder and the classes.

The script runs against the Parallax library on demand; here its machinery
runs on a few programs written for the test, so that a change that breaks
the sweep's standard folder or its classification shows in the default run.
"""
import importlib.util
import os

import pytest

_SPEC = importlib.util.spec_from_file_location(
    "library_runs", os.path.join(os.path.dirname(__file__), "benchmarks", "library_runs.py"))
library_runs = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(library_runs)

PLAIN = """\
PUB main
  dira[3] := 1
  outa[3] := 1
"""


def _write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)
    return path


@pytest.fixture
def fake_library(tmp_path):
    lib = tmp_path / "lib"
    # three copies of a standard object's name: two alike (the common version), one different
    _write(str(lib / "a" / "Simple_Numbers.spin"), "PUB dec(v)\n  return v + 1\n")
    _write(str(lib / "b" / "Simple_Numbers.spin"), "PUB dec(v)\n  return v + 1\n")
    _write(str(lib / "c" / "simple_numbers.spin"), "PUB dec(v)\n  return v + 2\n")
    uses = _write(str(lib / "d" / "uses.spin"), 'OBJ\n  num : "Simple_Numbers"\nPUB main\n  outa[0] := num.dec(1)\n')
    missing = _write(str(lib / "e" / "missing.spin"), 'OBJ\n  x : "NoSuchObjectAnywhere"\nPUB main\n')
    broken = _write(str(lib / "e" / "broken.spin"), "PUB main\n  x := \n")
    plain = _write(str(lib / "e" / "plain.spin"), PLAIN)
    return lib, {"uses": uses, "missing": missing, "broken": broken, "plain": plain}


def test_the_standard_folder_takes_the_version_most_copies_share(fake_library, tmp_path):
    lib, _ = fake_library
    versions = library_runs.build_standard_folder(library_runs.spin_files(str(lib)), str(tmp_path / "std"))
    assert [n for n, _d, _p in versions["Simple_Numbers"]] == [2, 1]
    with open(tmp_path / "std" / "Simple_Numbers.spin") as fh:
        assert "v + 1" in fh.read()


def test_runs_are_classified_as_a_user_would_see_them(fake_library, tmp_path):
    lib, files = fake_library
    std = str(tmp_path / "std")
    library_runs.build_standard_folder(library_runs.spin_files(str(lib)), std)
    env = dict(os.environ, SPINEMU_PATH=std, PYTHONPATH=library_runs.ROOT)
    results = {name: library_runs.run_one(path, ["--cycles", "200000"], 120, env, std, "")
               for name, path in files.items()}
    assert results["uses"]["class"] == "ran"                  # found through SPINEMU_PATH only
    assert results["plain"]["class"] == "ran" and results["plain"]["ended"] == "all cogs stopped"
    assert results["missing"]["class"] == "compile: missing object"
    assert results["missing"]["missing"] == "NoSuchObjectAnywhere"
    assert results["broken"]["class"] == "compile: error"      # no OpenSpin given to tell more


def test_a_warning_saying_something_is_not_emulated_counts_as_a_gap():
    assert library_runs.classify_warning("WAITVID output is not emulated").startswith("GAP")
    assert library_runs.classify_warning("'tv.spin' is spelled 'TV.spin' on disk (x)") == \
        "name in another letter case"
