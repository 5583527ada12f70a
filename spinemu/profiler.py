"""A cycle profiler for Spin programs: cycles per Spin line and per method, per cog, waits apart.

:class:`Profiler` is a chip probe (``Chip.probe``; the instrumented loop calls
it around every bytecode, see :mod:`spinemu.chip.scheduler`).  Each bytecode
is charged the cycles from its start to the start of the same cog's next
bytecode, so every cycle of a cog's life lands somewhere:

* **work**: the bytecode's own time (its hub windows included);
* **wait**: the part a ``WAITCNT`` spends until its count comes, a
  ``WAITPEQ``/``WAITPNE`` until its pins match, a ``WAITVID`` until the video
  generator takes the frame (the fixed cost of the instruction is work);
* **start**: from the ``COGINIT`` that started the cog to its first bytecode.

So for every cog, work + wait + start is exactly the cycles from its start
to its stop (or to the end of the run): for cog 0, which runs from cycle 0,
that is the run's length if it runs to the end.  A cog running PASM is not
broken down by line (the probe sees Spin bytecodes only): its lives count as
``pasm`` cycles, so work + wait + start + pasm is its running time.  Lines and methods come from
the program's :class:`~spinemu.debuginfo.DebugInfo` (an image without one is
profiled by bytecode address).  Method figures are *self* cycles: the
bytecodes of the method itself, not of the methods it calls.

Compiled blocks and busy-loop fast-forward are off while profiling (each
bytecode is seen); the program runs exactly as without the profiler.
"""
from __future__ import annotations

import csv
import io
import json
import os
from dataclasses import asdict, dataclass, field
from typing import Optional

__all__ = ["Profiler", "Profile", "LineStat", "MethodStat", "CogStat", "profile_program"]

_MASK = 0xFFFFFFFF
_WAITCNT, _WAITPEQ, _WAITPNE, _WAITVID = 0x23, 0x1B, 0x1F, 0x27


@dataclass
class LineStat:
    """Cycles of one Spin line in one cog (``path``/``line`` ``None``: bytecode at ``addr`` without a line)."""

    cog: int
    path: Optional[str]
    line: Optional[int]
    method: Optional[str]
    bytecodes: int = 0
    work: int = 0
    wait: int = 0
    addr: Optional[int] = None

    @property
    def cycles(self) -> int:
        return self.work + self.wait


@dataclass
class MethodStat:
    """Self cycles of one method (``object.method``) in one cog."""

    cog: int
    method: str
    path: Optional[str]
    bytecodes: int = 0
    work: int = 0
    wait: int = 0

    @property
    def cycles(self) -> int:
        return self.work + self.wait


@dataclass
class CogStat:
    """One cog over the run: its lives (start to stop), and how their cycles split."""

    cog: int
    lives: list = field(default_factory=list)       # [(start cycle, stop cycle)]
    start: int = 0                                   # cycles from COGINIT to the first bytecode
    work: int = 0
    wait: int = 0
    bytecodes: int = 0
    pasm: int = 0                                    # cycles it ran PASM (not broken down)

    @property
    def cycles(self) -> int:
        return sum(b - a for a, b in self.lives)


