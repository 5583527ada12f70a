"""Plots with matplotlib: a pin trace as a logic analyser draws it, and a motor's motion.

:func:`plot_trace` draws each pin as a step waveform on its own row; undriven
stretches are drawn as a dashed line at mid height (the 'z' of a logic analyser).
:func:`plot_motion` draws what a stepper motor's shaft did
(:class:`~spinemu.bench.stepper_motor.Motion`): position, speed and acceleration
against time, one panel each, several motions on the same axes.
matplotlib is imported only when a plot is made (``pip install spinemu[plot]``).
"""
from __future__ import annotations

from typing import Iterable, Optional

from ..trace import PinTrace

__all__ = ["plot_trace", "plot_motion", "plot_formats"]


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


def plot_motion(motions, path: Optional[str] = None, title: Optional[str] = None,
                start: Optional[float] = None, end: Optional[float] = None,
                panels: Iterable[str] = ("position", "speed", "acceleration"),
                rest_after: Optional[float] = None):
    """Position, speed and acceleration of a stepper motor's shaft against time.

    Args:
        motions: a :class:`~spinemu.bench.stepper_motor.Motion`, or a dict of
            label -> Motion to draw several on the same axes.
        path: if given, save the figure there (PNG, SVG or PDF by extension).
        title: figure title.
        start, end: the time window in seconds (default: everything).
        panels: which of ``"position"``, ``"speed"``, ``"acceleration"``, top to bottom.
        rest_after: intervals longer than this (s) count as standing still (see ``Motion.speeds``).

    Returns:
        The matplotlib ``Figure``.  Speed is drawn as steps (one value per interval
        between two moves); missed steps are red crosses on the position panel, with
        the position the drive asked for dashed.
    """
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    if not isinstance(motions, dict):
        motions = {None: motions}
    panels = list(panels)
    unknown = [p for p in panels if p not in ("position", "speed", "acceleration")]
    if unknown or not panels:
        raise ValueError(f"panels are 'position', 'speed' and 'acceleration', not {unknown or panels}")
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(9, 2.3 * len(panels) + 0.6), squeeze=False)
    axes = [a[0] for a in axes]

    def inside(t: float) -> bool:
        return (start is None or t >= start) and (end is None or t <= end)

    unit = "steps"
    for label, m in motions.items():
        unit = m.unit
        for ax, panel in zip(axes, panels):
            if panel == "position":
                pts = [(s.time, s.position) for s in m.steps if inside(s.time)]
                line, = ax.plot([t for t, _ in pts], [p for _, p in pts], drawstyle="steps-post", label=label)
                missed = [s for s in m.missed if inside(s.time)]
                if missed:
                    cmd = [(s.time, s.commanded) for s in m.steps if inside(s.time)]
                    ax.plot([t for t, _ in cmd], [c for _, c in cmd], linestyle="--", linewidth=0.8,
                            color=line.get_color(), drawstyle="steps-post")
                    ax.plot([s.time for s in missed], [s.position for s in missed], "x", color="red",
                            markersize=4, label=f"{label or 'motor'}: missed")
            elif panel == "speed":
                sp = [(a, b, v) for a, b, v in m.speeds(rest_after) if inside(a)]
                xs = [a for a, _, _ in sp] + [sp[-1][1]] if sp else []
                ys = [v for _, _, v in sp] + [0.0] if sp else []
                ax.plot(xs, ys, drawstyle="steps-post", label=label)
            else:
                acc = [(t, a) for t, a in m.accelerations(rest_after) if inside(t)]
                ax.plot([t for t, _ in acc], [a for _, a in acc], ".", markersize=2, label=label)
    names = {"position": f"position ({unit})", "speed": f"speed ({unit}/s)",
             "acceleration": f"acceleration ({unit}/s²)"}
    for ax, panel in zip(axes, panels):
        ax.set_ylabel(names[panel])
        ax.grid(True, linewidth=0.3)
        if any(k is not None for k in motions) or any(m.missed for m in motions.values()):
            ax.legend(loc="best", fontsize="small")
    axes[-1].set_xlabel("time (s)")
    if start is not None or end is not None:
        axes[-1].set_xlim(left=start, right=end)
    if title:
        axes[0].set_title(title)
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
