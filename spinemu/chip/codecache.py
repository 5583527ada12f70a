"""Compiled blocks kept on disk between runs of the same program, as Python keeps ``__pycache__``.

Compiling the Python source of a program's hot Spin blocks (:mod:`.blocks`)
takes a good part of a short run (0.03 s of the column's demo).  ``spinemu run`` gives its chip a :class:`CodeCache` for the
image: the code objects compiled in one run are written to one file, and the
next run of the same image takes them from there instead of compiling.

A cached code object is found by the exact source text it was compiled
from (and its name), so a stale or foreign entry is never used: it just
misses.  The file is read with :mod:`marshal` (no code runs while loading)
and written atomically; a damaged or unreadable file counts as empty, and a
cache that cannot be written is silently skipped.  The directory is
``$SPINEMU_CACHE_DIR``, else ``$XDG_CACHE_HOME/spinemu``, else
``~/.cache/spinemu``, in a subdirectory per spinemu version and Python
version; ``SPINEMU_CACHE=0`` (or ``spinemu run --no-cache``) turns it off.  At
most :data:`KEEP` files are kept (the least recently used go first).
"""
from __future__ import annotations

import marshal
import os
import sys

__all__ = ["CodeCache", "for_image", "cache_dir", "KEEP"]

#: files (programs) kept per cache directory
KEEP = 256
_FORMAT = 3         # (1: the code objects alone; 2: generated blocks not by generator)


def cache_dir() -> str | None:
    """The directory for this spinemu and Python, or None when caching is off."""
    from .. import __version__
    from ..fileio import cache_base

    base = cache_base()
    if base is None:
        return None
    return os.path.join(base, f"blocks-{__version__}-{sys.implementation.cache_tag}-{sys.hexversion:08x}")


def for_image(image: bytes) -> "CodeCache" | None:
    """The cache of compiled blocks for a program image, or None when caching is off."""
    d = cache_dir()
    if d is None:
        return None
    from ..fileio import cache_name
    # (a name only: entries are found by their source, so a clash just misses)
    return CodeCache(os.path.join(d, cache_name(bytes(image), ".marshal")))


class CodeCache:
    """Code objects by ``(source, name)``, and generated blocks by what they were generated from
    (:meth:`blocks_at`), loaded from and saved to ``path``."""

    def __init__(self, path: str):
        self.path = path
        self.codes: dict = {}
        #: generator -> {(address, variant and the compiler's settings) -> [(inputs, generated block)]}:
        #: see blocks.py; blocks of another generator (spinemu's code changed) are dropped on saving
        self.blocks: dict = {}
        self.hits = self.misses = 0
        self._dirty = False
        self._used: set = set()         # code keys this run used
        self._generators: set = set()   # generators this run asked for blocks of
        try:
            with open(path, "rb") as f:
                saved = marshal.loads(f.read())
            if isinstance(saved, tuple) and len(saved) == 3 and saved[0] == _FORMAT:
                self.codes, self.blocks = saved[1], saved[2]
                os.utime(path)      # (recently used: pruned last)
        except Exception:           # missing, damaged, from another Python: start empty
            self.codes, self.blocks = {}, {}

    def blocks_at(self, generator, key) -> list:
        """The blocks ``generator`` made at ``key`` (a list to look through, and to add a new one to)."""
        if generator not in self._generators:
            self._generators.add(generator)
            if any(g != generator for g in self.blocks):
                self._dirty = True          # (blocks of another generator: drop them when saving)
        made = self.blocks.get(generator)
        if made is None:
            made = self.blocks[generator] = {}
        found = made.get(key)
        if found is None:
            found = made[key] = []
        return found

    def added_block(self) -> None:
        """A block was added to a :meth:`blocks_at` list: save it with the rest."""
        self._dirty = True

    def compile(self, src: str, name: str):
        """``compile(src, name, "exec")``, from the cache when it has it."""
        key = (src, name)
        self._used.add(key)
        code = self.codes.get(key)
        if code is not None:
            self.hits += 1
            return code
        self.misses += 1
        code = compile(src, name, "exec")
        self.codes[key] = code
        self._dirty = True
        return code

    def save(self) -> None:
        """Write the cache if this run compiled something new (errors are ignored)."""
        if not self._dirty:
            return
        from ..fileio import write_cache_file

        if self._generators:        # the blocks and code objects only other generators made go
            self.blocks = {g: v for g, v in self.blocks.items() if g in self._generators}
            sources = {made[0] for v in self.blocks.values() for lst in v.values() for _, made in lst}
            self.codes = {k: c for k, c in self.codes.items() if k in self._used or k[0] in sources}
        try:
            write_cache_file(self.path, marshal.dumps((_FORMAT, self.codes, self.blocks)), KEEP)
            self._dirty = False
        except OSError:
            pass
