"""Compiled programs kept between runs, reused while nothing they were made from has changed.

``spinemu run prog.spin`` compiles its program every time, and for a short
run the compiler (and importing it) is a good part of the time: about 0.03 s
of the column's 0.17 s demo.  :func:`compile_cached` keeps what a run needs
from a compilation (the image, its line table, the compiler's hints, the DAT
labels and the debug information) and gives it back on the next run of the
same command, without importing the compiler, when it is still what a new
compilation would produce.

That is decided as ``make`` would, but by contents rather than times:

* the command must be the same: the top file's path as given, the working
  folder, the ``-L`` folders, the ``-D`` names, ``SPINEMU_PATH`` (and on
  Windows the program folders) and the compiler: spinemu's version and the
  size and time of each of its modules and of its grammar;
* every file the compilation read (each object's source, each DAT ``file``,
  the library namesakes an OBJ hint compares) must have the same size and
  CRC-32 as the bytes the compiler read (or still be missing), so that an
  edit saved while it compiled is compiled by the next run;
* every folder whose files decided a lookup (each folder an OBJ or ``file``
  name was looked for in, up to where it was found, and the library folders)
  must still list the same names (or still be missing), so that a file added
  where it would now be found first is noticed.

A program that did not compile is never cached: its errors come from a real
compilation every time.  Entries are pickled into
``<cache>/programs-<version>/`` (see :func:`spinemu.fileio.cache_base`;
``SPINEMU_CACHE=0`` or ``spinemu run --no-cache`` turns this off); an
unreadable entry counts as missing.  At most :data:`KEEP` are kept.
"""
from __future__ import annotations

import os
import pickle
import zlib

from .linetable import LineTable

__all__ = ["compile_cached", "CachedProgram", "KEEP"]

#: programs kept (the least recently used go first)
KEEP = 256
_FORMAT = 1         # bump when an entry's layout changes


class CachedProgram:
    """What a run uses of a :class:`~spinemu.compiler.CompiledProgram`, as kept in the cache."""

    def __init__(self, binary: bytes, lines: list, warnings: list, labels: dict, symbols: list, debug):
        self.binary = binary
        self.line_table = LineTable(lines)
        self.warnings = warnings
        self._labels, self._symbols, self._debug = labels, symbols, debug

    def dat_labels(self) -> dict:
        return self._labels

    def dat_symbols(self) -> list:
        return self._symbols

    def debug_info(self):
        return self._debug

    def eeprom(self) -> bytes:
        from .image import to_eeprom
        return to_eeprom(self.binary)


def _fingerprint_file(path: str):
    """``(size, crc32)`` of a file's contents, or None if it cannot be read as one."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    return len(data), zlib.crc32(data)


def _fingerprint_dir(path: str):
    """``(entries, crc32 of their names)`` of a folder, or None if it is not one."""
    try:
        names = sorted(os.listdir(path))
    except OSError:
        return None
    return len(names), zlib.crc32("\0".join(names).encode("utf-8", "surrogateescape"))


#: the modules (besides the two packages) whose code makes a compiled program
_COMPILER_MODULES = ("bytecode.py", "image.py", "linetable.py", "debuginfo.py", "diagnostics.py", "messages.py",
                     "records.py", "progcache.py")


def _compiler_stamp() -> int:
    """A checksum of the size and time of every file of the compiler (its modules and its grammar), so that
    a changed compiler (a new version, or a checkout being worked on) compiles anew."""
    pkg = os.path.dirname(os.path.abspath(__file__))
    files = [os.path.join(pkg, name) for name in _COMPILER_MODULES]
    files += [os.path.join(pkg, "grammars", "spin.lark"), os.path.join(os.path.dirname(pkg), "grammars", "spin.lark")]
    for sub in ("frontend", "compiler"):
        try:
            files += [e.path for e in os.scandir(os.path.join(pkg, sub)) if e.name.endswith(".py")]
        except OSError:
            pass
    stamps = []
    for f in sorted(files):
        try:
            st = os.stat(f)
            stamps.append(f"{f}:{st.st_size}:{st.st_mtime_ns}")
        except OSError:
            stamps.append(f"{f}:-")
    return zlib.crc32("\n".join(stamps).encode("utf-8", "surrogateescape"))


def _key(path: str, include_dirs, defines) -> tuple:
    from . import __version__
    env = os.environ
    return (_FORMAT, __version__, _compiler_stamp(), os.fspath(path), os.getcwd(),
            tuple(os.path.abspath(d) for d in include_dirs), tuple(defines), env.get("SPINEMU_PATH"),
            # (where the installed tools' library folders are looked for on Windows)
            tuple(env.get(v) for v in ("ProgramFiles", "ProgramFiles(x86)", "ProgramW6432")))


def _entry_path(key: tuple):
    from .fileio import cache_base
    base = cache_base()
    if base is None:
        return None
    from .fileio import cache_name
    return os.path.join(base, f"programs-{key[1]}", cache_name(repr(key).encode("utf-8", "surrogateescape"), ".pickle"))


def _load(entry: str, key: tuple):
    try:
        with open(entry, "rb") as f:
            saved = pickle.load(f)
        if saved["key"] != key:
            return None
        if any(_fingerprint_file(p) != fp for p, fp in saved["files"]):
            return None
        if any(_fingerprint_dir(p) != fp for p, fp in saved["dirs"]):
            return None
        prog = CachedProgram(saved["binary"], saved["lines"], saved["warnings"], saved["labels"],
                             saved["symbols"], saved["debug"])
        os.utime(entry)             # (recently used: pruned last)
        return prog
    except Exception:               # missing, damaged, from another layout: compile
        return None


def _save(entry: str, key: tuple, prog) -> None:
    from .fileio import write_cache_file

    search = prog.objects[0].unit.search if prog.objects else None
    if search is None:
        return
    saved = {
        "key": key,
        # (the sources and DAT files as the compiler read them; the others as they are now)
        "files": [(p, fp if fp is not None else _fingerprint_file(p)) for p, fp in sorted(search.files.items())],
        "dirs": [(p, _fingerprint_dir(p)) for p in sorted(search.dirs)],
        "binary": bytes(prog.binary), "lines": prog.line_table.items(columns=True),
        "warnings": list(prog.warnings), "labels": prog.dat_labels(), "symbols": prog.dat_symbols(),
        "debug": prog.debug_info(),
    }
    try:
        write_cache_file(entry, pickle.dumps(saved, protocol=pickle.HIGHEST_PROTOCOL), KEEP)
    except (OSError, pickle.PicklingError, TypeError, AttributeError):
        pass                        # (a cache that cannot be written is skipped)


def compile_cached(path: str, include_dirs=(), defines=()):
    """``compile_file(path, include_dirs, defines)``, or the cached result when it is still valid.

    Returns a :class:`~spinemu.compiler.CompiledProgram` (compiled now, and cached) or a
    :class:`CachedProgram`.  Raises what ``compile_file`` raises.
    """
    include_dirs, defines = list(include_dirs or ()), list(defines or ())
    key = _key(path, include_dirs, defines)
    entry = _entry_path(key)
    if entry is not None:
        prog = _load(entry, key)
        if prog is not None:
            return prog
    from .compiler import compile_file

    prog = compile_file(path, include_dirs=include_dirs, defines=defines)
    if entry is not None:
        _save(entry, key, prog)
    return prog
