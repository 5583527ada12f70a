"""Decoded frames as an annotation file, to read beside a VCD in GTKWave or PulseView.

``spinemu trace decode ... --annotations FILE`` writes one line per decoded
frame, tab-separated, after a few ``#`` header lines (the protocol, the
pins, the clock, the VCD time unit)::

    # spinemu annotations: i2c on P28, P29
    # clock 80000000 Hz; VCD time unit 100 ps (125 per cycle)
    # start_s	end_s	start_vcd	end_vcd	start_cycle	end_cycle	text
    0.000131250	0.000497500	1312500	4975000	10500	39800	S 0x50 W ACK: 7F 00 2A P

``start_vcd``/``end_vcd`` are times in the unit of the VCD spinemu writes for
the same run (``--trace run.vcd``), so a frame is found in GTKWave by
jumping to that time (or by placing a marker there), and in PulseView by
its time in seconds; PulseView can also run its own decoder of the same
protocol on the VCD to draw the frames as a row of annotations.  The file
is plain text: a spreadsheet or ``awk`` reads it too.
"""
from __future__ import annotations

from typing import Iterable, Sequence, TextIO

from ..trace import vcd_timescale

__all__ = ["write_annotations", "read_annotations"]


def write_annotations(fp: TextIO, frames: Iterable, clock_hz: int, protocol: str, pins: Sequence[int]) -> None:
    """Write ``(start_cycle, end_cycle, text)`` frames (see the module docstring).

    >>> import io
    >>> buf = io.StringIO()
    >>> write_annotations(buf, [(80, 160, "$41 A")], 80_000_000, "uart", [30])
    >>> print(buf.getvalue().splitlines()[-1])
    0.000001000	0.000002000	10000	20000	80	160	$41 A
    """
    scale, per_cycle = vcd_timescale(clock_hz)
    fp.write(f"# spinemu annotations: {protocol} on " + ", ".join(f"P{p}" for p in pins) + "\n")
    fp.write(f"# clock {clock_hz} Hz; VCD time unit {scale} ({per_cycle} per cycle)\n")
    fp.write("# start_s\tend_s\tstart_vcd\tend_vcd\tstart_cycle\tend_cycle\ttext\n")
    for start, end, text in frames:
        fp.write(f"{start / clock_hz:.9f}\t{end / clock_hz:.9f}\t{start * per_cycle}\t{end * per_cycle}\t"
                 f"{start}\t{end}\t{text}\n")


def read_annotations(text: str) -> list:
    """The frames of an annotation file: ``(start_cycle, end_cycle, text)``.

    Raises:
        ValueError: for a line that is not an annotation.
    """
    out = []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cols = line.split("\t")
        if len(cols) != 7:
            raise ValueError(f"line {n}: expected 7 tab-separated columns")
        out.append((int(cols[4]), int(cols[5]), cols[6]))
    return out