@dataclass
class Profile:
    """What the profiler found (see the module docstring)."""

    program: str
    clock_hz: int
    end_cycle: int
    cogs: list
    lines: list
    methods: list
    sources: dict = field(default_factory=dict, repr=False)

    # ------------------------------------------------------------------ outputs
    def to_dict(self) -> dict:
        return {
            "program": self.program, "clock_hz": self.clock_hz, "end_cycle": self.end_cycle,
            "cogs": [dict(asdict(c), cycles=c.cycles) for c in self.cogs],
            "lines": [dict(asdict(s), cycles=s.cycles) for s in self.lines],
            "methods": [dict(asdict(m), cycles=m.cycles) for m in self.methods],
        }

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), indent=1)

    def to_csv(self) -> str:
        """One row per (cog, line): ``cog,file,line,method,bytecodes,work_cycles,wait_cycles,cycles``."""
        out = io.StringIO()
        w = csv.writer(out, lineterminator="\n")
        w.writerow(["cog", "file", "line", "method", "bytecodes", "work_cycles", "wait_cycles", "cycles"])
        for s in self.lines:
            w.writerow([s.cog, s.path if s.path else f"${s.addr:04X}", s.line or "", s.method or "", s.bytecodes,
                        s.work, s.wait, s.cycles])
        return out.getvalue()

    def listing(self) -> str:
        """Every source file with each line's cycles (all cogs): ``work  wait | line| source``."""
        per: dict = {}
        for s in self.lines:
            if s.path is not None:
                k = (s.path, s.line)
                work, wait = per.get(k, (0, 0))
                per[k] = (work + s.work, wait + s.wait)
        total = sum(c.cycles for c in self.cogs) or 1
        out = []
        for path, lines in self.sources.items():
            out.append(f"; {path}: cycles per line over all cogs (work, wait, share of all cogs' cycles)")
            for n, text in enumerate(lines, 1):
                work, wait = per.get((path, n), (0, 0))
                if work or wait:
                    figures = f"{work:>14,} {wait:>14,} {100 * (work + wait) / total:6.2f}%"
                else:
                    figures = " " * 37
                out.append(f"{figures} |{n:5d}| {text.rstrip()}")
            out.append("")
        return "\n".join(out)

    def table(self, top: int = 15):
        """A rich renderable: per cog, its split and its hottest lines and methods."""
        from rich.console import Group
        from rich.table import Table

        parts = []
        cogs = Table(title=f"cycles per cog ({self.end_cycle:,} cycles run)", box=None, header_style="bold")
        for col in ("cog", "lived", "work", "wait", "start", "bytecodes"):
            cogs.add_column(col, justify="right")
        for c in self.cogs:
            if c.pasm:
                cogs.add_row(str(c.cog), f"{c.cycles:,}", f"PASM: {c.pasm:,}", "", f"{c.start:,}", "")
                continue
            cogs.add_row(str(c.cog), f"{c.cycles:,}", _share(c.work, c.cycles), _share(c.wait, c.cycles),
                         f"{c.start:,}", f"{c.bytecodes:,}")
        parts.append(cogs)
        for c in self.cogs:
            if not c.bytecodes:
                continue
            lines = sorted((s for s in self.lines if s.cog == c.cog), key=lambda s: -s.cycles)[:top]
            t = Table(title=f"cog {c.cog}: hottest lines", box=None, header_style="bold")
            for col, just, width in (("line", "left", 21), ("work", "right", 11), ("wait", "right", 11),
                                     ("%", "right", 5), ("bytecodes", "right", 9)):
                t.add_column(col, justify=just, no_wrap=True, min_width=width)
            t.add_column("source", overflow="ellipsis", no_wrap=True)
            for s in lines:
                src = (self._source(s.path, s.line) or s.method or "").split("'")[0].strip()
                where = f"{os.path.basename(s.path)}:{s.line}" if s.path else f"${s.addr:04X}"
                t.add_row(where, f"{s.work:,}", f"{s.wait:,}", _percent(s.cycles, c.cycles), f"{s.bytecodes:,}", src)
            parts.append(t)
            ms = sorted((m for m in self.methods if m.cog == c.cog), key=lambda m: -m.cycles)[:top]
            mt = Table(title=f"cog {c.cog}: methods (self cycles)", box=None, header_style="bold")
            for col, width in (("method", 18), ("work", 11), ("wait", 11), ("%", 5), ("bytecodes", 9)):
                mt.add_column(col, justify="left" if col == "method" else "right", no_wrap=True, min_width=width)
            for m in ms:
                mt.add_row(m.method, f"{m.work:,}", f"{m.wait:,}", _percent(m.cycles, c.cycles), f"{m.bytecodes:,}")
            parts.append(mt)
        return Group(*parts)

    def _source(self, path, line):
        lines = self.sources.get(path) if path else None
        return lines[line - 1] if lines and line and 0 < line <= len(lines) else None


def _percent(part: int, whole: int) -> str:
    return f"{100 * part / whole:.1f}" if whole else "-"


def _share(part: int, whole: int) -> str:
    return f"{part:,} ({100 * part / whole:.1f}%)" if whole else f"{part:,}"


