"""Logic-analyser style plots of a pin trace with matplotlib.

Each pin is drawn as a step waveform on its own row; undriven stretches are
drawn as a dashed line at mid height (the 'z' of a logic analyser).
matplotlib is imported only when a plot is made (``pip install spinemu[plot]``).
"""
from __future__ import annotations

from typing import Iterable, Optional

from ..trace import PinTrace

__all__ = ["plot_trace", "plot_formats"]


def _segments(trace: PinTrace, pin: int, start: int, end: int):
    """(t0, t1, level) runs of one pin inside [start, end]; level is 0, 1 or None (floating)."""
    runs = []
    level = None
    t = start
    for c, d, o in trace.changes:
        new = (o >> pin & 1) if d >> pin & 1 else None
        if c <= start:
            level = new
            continue
        if c >= end:
            break
        if new != level:
            runs.append((t, c, level))
            t, level = c, new
    runs.append((t, end, level))
    return runs


def plot_formats() -> set:
    """The file extensions (without the dot) matplotlib can save a figure as: png, svg, pdf, ..."""
    from matplotlib.backend_bases import FigureCanvasBase

    return set(FigureCanvasBase.get_supported_filetypes())


def plot_trace(trace: PinTrace, pins: Optional[Iterable[int]] = None, start: int = 0,
               end: Optional[int] = None, path: Optional[str] = None, title: Optional[str] = None):
    """Draw the pins' waveforms over ``[start, end]`` (cycles).

    Args:
        trace: the trace.
        pins: which pins (default: every pin ever driven), drawn top to bottom.
        start, end: the window in cycles (default: the whole run).
        path: if given, save the figure there (PNG, SVG or PDF by extension).
        title: figure title.

    Returns:
        The matplotlib ``Figure``.
    """
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    end = trace.end_cycle if end is None else end
    end = max(end, start + 1)       # an empty window (a trace of one instant, --end before --start): one cycle
    pins = list(trace.driven_pins() if pins is None else pins)
    scale, unit = _time_unit((end - start) / trace.clock_hz)
    fig, ax = plt.subplots(figsize=(10, 0.6 * len(pins) + 1.2))
    for row, pin in enumerate(pins):
        base = (len(pins) - 1 - row) * 1.5
        for t0, t1, level in _segments(trace, pin, start, end):
            x0, x1 = t0 / trace.clock_hz * scale, t1 / trace.clock_hz * scale
            if level is None:
                ax.plot([x0, x1], [base + 0.5, base + 0.5], linestyle="--", color="grey", linewidth=0.8)
            else:
                ax.plot([x0, x1], [base + level, base + level], color="tab:green", linewidth=1.2)
                ax.plot([x1, x1], [base, base + 1], color="tab:green", linewidth=0.4, alpha=0.5)
    ax.set_yticks([(len(pins) - 1 - r) * 1.5 + 0.5 for r in range(len(pins))])
    ax.set_yticklabels([trace.pin_names.get(p, f"P{p}") for p in pins])
    ax.set_xlabel(f"time ({unit})")
    x0, x1 = start / trace.clock_hz * scale, end / trace.clock_hz * scale
    if not x1 > x0:                 # a window far out (--start 10**20): one cycle is below float precision
        x1 = x0 + max(abs(x0) * 1e-9, 1e-9)
    ax.set_xlim(x0, x1)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path)
    return fig


def _time_unit(span_s: float) -> tuple[float, str]:
    if span_s >= 2:
        return 1.0, "s"
    if span_s >= 2e-3:
        return 1e3, "ms"
    return 1e6, "us"
