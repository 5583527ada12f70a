"""The compiled-program cache: reused only while every source and folder it came from is unchanged."""
import os
import subprocess
import sys

import pytest

from spinemu.compiler import compile_file
from spinemu.diagnostics import SpinError
from spinemu.progcache import CachedProgram, compile_cached

TOP = """OBJ
  c : "Child"
PUB main
  dira[0]~~
  outa[0] := c.value
"""
CHILD = "PUB value\n  return {}\n"


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("SPINEMU_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("SPINEMU_CACHE", raising=False)
    monkeypatch.delenv("SPINEMU_PATH", raising=False)
    return tmp_path / "cache"


def _program(folder, top=TOP, child=CHILD.format(1), child_name="child.spin"):
    folder.mkdir(exist_ok=True)
    (folder / "top.spin").write_text(top)
    (folder / child_name).write_text(child)
    return str(folder / "top.spin")


def test_second_compile_comes_from_the_cache_with_everything_a_run_uses(tmp_path, cache):
    path = _program(tmp_path / "src")                      # "Child" found as child.spin: a case warning
    first = compile_cached(path)
    assert not isinstance(first, CachedProgram) and first.warnings
    again = compile_cached(path)
    assert isinstance(again, CachedProgram)
    assert again.binary == first.binary
    assert again.line_table.items(columns=True) == first.line_table.items(columns=True)
    assert [d.message for d in again.warnings] == [d.message for d in first.warnings]
    assert again.dat_labels() == first.dat_labels() and again.dat_symbols() == first.dat_symbols()
    addr = first.line_table.items()[0][0]
    assert again.debug_info().position(addr) == first.debug_info().position(addr)
    assert again.eeprom() == first.eeprom()


@pytest.mark.parametrize("edit", ["top", "child"])
def test_an_edited_source_is_compiled_again_even_at_the_same_size(tmp_path, cache, edit):
    path = _program(tmp_path / "src")
    before = compile_cached(path).binary
    if edit == "top":
        (tmp_path / "src" / "top.spin").write_text(TOP.replace("dira[0]", "dira[1]").replace("outa[0]", "outa[1]"))
    else:
        (tmp_path / "src" / "child.spin").write_text(CHILD.format(2))
    after = compile_cached(path)
    assert not isinstance(after, CachedProgram)
    assert after.binary != before and after.binary == compile_file(path).binary


def test_a_file_added_where_it_would_now_be_found_first_is_noticed(tmp_path, cache):
    src, lib = tmp_path / "src", tmp_path / "lib"
    src.mkdir()
    (src / "top.spin").write_text(TOP)
    lib.mkdir()
    (lib / "Child.spin").write_text(CHILD.format(1))
    path = str(src / "top.spin")
    from_lib = compile_cached(path, [str(lib)]).binary
    assert isinstance(compile_cached(path, [str(lib)]), CachedProgram)
    (src / "Child.spin").write_text(CHILD.format(7))         # the source's folder comes before -L
    prog = compile_cached(path, [str(lib)])
    assert not isinstance(prog, CachedProgram)
    assert prog.binary != from_lib and prog.binary == compile_file(path, [str(lib)]).binary


def test_a_dat_file_change_is_noticed(tmp_path, cache):
    folder = tmp_path / "src"
    folder.mkdir()
    (folder / "top.spin").write_text('PUB main\n  dira[0] := table\nDAT\ntable file "t.dat"\n')
    (folder / "t.dat").write_bytes(b"\x01\x02")
    path = str(folder / "top.spin")
    compile_cached(path)
    (folder / "t.dat").write_bytes(b"\x03\x02")
    prog = compile_cached(path)
    assert not isinstance(prog, CachedProgram) and b"\x03\x02" in prog.binary


def test_other_defines_or_search_folders_are_other_entries(tmp_path, cache):
    folder = tmp_path / "src"
    folder.mkdir()
    (folder / "top.spin").write_text("PUB main\n#ifdef FAST\n  dira[1]~~\n#else\n  dira[2]~~\n#endif\n")
    path = str(folder / "top.spin")
    plain, fast = compile_cached(path), compile_cached(path, defines=["FAST"])
    assert plain.binary != fast.binary
    assert compile_cached(path, defines=["FAST"]).binary == fast.binary
    assert compile_cached(path).binary == plain.binary


def test_errors_are_never_cached(tmp_path, cache):
    folder = tmp_path / "src"
    folder.mkdir()
    (folder / "top.spin").write_text("PUB main\n  x := 1\n")
    for _ in range(2):
        with pytest.raises(SpinError):
            compile_cached(str(folder / "top.spin"))
    assert not (cache / "programs-0.1.0").exists() or not os.listdir(cache / "programs-0.1.0")


def test_a_damaged_entry_counts_as_missing(tmp_path, cache):
    path = _program(tmp_path / "src")
    compile_cached(path)
    (entry,) = [p for p in cache.rglob("*.pickle")]
    entry.write_bytes(b"not a pickle")
    assert not isinstance(compile_cached(path), CachedProgram)
    assert isinstance(compile_cached(path), CachedProgram)


def test_caching_off(tmp_path, cache, monkeypatch):
    monkeypatch.setenv("SPINEMU_CACHE", "0")
    path = _program(tmp_path / "src")
    compile_cached(path)
    assert not isinstance(compile_cached(path), CachedProgram)
    assert not cache.exists()


def test_cli_run_from_the_cache_prints_the_hints_and_the_same_trace(tmp_path, cache):
    path = _program(tmp_path / "src")
    env = dict(os.environ, SPINEMU_CACHE_DIR=str(cache))
    outs = []
    for i in range(2):
        r = subprocess.run([sys.executable, "-m", "spinemu", "run", path, "--cycles", "200000",
                            "--trace", str(tmp_path / f"t{i}.log"), "--no-progress"],
                           capture_output=True, text=True, env=env, cwd=os.path.dirname(os.path.dirname(__file__)))
        assert r.returncode == 0, r.stderr
        outs.append(r.stderr)
    assert "child.spin" in outs[0] and outs[0] == outs[1]
    assert (tmp_path / "t0.log").read_text() == (tmp_path / "t1.log").read_text()
    assert list(cache.rglob("programs-*/*.pickle"))


def test_a_changed_compiler_compiles_anew(tmp_path, cache, monkeypatch):
    from spinemu import progcache

    path = _program(tmp_path / "src")
    compile_cached(path)
    assert isinstance(compile_cached(path), CachedProgram)
    stamp = progcache._compiler_stamp()
    monkeypatch.setattr(progcache, "_compiler_stamp", lambda: stamp + 1)     # a module of it was edited
    assert not isinstance(compile_cached(path), CachedProgram)


def test_the_compiler_stamp_follows_its_files():
    from spinemu import progcache

    pkg = os.path.dirname(progcache.__file__)
    target = os.path.join(pkg, "frontend", "limits.py")
    before = progcache._compiler_stamp()
    st = os.stat(target)
    try:
        os.utime(target, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000_000))
        assert progcache._compiler_stamp() != before
    finally:
        os.utime(target, ns=(st.st_atime_ns, st.st_mtime_ns))
    assert progcache._compiler_stamp() == before


def test_a_source_changed_while_it_compiles_is_not_cached_as_its_new_text(tmp_path, cache, monkeypatch):
    """The cache holds the file as the compiler read it: an edit saved during the compilation is compiled
    by the next run, not hidden behind the image of the old text."""
    import spinemu.frontend.objects as objects

    path = _program(tmp_path / "src")
    child = tmp_path / "src" / "child.spin"
    real = objects.read_source

    def read_then_edit(p):
        text = real(p)
        if os.path.basename(p) == "child.spin":
            child.write_text(CHILD.format(5))           # saved by an editor just after the read
        return text

    monkeypatch.setattr(objects, "read_source", read_then_edit)
    old = compile_cached(path).binary
    monkeypatch.setattr(objects, "read_source", real)
    new = compile_cached(path)
    assert not isinstance(new, CachedProgram) and new.binary != old