class Profiler:
    """The probe that counts (attach with ``chip.probe = Profiler(chip, info)``; then :meth:`finish`).

    Args:
        chip: the :class:`spinemu.chip.Chip` it will run on.
        info: the program's :class:`~spinemu.debuginfo.DebugInfo`, or ``None``.
    """

    def __init__(self, chip, info=None):
        self.chip = chip
        self.info = info
        T = chip.timing
        self._waitcnt_fixed = T.waitcnt_issue + T.waitcnt_min
        self._waitpin_fixed = {op: sum(T.waitpin[op == _WAITPEQ]) for op in (_WAITPEQ, _WAITPNE)}
        self._waitvid_fixed = T.waitvid_issue + T.waitvid_after
        self._open: list = [None] * 8       # per cog: (pc, t, op, waitcnt wait) of the bytecode now running
        self._counts: dict = {}             # (cog, pc) -> [bytecodes, work, wait]
        self._cogs = [CogStat(i) for i in range(8)]
        self._life_start: list = [None] * 8
        self._fresh = [False] * 8          # a life has started and its first bytecode is still to come
        self._pasm = [False] * 8           # the current life runs PASM
        self._events = 0

    # ------------------------------------------------------------------ the probe
    def before(self, chip, c) -> None:
        if len(chip.cog_events) != self._events:
            self._scan(chip)
        cid = c.id
        t = c.t
        last = self._open[cid]
        if last is not None:
            self._close(cid, last, t)
        elif self._fresh[cid]:
            self._fresh[cid] = False
            self._cogs[cid].start += t - self._life_start[cid]
        pc = c.pc
        op = chip.mem[pc]
        wait = 0
        if op == _WAITCNT:
            tf = t + 12
            tf += (c.hub_phase - tf) & 15
            target = chip.mem_longs[((c.sp - 4) & 0xFFFF) >> 2]
            wait = (target - tf - self._waitcnt_fixed) & _MASK
        self._open[cid] = (pc, t, op, wait)

    def after(self, chip, c, pc: int, t: int) -> None:
        pass

    def _close(self, cid: int, rec, t_end: int) -> None:
        pc, t, op, wait = rec
        elapsed = t_end - t
        if op == _WAITCNT:
            wait = min(wait, elapsed)
        elif op in (_WAITPEQ, _WAITPNE, _WAITVID):
            tf = t + 12
            tf += (self.chip.cogs[cid].hub_phase - tf) & 15
            fixed = (tf - t) + (self._waitvid_fixed if op == _WAITVID else self._waitpin_fixed[op])
            wait = max(0, elapsed - fixed)
        k = (cid, pc)
        entry = self._counts.get(k)
        if entry is None:
            entry = self._counts[k] = [0, 0, 0]
        entry[0] += 1
        entry[1] += elapsed - wait
        entry[2] += wait
        self._open[cid] = None

    def _scan(self, chip) -> None:
        """Cog starts and stops since the last look: close a stopped cog's last bytecode at its stop."""
        for t, cid, kind, detail in chip.cog_events[self._events:]:
            if kind == "start":
                if self._life_start[cid] is not None:   # restarted without a stop of its own
                    self._end_life(cid, t)
                self._life_start[cid] = t
                self._pasm[cid] = detail.startswith("PASM")
                self._fresh[cid] = not self._pasm[cid]
            else:
                self._end_life(cid, t)
        self._events = len(chip.cog_events)

    def _end_life(self, cid: int, t: int) -> None:
        last = self._open[cid]
        if last is not None:
            self._close(cid, last, t)
        elif self._fresh[cid]:                      # stopped before its first bytecode
            self._fresh[cid] = False
            self._cogs[cid].start += t - self._life_start[cid]
        if self._life_start[cid] is not None:
            if self._pasm[cid]:
                self._cogs[cid].pasm += t - self._life_start[cid]
            self._cogs[cid].lives.append((self._life_start[cid], t))
            self._life_start[cid] = None

    # ------------------------------------------------------------------ the result
    def finish(self, program: str = "") -> Profile:
        """Close the bytecodes still running at the end of the run and sum everything up."""
        chip = self.chip
        self._scan(chip)
        end = chip.now
        for cid in range(8):
            if self._life_start[cid] is not None or self._open[cid] is not None:
                self._end_life(cid, end)
        info = self.info
        lines: dict = {}
        methods: dict = {}
        for (cid, pc), (n, work, wait) in sorted(self._counts.items()):
            pos = info.position(pc) if info is not None else None
            m = info.method_at(pc) if info is not None else None
            back = pc
            while pos is None and m is not None and back > m.start:
                back -= 1                               # the method's closing RETURN: its last line
                pos = info.position(back)
            if m is not None:
                mname = f"{os.path.splitext(os.path.basename(m.path))[0]}.{m.name}"
            else:
                mname = "(ROM)" if pc >= 0x8000 else None
            key = (cid, pos[0], pos[1]) if pos else (cid, None, pc)
            s = lines.get(key)
            if s is None:
                s = lines[key] = LineStat(cid, pos[0] if pos else None, pos[1] if pos else None, mname,
                                          addr=None if pos else pc)
            s.bytecodes += n
            s.work += work
            s.wait += wait
            mk = (cid, mname or "?")
            ms = methods.get(mk)
            if ms is None:
                ms = methods[mk] = MethodStat(cid, mname or "(no method)", m.path if m else None)
            ms.bytecodes += n
            ms.work += work
            ms.wait += wait
            cog = self._cogs[cid]
            cog.bytecodes += n
            cog.work += work
            cog.wait += wait
        cogs = [c for c in self._cogs if c.lives]
        sources = dict(info.sources) if info is not None else {}
        return Profile(program, chip.clock_hz, end, cogs, list(lines.values()), list(methods.values()), sources)


def profile_program(path: str, *, cycles: Optional[int] = None, include_dirs=(), defines=(),
                    compat: str = "spinsim", inputs=None, warn=False):
    """Compile (a ``.spin`` file) or load an image, run it under the profiler.

    Returns:
        ``(Profile, RunResult)``.
    """
    from .chip import Chip
    from .compiler import compile_file
    from .image import load_image

    info = None
    if str(path).lower().endswith(".spin"):
        prog = compile_file(str(path), include_dirs, defines=defines)
        image, info = prog.binary, prog.debug_info()
    else:
        with open(path, "rb") as f:
            image = load_image(f.read(), str(path))
    chip = Chip(image, compat=compat, inputs=inputs, debug_info=info, warn=warn)
    profiler = Profiler(chip, info)
    chip.probe = profiler
    result = chip.run(max_cycles=cycles)
    return profiler.finish(str(path)), result
