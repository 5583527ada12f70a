"""Writing a whole file or nothing: to a new file beside it first, then renaming it over the target.

Used for the files spinemu writes (traces, images, hub dumps, its caches).
Unlike :func:`tempfile.mkstemp`, the new file gets the permissions the user's
umask gives any new file (mkstemp's 0600 would stay on a trace after the
rename), and :mod:`tempfile` (some milliseconds to import: it pulls in
shutil, random and the compression modules) stays out of a run's start-up.
"""
from __future__ import annotations

import itertools
import os
import zlib

__all__ = ["create_beside", "write_atomic", "cache_base", "cache_name", "write_cache_file"]

_serial = itertools.count()


def create_beside(path: str, suffix: str = ".tmp"):
    """``(fd, name)`` of a new, empty file (opened for writing) in ``path``'s folder; raises OSError."""
    folder = os.path.dirname(os.path.abspath(path)) or "."
    base = os.path.basename(path)
    while True:
        name = os.path.join(folder, f".{base}.{os.getpid()}-{next(_serial)}{suffix}")
        try:
            return os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), 0o666), name
        except FileExistsError:     # (left by a process that died with this pid: take the next name)
            continue


def write_atomic(path: str, data, binary: bool = True) -> None:
    """Write ``data`` (bytes or str, or a function given the open file) to ``path``, whole or not at all."""
    fd, tmp = create_beside(path)
    try:
        with os.fdopen(fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8"})) as f:
            if callable(data):
                data(f)
            else:
                f.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def cache_base() -> str | None:
    """Where spinemu keeps its caches (compiled blocks, compiled programs), or None when caching is off.

    ``$SPINEMU_CACHE_DIR``, else ``$XDG_CACHE_HOME/spinemu``, else ``~/.cache/spinemu``;
    ``SPINEMU_CACHE=0`` turns caching off.
    """
    if os.environ.get("SPINEMU_CACHE", "1") == "0":
        return None
    base = os.environ.get("SPINEMU_CACHE_DIR")
    if not base:
        xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        base = os.path.join(xdg, "spinemu")
    return base


def cache_name(data: bytes, ext: str) -> str:
    """A cache file's name for the key ``data``: its checksums and length (a clash just misses: each
    cache checks that an entry is for what it looks up)."""
    return f"{zlib.crc32(data):08x}{zlib.adler32(data):08x}{len(data):x}{ext}"


def write_cache_file(path: str, data: bytes, keep: int = 0) -> None:
    """Write a cache file whole or not at all (its folder made if need be); with ``keep``, then remove
    the least recently used files of its folder with its extension past ``keep``.  Raises OSError."""
    folder = os.path.dirname(path)
    os.makedirs(folder, exist_ok=True)
    write_atomic(path, data)
    if keep:
        ext = os.path.splitext(path)[1]
        files = [os.path.join(folder, n) for n in os.listdir(folder) if n.endswith(ext)]
        if len(files) > keep:
            files.sort(key=os.path.getmtime)
            for p in files[:len(files) - keep]:
                os.unlink(p)
