"""The listing: the image's bytes beside the Spin lines that made them.

It is a second view of the compiler's spans (the binary is the first), so
the two cannot disagree.  Layout::

    ; object stepper.spin (size $01FC)
    ;   54|  mode := m & %1111
    $0113  64 37 23 E8 ...        PUSH m ...

With ``addresses=False`` (golden test files) the address column is left out
and the object header shows no size, so goldens do not churn.
"""
from __future__ import annotations

import os

__all__ = ["format_listing"]

_BYTES_PER_ROW = 8


def format_listing(prog, addresses: bool = True) -> str:
    out: list[str] = []
    for cobj in prog.objects:
        base = prog.addresses[id(cobj.unit)]
        name = os.path.basename(cobj.unit.path)
        out.append(f"; object {name}" + (f" at ${base:04X} (size ${cobj.size:04X})" if addresses else ""))
        source = cobj.unit.spin.source
        last_line = None
        data = getattr(cobj, "linked", None) or bytes(cobj.data)
        for span in cobj.spans:
            if span.pos is not None and span.pos.line != last_line:
                last_line = span.pos.line
                text = (source.line(last_line) or "").rstrip()
                out.append(f";{last_line:5d}| {text}")
            chunk = data[span.offset:span.offset + len(span.data)]
            for i in range(0, len(chunk), _BYTES_PER_ROW):
                row = chunk[i:i + _BYTES_PER_ROW]
                hexes = " ".join(f"{b:02X}" for b in row)
                note = span.note if i == 0 else ""
                prefix = f"${base + span.offset + i:04X}  " if addresses else "  "
                out.append(f"{prefix}{hexes:<24}  {note}".rstrip())
        out.append("")
    return "\n".join(out)
