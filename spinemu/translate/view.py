"""The teaching view: Spin source and its Python translation next to each other, line-aligned.

Each generated Python line knows the Spin line it came from (``# L<n>``);
the view puts each Spin line in the left column and the Python lines it
became in the right one (a Spin line that became several Python lines gets
blank rows on the left).  The Python column is syntax-highlighted; the
bookkeeping at the end of a module (the cycle table) is left out.
"""
from __future__ import annotations

import os

from rich.console import Group
from rich.syntax import Syntax
from rich.table import Table
from rich.text import Text

__all__ = ["side_by_side_view", "aligned_rows"]


def aligned_rows(spin_text: str, module) -> list[tuple]:
    """``(spin_line_no, spin_text, python_line)`` rows, aligned on the Spin line numbers.

    Python lines with no Spin line (imports, blank lines, class header) are
    shown next to nothing; Spin lines with no Python (comments carried as
    comments, blank lines) next to nothing.
    """
    spin_lines = spin_text.splitlines()
    py_lines = module.text.splitlines()
    end = next((i for i, line in enumerate(py_lines) if line.startswith("# Cycles each line")), len(py_lines))
    while end > 0 and not py_lines[end - 1].strip():
        end -= 1
    rows = []
    next_spin = 1
    for i in range(end):
        n = module.spin_lines[i] if i < len(module.spin_lines) else None
        if n is not None and n >= next_spin:
            for k in range(next_spin, n):
                rows.append((k, spin_lines[k - 1] if k - 1 < len(spin_lines) else "", ""))
            rows.append((n, spin_lines[n - 1] if n - 1 < len(spin_lines) else "", py_lines[i]))
            next_spin = n + 1
        else:
            rows.append((None, "", py_lines[i]))
    for k in range(next_spin, len(spin_lines) + 1):
        rows.append((k, spin_lines[k - 1], ""))
    return rows


def _table(module) -> Table:
    with open(module.spin_path, encoding="utf-8", errors="replace") as fh:
        spin_text = fh.read()
    table = Table(title=f"{os.path.basename(module.spin_path)}  ->  {module.module}.py",
                  show_lines=False, expand=True, pad_edge=False)
    table.add_column("Spin", no_wrap=True, overflow="ellipsis", ratio=1)
    table.add_column("Python", no_wrap=True, overflow="ellipsis", ratio=1)
    for n, spin, py in aligned_rows(spin_text, module):
        python = Syntax(py, "python", theme="ansi_dark", background_color="default") if py.strip() else Text("")
        left = Text(f"{n:>4} " if n is not None else "     ", style="dim")
        left.append(spin.expandtabs(8))
        table.add_row(left, python)
    return table


def side_by_side_view(modules) -> Group:
    """A rich renderable with one aligned table per module (top object first)."""
    return Group(*(_table(m) for m in modules))
