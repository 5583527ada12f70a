"""The OBJ-file hint: a library folder's file hides a different file of the same name.

OBJ files are looked for next to the file that names them, then in the
library folders in order (:func:`spinemu.frontend.objects.resolve_object_file`);
the first found wins.  When that one comes from a library folder and a later
library folder has a *different* file of the same name, the program may not
use the object its author expected: a hint says which one was taken.  Kept
apart from the loader so that how folders are searched can change without it.
"""
from __future__ import annotations

import filecmp
import os

from ..diagnostics import Diagnostic
from .. import messages as msg

__all__ = ["shadowed_object_hints"]


def shadowed_object_hints(decl, found: str, from_dir: str, include_dirs, source) -> list:
    """Hints for OBJ line ``decl`` whose file resolved to ``found`` (``source``: the naming file's text)."""
    if os.path.dirname(os.path.abspath(found)) == os.path.abspath(from_dir):
        return []                                   # the object's own folder: no library involved
    fname = os.path.basename(found)
    seen = {os.path.realpath(found)}
    out = []
    for d in include_dirs:
        cand = os.path.join(d, fname)
        real = os.path.realpath(cand)
        if real in seen or not os.path.isfile(cand):
            continue
        seen.add(real)
        try:
            same = filecmp.cmp(found, cand, shallow=False)
        except OSError:
            same = False
        if not same:
            pos = decl.pos
            out.append(Diagnostic(msg.HINT_SHADOWED_OBJECT.format(name=decl.filename, used=found, other=cand),
                                  pos.path, pos.line, pos.col, source.line(pos.line), "warning"))
    return out
