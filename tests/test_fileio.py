"""Atomic file writes: the whole file or nothing, with the permissions any new file gets."""
import os
import stat

import pytest

from spinemu.fileio import create_beside, write_atomic


def test_write_atomic_writes_bytes_text_and_callables(tmp_path):
    p = tmp_path / "out.bin"
    write_atomic(str(p), b"\x00\x01")
    assert p.read_bytes() == b"\x00\x01"
    write_atomic(str(p), "h\u00e9\n", binary=False)
    assert p.read_text(encoding="utf-8") == "h\u00e9\n"
    write_atomic(str(p), lambda f: f.write(b"abc"))
    assert p.read_bytes() == b"abc"
    assert os.listdir(tmp_path) == ["out.bin"]


def test_failed_write_leaves_the_old_file_and_no_temporary(tmp_path):
    p = tmp_path / "trace.log"
    p.write_text("old")

    def boom(f):
        f.write(b"partial")
        raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_atomic(str(p), boom)
    assert p.read_text() == "old"
    assert os.listdir(tmp_path) == ["trace.log"]


@pytest.mark.skipif(os.name != "posix", reason="file modes are POSIX")
def test_new_file_gets_the_umask_permissions_not_0600(tmp_path):
    old = os.umask(0o022)
    try:
        write_atomic(str(tmp_path / "t.vcd"), b"x")
    finally:
        os.umask(old)
    assert stat.S_IMODE(os.stat(tmp_path / "t.vcd").st_mode) == 0o644


def test_create_beside_takes_the_next_name_when_one_exists(tmp_path):
    fd1, a = create_beside(str(tmp_path / "x"))
    fd2, b = create_beside(str(tmp_path / "x"))
    os.close(fd1)
    os.close(fd2)
    assert a != b and os.path.dirname(a) == os.path.dirname(b) == str(tmp_path)


def test_a_cache_file_write_keeps_the_most_recently_used_of_its_kind(tmp_path):
    from spinemu.fileio import cache_name, write_cache_file

    folder = tmp_path / "cache"
    for i in range(4):
        write_cache_file(str(folder / f"{i}.marshal"), b"x", keep=3)
        os.utime(folder / f"{i}.marshal", (1000 + i, 1000 + i))
    (folder / "other.pickle").write_bytes(b"y")
    write_cache_file(str(folder / "4.marshal"), b"z", keep=3)
    assert sorted(os.listdir(folder)) == ["2.marshal", "3.marshal", "4.marshal", "other.pickle"]
    assert cache_name(b"abc", ".pickle") == cache_name(b"abc", ".pickle") != cache_name(b"abd", ".pickle")
