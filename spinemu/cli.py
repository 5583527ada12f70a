"""The ``spinemu`` command: argument parsing around the library, nothing more.

Each subcommand calls one library function, renders its result with rich and
sets the exit status: 0 success, 1 bad input (a :class:`SpinError`), 2 usage
errors, 70 an internal error (a bug in spinemu: any other exception, caught by
the last-resort guard in :func:`main`).  Library errors are rendered
``file:line:col: error: ...`` with the source line and a caret; a Python
traceback is never shown unless asked for (``--traceback`` or
``SPINEMU_TRACEBACK=1``).
Nothing imports this module; it imports the rest of spinemu lazily so that
``spinemu --help`` starts fast.
"""
from __future__ import annotations

import argparse
import contextlib
import math
import os
import sys
import time
from collections.abc import Sequence
from io import TextIOBase

from . import __version__
from .cli_bench import RunBench, add_decode_parser, bench_options, chip_input_model, decode_command
from .cli_console import ConsoleSession, console_options, console_wanted
from .cli_tools import (_add_debug_parser, _add_profile_parser, _attach_profiler, _print_hints,
                        _runtime_warning_log, _runtime_warning_rows, _warning_options)
from .diagnostics import SpinError, UsageError

__all__ = ["main", "entry_point", "build_parser"]

CLOCK_DEFAULT = 80_000_000
SPIN_EXT = (".spin",)
IMAGE_EXT = (".binary", ".bin", ".eeprom", ".eep")
BS2_EXT = (".bs2", ".bs1", ".pbasic", ".bas")

EPILOG = """\
examples:
  spinemu run spin_src/stepper_demo.spin                 run the column's demo to the end
  spinemu run spin_src/stepper_demo.spin --trace demo.vcd --trace-format vcd
  spinemu compile spin_src/stepper_demo.spin -o demo.binary
  spinemu run spin_src/bs2/stepper_bs2.bs2 --seconds 3   the BASIC Stamp original
  spinemu run spin_src/examples/serial_echo.spin --baud 9600 --console
                                                         a serial console on P30/P31: type numbers
  spinemu trace show demo.log --pins 0..4                timeline of pins 0-4
  spinemu trace steps demo.log --pins 1..4               stepper decoder (coils)
  spinemu trace steps accel.log --step-dir 0,1 --plot m.png   step/dir driver, motion plot
  spinemu trace decode uart run.log --pin 30 --baud 9600  serial text on a pin
  spinemu run spin_src/stepper_demo.spin --bench spin_src/stepper_board.toml
                                                         parts on the pins: the motor's steps per run
  spinemu trace decode i2c run.log --pins 28,29          I2C transfers (addresses, data, ACK/NAK)
  spinemu disasm demo.binary                             listing of an image

OBJ and DAT file names are looked up in the source's folder, the -L folders, the
folders in SPINEMU_PATH (separated by '%s') and the Spin library folders of an
installed Propeller Tool, PropellerIDE or SimpleIDE; a name found only in another
letter case (a project written on Windows) is used with a warning.

exit status:
  0   success (trace compare / sidebyside: the traces agree)
  1   an error in the input (file:line:col: error: ...), or traces that differ
  2   a usage error (wrong or missing arguments)
  70  an internal error: a bug in spinemu (--traceback shows where it failed)
""" % os.pathsep


# ----------------------------------------------------------------------------- helpers
def _whole_number(text: str, least: int, what: str) -> int:
    """An argparse type: a whole number (``1_000``, ``0x10`` allowed) of at least ``least``."""
    t = text.strip().replace("_", "")
    try:
        if not t.isascii() or len(t) > 40:        # no other scripts' digits, no 5,000-digit numbers
            raise ValueError
        v = int(t, 0)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}")
    if v < least:
        raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}")
    return v


def _positive_int(text: str) -> int:
    return _whole_number(text, 1, "a number above 0")


def _count(text: str) -> int:
    """A count or a cycle number: 0 or more."""
    return _whole_number(text, 0, "a number, 0 or more")


def _finite_float(text: str, least: float, strict: bool, most: float = float("inf")) -> float:
    try:
        v = float(text.replace("_", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}")
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    if v < least or (strict and v == least):
        raise argparse.ArgumentTypeError(f"expected a number {'above' if strict else 'of at least'} {least:g}, "
                                         f"got {text!r}")
    if v > most:
        raise argparse.ArgumentTypeError(f"expected a number of at most {most:g}, got {text!r}")
    return v


#: The longest time a command line names (``--seconds``, ``--input`` times): about 32 years.
MAX_SECONDS = 1e9


def _positive_float(text: str) -> float:
    """Seconds of simulated time: above 0, at most :data:`MAX_SECONDS`."""
    return _finite_float(text, 0.0, strict=True, most=MAX_SECONDS)


def _fraction(text: str) -> float:
    """A relative error: finite, 0 or more."""
    return _finite_float(text, 0.0, strict=False)


def _width(text: str) -> int:
    v = _positive_int(text)
    if v > 1000:
        raise argparse.ArgumentTypeError(f"expected at most 1000 columns, got {text!r}")
    return v


def _write_atomic(path: str, data, binary: bool) -> None:
    """Write a whole file or nothing: to a temporary file first, then rename."""
    from .fileio import write_atomic

    write_atomic(path, data, binary)


def _read_bytes(path: str) -> bytes:
    if os.path.exists(path) and not os.path.isfile(path) and not os.path.isdir(path):
        # a device or a FIFO: /dev/zero would never end, a FIFO would wait for a writer
        raise SpinError("cannot read file: not a regular file", path=path)
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError as e:
        raise SpinError(f"cannot read file: {e.strerror or e}", path=path)


def _kind(path: str) -> str:
    low = path.lower()
    if low.endswith(SPIN_EXT):
        return "spin"
    if low.endswith(IMAGE_EXT):
        return "image"
    if low.endswith(BS2_EXT):
        return "pbasic"
    raise UsageError(f"cannot tell what '{path}' is: expected .spin, .binary, .eeprom or .bs2")


class _Out:
    """stdout/stderr plus rich consoles on them (made when first used: importing rich
    costs a plain ``run`` a tenth of its start-up)."""

    def __init__(self, stdout: TextIOBase, stderr: TextIOBase, quiet: bool = False):
        self.stdout, self.stderr, self.quiet = stdout, stderr, quiet
        self._console = self._err_console = None

    @property
    def console(self):
        if self._console is None:
            from rich.console import Console

            self._console = Console(file=self.stdout, highlight=False, soft_wrap=False)
        return self._console

    @property
    def err_console(self):
        if self._err_console is None:
            from rich.console import Console

            self._err_console = Console(file=self.stderr, highlight=False, soft_wrap=True)
        return self._err_console

    def print(self, *items) -> None:
        if not self.quiet:
            self.console.print(*items)

    def warn(self, text: str) -> None:
        """One line (or more) on stderr, as it is (no markup)."""
        self.stderr.write(text + "\n")
        self.stderr.flush()

    def rows(self, rows) -> None:
        """Label/value rows as two aligned columns (a value's further lines are indented)."""
        if self.quiet:
            return
        width = max((len(k) for k, _ in rows), default=0) + 2
        lines = []
        for k, v in rows:
            first, *rest = str(v).split("\n")
            lines.append(f"{k:<{width}}{first}".rstrip())
            lines += [(" " * width + more).rstrip() for more in rest]
        self.stdout.write("\n".join(lines) + "\n")
        self.stdout.flush()


# ----------------------------------------------------------------------------- compile
def _compile(path: str, include_dirs, defines=()):
    from .compiler import compile_file

    if not os.path.exists(path):
        raise SpinError("no such file", path=path)
    return compile_file(path, include_dirs=list(include_dirs or ()), defines=list(defines or ()))


def cmd_compile(args, out: _Out) -> int:
    if _kind(args.source) != "spin":
        raise UsageError(f"'{args.source}' is not a .spin source file")
    prog = _compile(args.source, args.include, args.define)
    _print_hints(out, prog)
    target = args.output or os.path.splitext(args.source)[0] + ".binary"
    written = []
    if not args.eeprom or args.output:
        _write_atomic(target, prog.binary, True)
        written.append(target)
    if args.eeprom:
        _write_atomic(args.eeprom, prog.eeprom(), True)
        written.append(args.eeprom)
    if args.listing:
        _write_atomic(args.listing, prog.listing(), False)
        written.append(args.listing)
    out.print(f"{args.source}: {len(prog.binary)} bytes of program -> {', '.join(written)}")
    return 0


# ----------------------------------------------------------------------------- run
def _load_target(path: str, include_dirs, defines=(), cached: bool = False):
    """(image bytes, source_map or None, program or None) for a .spin/.binary/.eeprom target.

    ``cached``: a Spin program may come from the compiled-program cache (spinemu.progcache).
    """
    from .image import load_image

    if _kind(path) == "spin":
        if cached and os.path.isfile(path):
            from .progcache import compile_cached
            prog = compile_cached(path, include_dirs, defines)
        else:
            prog = _compile(path, include_dirs, defines)
        table = getattr(prog, "line_table", None)
        source_map = (lambda addr: table.get(addr)) if isinstance(table, dict) else table
        return prog.binary, source_map, prog
    return load_image(_read_bytes(path), path), None, None


def _progress_callback(out: _Out, total: int | None, clock_hz: int, enabled: bool):
    """A rich progress display on a terminal: a bar towards the cycle limit, or the
    simulated time so far when the run goes until every cog stops."""
    if not enabled or out.quiet or not out.stderr.isatty():
        return None, None
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

    if total:
        columns = [TextColumn("simulating"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                   TimeRemainingColumn()]
    else:
        columns = [TextColumn("simulating until every cog stops:"), TextColumn("{task.fields[sim]}"),
                   TimeElapsedColumn()]
    progress = Progress(*columns, console=out.err_console, transient=True)
    task = progress.add_task("run", total=total, sim="0.000 s")
    last = [time.monotonic()]

    def update(cycle: int) -> None:
        now = time.monotonic()
        if now - last[0] > 0.1:
            last[0] = now
            progress.update(task, completed=min(cycle, total) if total else cycle,
                            sim=f"{cycle / clock_hz:.3f} s simulated")

    return progress, update


def _spin_inputs(args, clock_hz: int):
    """The chip's input model for ``--inputs``/``--input`` (the profiler's runs; ``run`` has a bench)."""
    return chip_input_model(args, clock_hz, _compat(args))


def _compat(args) -> str:
    return args.compat or "spinsim"


def _run_limit(args, clock_hz: int) -> int | None:
    if args.cycles is not None:
        return args.cycles
    if args.seconds is not None:
        return int(round(args.seconds * clock_hz))
    return None


def _summary_rows(trace, end_cycle: int, extra_rows) -> list:
    from .analysis.view import format_time

    rows = [("simulated", f"{format_time(end_cycle, trace.clock_hz)} ({end_cycle:,} cycles at {trace.clock_hz:,} Hz)")]
    rows += extra_rows
    edges = trace.edge_counts()
    driven = trace.driven_pins()
    if driven:
        rows.append(("pins", ", ".join(f"P{p}: {edges.get(p, 0)} edges" for p in driven)))
    else:
        rows.append(("pins", "no pin was ever driven"))
    return rows


def _write_trace(args, trace) -> None:
    if not args.trace:
        return
    fmt = args.trace_format or ("vcd" if args.trace.lower().endswith(".vcd") else "log")
    _write_atomic(args.trace, trace.write_vcd if fmt == "vcd" else trace.write_log, False)


def cmd_run(args, out: _Out) -> int:
    kind = _kind(args.target)
    if kind == "pbasic":
        return _run_pbasic(args, out)
    if args.timing or args.debug_in:
        raise UsageError("--timing and --debug-in apply to BASIC Stamp programs (.bs2) only")
    if args.console_in_at is not None and not args.console_in:
        raise UsageError("--console-in-at needs --console-in FILE (the bytes to send)")
    image, source_map, prog = _load_target(args.target, args.include, args.define,
                                           cached=not args.no_cache and args.engine != "python")
    _print_hints(out, prog)
    from .image import FALLBACK_CLOCK_HZ, ImageHeader, to_eeprom

    clock = ImageHeader.parse(image).clkfreq or FALLBACK_CLOCK_HZ       # the chip's time base too
    limit = _run_limit(args, clock)
    session = ConsoleSession(args, out, clock, live_text=not args.view) if console_wanted(args) else None
    raw = _read_bytes(args.target) if kind == "image" else None
    eeprom = raw if raw is not None and len(raw) == 32768 else to_eeprom(image)
    bench = RunBench(args, out, clock_hz=clock, pin_count=32, engine="the Propeller", eeprom_image=eeprom,
                     session=session)
    t0 = time.perf_counter()
    chip = None
    with session or contextlib.nullcontext(), bench.run_context():
        if args.engine == "python":
            if kind != "spin":
                raise UsageError("--engine python needs a .spin source (it translates the source)")
            if args.trace_cog:
                raise UsageError("--trace-cog works with the bytecode engine (leave out --engine python)")
            from .translate import run_translated

            result = run_translated(args.target, include_dirs=list(args.include or ()), max_cycles=limit,
                                    compat=_compat(args), inputs=bench.chip_inputs(_compat(args)),
                                    parts=bench.bench if bench.active else ())
        else:
            from .chip import Chip

            log = _runtime_warning_log(args, out, prog)
            chip = Chip(eeprom if raw is not None and len(raw) == 32768 else image, compat=_compat(args),
                        inputs=bench.chip_inputs(_compat(args)), source_map=source_map,
                        labels=prog.dat_labels() if prog is not None else None,
                        warn=log if log is not None else False,
                        debug_info=prog.debug_info() if prog is not None else None,
                        steady_skip=not args.no_steady_skip)
            if not args.no_cache:
                from .chip.codecache import for_image
                chip.code_cache = for_image(image)
            profiler = _attach_profiler(chip, prog) if args.profile else None
            bench.attach(chip)
            with _pasm_trace_sink(args, out, chip, prog) as sink:
                for cog_id in args.trace_cog or ():
                    chip.trace_cog(cog_id, sink)
                progress, update = _progress_callback(out, limit, clock, not args.no_progress and not args.view
                                                      and not (session and session.shows))
                if progress is not None:
                    with progress:
                        result = chip.run(max_cycles=limit, progress=update)
                else:
                    result = chip.run(max_cycles=limit)
    wall = time.perf_counter() - t0
    if chip is not None and chip.code_cache is not None:
        chip.code_cache.save()         # the blocks this run compiled, for the next run
    _write_trace(args, bench.trace(result.trace))
    bench.finish()
    if args.dump_hub:
        _write_atomic(args.dump_hub, bytes(result.hub), True)
    for w in result.warnings + (session.warnings(result.end_cycle) if session else []) + bench.warnings():
        out.warn(f"warning: {w}")
    if not out.quiet:
        started = sum(1 for e in result.cog_events if e[2] == "start")
        stopped = sum(1 for e in result.cog_events if e[2] == "stop")
        sim_s = result.end_cycle / result.trace.clock_hz
        reason = result.reason
        if session and reason == "deadlock":
            reason += ": the cogs wait on pins nothing will change (input the console does not have)"
        elif session and reason == "stalled":
            reason += ": the cogs poll pins and memory nothing will change (input the console does not have)"
        rows = [("ended", reason),
                ("cogs", f"{started} started, {stopped} stopped"),
                ("speed", f"{sim_s / wall:.1f}x real time ({wall:.2f} s wall)" if wall > 0 else "-")]
        rows += _pasm_rows(result)
        if result.stats.get("steady_periods_skipped"):
            rows.append(("steady", f"{result.stats['steady_periods_skipped']:,} periods of a steady state skipped"))
        if args.trace:
            rows.append(("trace", f"{args.trace} ({len(result.trace.changes)} changes)"))
        if session:
            rows.append(session.summary())
        rows += bench.rows()
        if result.stats.get("pll"):
            rows.append(("PLL", _pll_summary(result.stats["pll"])))
        rows.extend(_runtime_warning_rows(getattr(result, "runtime_warnings", [])))
        out.rows(_summary_rows(result.trace, result.end_cycle, rows))
    if args.engine != "python" and args.profile:
        out.console.print(profiler.finish(args.target).table())
    return 0


def _pll_summary(plls: list) -> str:
    """One line per PLL output of a run: pins, frequency, which counter, and whether the trace shows it."""
    def hz(f):
        return f"{f / 1e6:.6g} MHz" if f >= 1e6 else f"{f / 1e3:.6g} kHz" if f >= 1e3 else f"{f:.6g} Hz"
    lines = []
    for p in plls[:8]:
        pins = ", ".join(f"P{x}" for x in p["pins"]) or "internal"
        note = "" if p["traced"] or not p["pins"] else ", not in the trace"
        lines.append(f"{pins}: {hz(p['frequency_hz'])} (cog {p['cog']} CTR{p['counter']}, {p['mode']}{note})")
    if len(plls) > 8:
        lines.append(f"... and {len(plls) - 8} more")
    return "\n".join(lines)


def _pasm_rows(result) -> list:
    """Summary rows for the PASM cogs a run started: where, and how many instructions they ran."""
    counts = result.stats.get("pasm_instructions_per_cog", {})
    rows = []
    for cycle, cog_id, kind, detail in result.cog_events:
        if kind == "start" and detail.startswith("PASM"):
            rows.append((f"cog {cog_id}", f"{detail} at cycle {cycle:,}"))
    if counts:
        text = ", ".join(f"cog {k}: {n:,} instructions" for k, n in sorted(counts.items()))
        skipped = result.stats.get("pasm_instructions_skipped", 0)
        if skipped:
            text += f" ({skipped:,} of them skipped in idle loops)"
        rows.append(("PASM", text))
    return rows


class _pasm_trace_sink:
    """``--trace-cog``: a callback writing one line per PASM instruction to the chosen file (or stdout).

    With the program's source, the DAT labels of the code the cog was loaded
    from name its registers and jump targets (a label counts when its cog
    address matches its distance from the start of the loaded code).
    """

    def __init__(self, args, out: "_Out", chip, prog):
        self.path = getattr(args, "trace_cog_file", None) if getattr(args, "trace_cog", None) else None
        self.stream = out.stdout
        self.file = None
        self.chip = chip
        self.dat = prog.dat_symbols() if prog is not None else []
        self.symbols: dict = {}         # code address -> {cog address: label}

    def _symbols(self, code: int) -> dict:
        table = self.symbols.get(code)
        if table is None:
            table = self.symbols[code] = {cog: name for hub, cog, name in self.dat
                                          if hub >= code and (hub - code) == 4 * cog}
        return table

    def __enter__(self):
        if self.path and self.path != "-":
            try:
                self.file = self.stream = open(self.path, "w", encoding="utf-8")
            except OSError as e:
                raise UsageError(f"cannot write '{self.path}': {e.strerror}") from None
        write, cogs = self.stream.write, self.chip.cogs
        return lambda step: write(step.text(self._symbols(cogs[step.cog].code_addr)) + "\n")

    def __exit__(self, *exc):
        if self.file is not None:
            self.file.close()
        return False


_PBASIC_REASONS = {"end": "END statement", "stop": "STOP statement", "time": "time limit",
                   "input": "waiting for DEBUGIN/SERIN input that never came",
                   "instructions": "instruction limit (a loop without PAUSE never lets time pass)"}


def _run_pbasic(args, out: _Out) -> int:
    from .pbasic import CLOCK_HZ, run_file

    if args.engine == "python" or args.compat is not None or args.inputs is not None:
        raise UsageError("--engine, --compat and --inputs apply to Spin programs only")
    if args.console_in_at is not None and not args.console_in:
        raise UsageError("--console-in-at needs --console-in FILE (the bytes to send)")
    if args.cycles is not None:
        raise UsageError("BASIC Stamp runs are limited with --seconds (the BS2 has no system counter)")
    if not os.path.exists(args.target):
        raise SpinError("no such file", path=args.target)
    seconds = args.seconds if args.seconds is not None else 10.0
    session = None
    if console_wanted(args):
        if not args.console_pins:
            raise UsageError("the serial console on a BASIC Stamp program needs --console-pins TX,RX (pins "
                             "0..15, the SEROUT and SERIN pins; its DEBUG text is printed anyway)")
        session = ConsoleSession(args, out, CLOCK_HZ, live_text=not args.view)
    bench = RunBench(args, out, clock_hz=CLOCK_HZ, pin_count=16, engine="the BASIC Stamp", session=session)
    t0 = time.perf_counter()
    with session or contextlib.nullcontext(), bench.run_context():
        result = run_file(args.target, seconds=seconds, timing=args.timing or "exact", inputs=bench.spec or None,
                          debug_in=args.debug_in, parts=bench.bench if bench.active else ())
    wall = time.perf_counter() - t0
    if result.debug_output:
        out.stdout.write(result.debug_output)
        if not result.debug_output.endswith("\n"):
            out.stdout.write("\n")
    _write_trace(args, bench.trace(result.trace))
    for w in result.warnings:
        out.warn(w.render() if hasattr(w, "render") else f"warning: {w}")
    for w in (session.warnings(result.end_cycle) if session else []) + bench.warnings():
        out.warn(f"warning: {w}")
    if not out.quiet:
        trace = result.trace
        end = trace.end_cycle
        sim_s = end / trace.clock_hz
        rows = [("ended", _PBASIC_REASONS.get(result.reason, result.reason)), ("timing", args.timing or "exact"),
                ("speed", f"{sim_s / wall:.1f}x real time ({wall:.2f} s wall)" if wall > 0 else "-")]
        if args.trace:
            rows.append(("trace", f"{args.trace} ({len(trace.changes)} changes)"))
        if session:
            rows.append(session.summary())
        rows += bench.rows()
        out.rows(_summary_rows(trace, end, rows))
    return 0


# ----------------------------------------------------------------------------- disasm
def cmd_disasm(args, out: _Out) -> int:
    from .analysis.disasm import disassemble_image

    source_map = None
    if _kind(args.target) == "spin":
        image, source_map, _ = _load_target(args.target, args.include)
    else:
        image, _, _ = _load_target(args.target, args.include)
    text = disassemble_image(image, source_map=source_map)
    if args.output:
        _write_atomic(args.output, text, False)
    else:
        out.stdout.write(text if text.endswith("\n") else text + "\n")
    return 0


# ----------------------------------------------------------------------------- translate
def cmd_translate(args, out: _Out) -> int:
    from . import translate

    if _kind(args.source) != "spin":
        raise UsageError(f"'{args.source}' is not a .spin source file")
    if not os.path.exists(args.source):
        raise SpinError("no such file", path=args.source)
    if args.side_by_side:
        out.console.print(translate.side_by_side(args.source, include_dirs=list(args.include or ())))
        return 0
    if not args.output:
        raise UsageError("translate needs -o OUT_DIR (or --side-by-side)")
    files = translate.translate_file(args.source, args.output, include_dirs=list(args.include or ()))
    out.print(f"{args.source} -> " + ", ".join(files))
    return 0


# ----------------------------------------------------------------------------- trace tools
def _load_trace(path: str, clock_hz: int):
    from .trace import TraceFormatError, read_log

    text = _read_bytes(path).decode("utf-8", "replace")
    if text.lstrip().startswith("$"):
        raise UsageError(f"'{path}' looks like a VCD file; trace tools read the log format")
    try:
        return read_log(text, clock_hz)
    except TraceFormatError as e:
        raise SpinError(e.message, path=path, line=e.line, column=1, source_line=e.text)


def _pins(spec: str | None, option: str = "--pins", coils: bool = False):
    """The pins of a ``--pins`` spec; ``coils``: exactly four different pins (a stepper's coils)."""
    if spec is None:
        return None
    from .analysis.view import parse_pins

    try:
        pins = parse_pins(spec)
    except ValueError as e:
        raise UsageError(f"{option}: {e}")
    if coils and (len(pins) != 4 or len(set(pins)) != 4):
        raise UsageError(f"{option}: a stepper has four coil pins (four different pins in table order, "
                         f"e.g. 1..4), got {spec!r}")
    return pins


def _plot_path(path: str) -> str:
    """``path`` if matplotlib can write a plot in the format its extension names."""
    try:
        from .analysis.plot import plot_formats
        formats = plot_formats()
    except ImportError:
        raise SpinError("trace plot needs matplotlib: pip install 'spinemu[plot]'")
    ext = os.path.splitext(path)[1].lower().lstrip(".")
    if ext not in formats:
        raise UsageError(f"-o: cannot tell the image format of '{path}'; the extension must be one of "
                         + ", ".join("." + f for f in sorted(formats)))
    return path


def cmd_trace(args, out: _Out) -> int:
    action = args.trace_action
    if action == "compare":
        from .analysis.compare import compare_traces

        ref, cand = _load_trace(args.reference, args.clock), _load_trace(args.candidate, args.clock)
        result = compare_traces(ref, cand, until=args.until, slack=args.slack, tolerance=args.tolerance)
        out.stdout.write(result.render() + "\n")
        return 0 if result.passed else 1
    if action == "plot":
        _plot_path(args.output)
    trace = _load_trace(args.file, args.clock)
    start = args.start or 0
    end = args.end if args.end is not None else trace.end_cycle
    if action == "show":
        from .analysis.view import render_changes, render_timeline

        out.console.print(render_timeline(trace, _pins(args.pins), start, end, args.width))
        if args.changes:
            out.console.print(render_changes(trace, start, end, args.changes))
        return 0
    if action == "convert":
        _write_atomic(args.output, trace.write_vcd, False)
        out.print(f"{args.file} -> {args.output}")
        return 0
    if action == "plot":
        from .analysis.plot import plot_trace

        fig = plot_trace(trace, _pins(args.pins), start, end, path=args.output, title=os.path.basename(args.file))
        import matplotlib.pyplot as plt
        plt.close(fig)
        out.print(f"{args.file} -> {args.output}")
        return 0
    if action == "steps":
        return _trace_steps(args, trace, start, end, out)
    if action == "decode":
        return decode_command(args, trace, out)
    raise UsageError(f"unknown trace action {action!r}")


def _trace_steps(args, trace, start: int, end: int, out: _Out) -> int:
    from .analysis.stepper import decode_step_dir, decode_steps, render_steps
    from .bench.stepper_motor import motor_from_trace

    if bool(args.pins) == bool(args.step_dir):
        raise UsageError("trace steps needs either --pins with the four coil pins (e.g. --pins 1..4) "
                         "or --step-dir with the step and dir pins (e.g. --step-dir 0,1)")
    window = dict(start=start / trace.clock_hz, end=end / trace.clock_hz)
    if args.pins:
        coils = _pins(args.pins, coils=True)
        drive = dict(coils=coils)
        steps = decode_steps(trace, coils, **window)
    else:
        pins = _pins(args.step_dir)
        if len(pins) != 2:
            raise UsageError(f"--step-dir needs two pins, STEP,DIR (e.g. 0,1), got {args.step_dir!r}")
        drive = dict(step=pins[0], dir=pins[1])
        steps = decode_step_dir(trace, pins[0], pins[1], **window)
    out.stdout.write(render_steps(steps, trace.clock_hz, limit=args.limit, max_segments=args.segments) + "\n")
    if args.pull_in is not None or args.plot:
        try:
            motion = motor_from_trace(trace, pull_in=args.pull_in, **drive)
        except ValueError as e:
            raise UsageError(str(e))
        out.stdout.write("\n" + motion.summary() + "\n")
        if args.plot:
            from .analysis.plot import plot_motion

            plot_motion(motion, path=args.plot, title=os.path.basename(args.file),
                        start=window["start"], end=window["end"])
            out.print(f"{args.file} -> {args.plot}")
    return 0


def cmd_sidebyside(args, out: _Out) -> int:
    from .analysis.stepper import compare_stepper_traces

    left = _load_trace(args.left, args.left_clock)
    right = _load_trace(args.right, args.right_clock)
    names = (os.path.basename(args.left), os.path.basename(args.right))
    report = compare_stepper_traces(left, _pins(args.left_pins, "--left-pins", coils=True), right,
                                    _pins(args.right_pins, "--right-pins", coils=True),
                                    steps=args.steps, names=names)
    out.stdout.write(report.render() + "\n")
    return 0 if report.same_sequence else 1


# ----------------------------------------------------------------------------- parser
_TRACE_DESCRIPTIONS = {
    "steps": "Decode a stepper motor's steps from a trace log: four coil pins in table order (--pins) "
             "or a step/direction driver (--step-dir STEP,DIR). Prints the runs at one speed and the "
             "first steps. --pull-in and --plot run the steps through the bench's stepper motor "
             "(docs/stepper_motor.md): the steps a motor with that pull-in rate misses, and position, "
             "speed and acceleration against time. --start/--end (cycles) limit the listed steps and the plot "
             "to a window (the motor runs through the whole trace).",
}


def _obj_search_option(p) -> None:
    p.add_argument("-L", "-I", dest="include", action="append", metavar="DIR",
                   help="add a folder to search for OBJ and DAT file names (after the source's own folder, "
                        "before SPINEMU_PATH and the installed tools' libraries)")


def _define_option(p) -> None:
    p.add_argument("-D", dest="define", action="append", metavar="NAME",
                   help="define NAME for #ifdef in every file (as OpenSpin's -D)")


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose help is as wide as the terminal, found without importing :mod:`shutil`
    (argparse imports it for that on every parser built; it costs start-up some milliseconds)."""

    def _get_formatter(self):
        columns = os.environ.get("COLUMNS", "")
        if not columns.isdigit() or int(columns) <= 0:          # as shutil.get_terminal_size
            try:
                columns = os.get_terminal_size(sys.__stdout__.fileno()).columns
            except (AttributeError, ValueError, OSError):
                columns = 0
        return self.formatter_class(prog=self.prog, width=(int(columns) or 80) - 2)


#: the commands, in the order the help lists them
COMMANDS = {
    "compile": "compile Spin to a Propeller image (byte-identical with OpenSpin)",
    "run": "run a .spin, .binary, .eeprom or .bs2 program and record its pins",
    "disasm": "list an image: header, objects, bytecode, PASM",
    "translate": "translate Spin to readable Python",
    "trace": "look at, compare, convert, plot and decode pin traces (log files)",
    "sidebyside": "compare two traces as stepper step sequences (e.g. BS2 vs Propeller)",
    "debug": "debug a Spin program (and its PASM cogs): breakpoints, stepping, call stacks, variables",
    "profile": "cycles per Spin line and per method, per cog (waits apart from work)",
}


def _add_compile_parser(sub) -> None:
    c = sub.add_parser("compile", help=COMMANDS["compile"],
                       description="Compile a Spin program (and its OBJ children) to a Propeller 1 image.")
    c.add_argument("source", metavar="SRC.spin")
    c.add_argument("-o", "--output", metavar="OUT.binary", help="image file (default: SRC.binary)")
    c.add_argument("-e", "--eeprom", metavar="OUT.eeprom", help="also (or only) write the 32 KB EEPROM image")
    _obj_search_option(c)
    _define_option(c)
    c.add_argument("--listing", metavar="FILE", help="write a listing (bytecode with source lines)")
    c.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")
    c.set_defaults(func=cmd_compile)


def _add_run_parser(sub) -> None:
    r = sub.add_parser("run", help=COMMANDS["run"],
                       description="Run a program on the emulated chip and record every pin change.\n"
                                   "Spin sources are compiled first. A run ends when every cog has "
                                   "stopped, when nothing can change any more (every cog waits on pins "
                                   "or polls in a loop nothing will wake: 'deadlock', 'stalled'), or at "
                                   "the limit (--cycles, --seconds; BASIC Stamp programs: 10 s by default).",
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    r.add_argument("target", metavar="TARGET", help=".spin, .binary, .eeprom or .bs2 file")
    lim = r.add_mutually_exclusive_group()
    lim.add_argument("--cycles", type=_positive_int, metavar="N", help="stop after N clock cycles")
    lim.add_argument("--seconds", type=_positive_float, metavar="S", help="stop after S simulated seconds")
    r.add_argument("--trace", metavar="FILE", help="write the pin trace to FILE")
    r.add_argument("--trace-format", choices=["log", "vcd"],
                   help="log: '<cycle> <dir> <out>' lines; vcd: for GTKWave/PulseView (default: by extension, else log)")
    r.add_argument("--dump-hub", metavar="FILE", help="write the 32 KB hub RAM at the end of the run")
    _obj_search_option(r)
    _define_option(r)
    r.add_argument("--compat", choices=["spinsim", "chip"],
                   help="spinsim (default): Parallax's ROM interpreter as the cycle-exact reference simulator runs "
                        "it, cycle for cycle; chip: the silicon where it differs (a new cog loads for 7,952 "
                        "cycles, lock 0 first, one hub window per cog); see docs/timing.md")
    r.add_argument("--inputs", choices=["pulldown", "pullup"],
                   help="what pins nobody drives read as (default: pullup with --compat spinsim, as the "
                        "reference reads them; pulldown with --compat chip)")
    r.add_argument("--input", dest="stimulus", metavar="SPEC",
                   help="drive input pins (any program): 'P3=1' holds P3 high; 'P5=0@0,1@0.25' sets P5 low at 0 s "
                        "and high at 0.25 s; several pins separated by ';'")
    r.add_argument("--debug-in", metavar="TEXT", default="", help="BASIC Stamp only: characters DEBUGIN/SERIN will read")
    r.add_argument("--engine", choices=["bytecode", "python"], default="bytecode",
                   help="bytecode: interpret the compiled image (default); python: run the Spin-to-Python translation")
    r.add_argument("--timing", choices=["exact", "realistic"],
                   help="BASIC Stamp only: exact command durations, or with per-instruction interpreter time")
    console_options(r)
    bench_options(r)
    r.add_argument("--trace-cog", type=int, action="append", choices=range(8), metavar="N",
                   help="log every PASM instruction cog N executes: cycle, address, disassembly, flags after it "
                        "and the value written (repeatable; bytecode engine only)")
    r.add_argument("--trace-cog-file", metavar="FILE", default="-",
                   help="where --trace-cog writes its log (default: standard output)")
    r.add_argument("--no-progress", action="store_true", help="no progress bar")
    r.add_argument("--no-cache", action="store_true",
                   help="compile the program (and its hot blocks) anew instead of taking them from the "
                        "cache of earlier runs, which is used only while no source or folder they came "
                        "from has changed (~/.cache/spinemu; SPINEMU_CACHE=0 turns it off for good)")
    r.add_argument("--no-steady-skip", action="store_true",
                   help="run every period of a steady state paced by WAITCNT (a blinking LED, a PWM loop) "
                        "instead of skipping the periods proven to repeat (the results are the same)")
    r.add_argument("-q", "--quiet", action="store_true", help="no summary")
    _warning_options(r)
    r.add_argument("--profile", action="store_true",
                   help="also profile the run: cycles per Spin line and method per cog (slower; see "
                        "'spinemu profile' for JSON, CSV and an annotated listing)")
    r.set_defaults(func=cmd_run)


def _add_disasm_parser(sub) -> None:
    d = sub.add_parser("disasm", help=COMMANDS["disasm"],
                       description="Disassemble a Propeller image (.binary/.eeprom from any compiler, or a .spin "
                                   "source, compiled first and listed with its source lines).")
    d.add_argument("target", metavar="TARGET")
    d.add_argument("-o", "--output", metavar="FILE", help="write the listing to FILE")
    _obj_search_option(d)
    d.set_defaults(func=cmd_disasm)


def _add_translate_parser(sub) -> None:
    t = sub.add_parser("translate", help=COMMANDS["translate"],
                       description="Translate a Spin program and its objects to Python modules that run on the same chip model.")
    t.add_argument("source", metavar="SRC.spin")
    t.add_argument("-o", "--output", metavar="OUT_DIR", help="folder for the generated modules")
    t.add_argument("--side-by-side", action="store_true", help="print Spin and Python next to each other")
    _obj_search_option(t)
    t.add_argument("-q", "--quiet", action="store_true")
    t.set_defaults(func=cmd_translate)


def _add_trace_parser(sub) -> None:
    tr = sub.add_parser("trace", help=COMMANDS["trace"],
                        description="Tools for '<cycle> <dir> <out>' trace logs written by 'spinemu run --trace'.")
    clock = _Parser(add_help=False)
    clock.add_argument("--clock", type=_positive_int, default=CLOCK_DEFAULT,
                       help="cycles per second of the log (default 80_000_000; BASIC Stamp logs: 1_000_000)")
    ts = tr.add_subparsers(dest="trace_action", metavar="ACTION")
    tc = ts.add_parser("compare", help="same pin-state sequence? timing error?", parents=[clock])
    tc.add_argument("reference")
    tc.add_argument("candidate")
    tc.add_argument("--until", type=_positive_int, metavar="CYCLE", help="ignore changes after this cycle")
    tc.add_argument("--tolerance", type=_fraction, default=0.005, help="worst timing error to pass (default 0.005)")
    tc.add_argument("--slack", type=_count, default=16_000, help="cycles of fixed offset forgiven (default 16000)")
    for name, help_ in (("show", "timeline of the pins in the terminal"), ("plot", "waveform plot to an image file"),
                        ("convert", "convert a log to VCD"),
                        ("steps", "decode stepper coil patterns or step/dir pulses into steps")):
        a = ts.add_parser(name, help=help_, parents=[clock], description=_TRACE_DESCRIPTIONS.get(name, help_))
        a.add_argument("file")
        if name in ("plot", "convert"):
            a.add_argument("-o", "--output", required=True, metavar="FILE")
        if name != "convert":
            a.add_argument("--pins", metavar="SPEC", help="pins, e.g. 0..4 or 4..7,0" +
                           (" (the coils, in table order)" if name == "steps" else ""))
        a.add_argument("--start", type=_count, metavar="CYCLE")
        a.add_argument("--end", type=_count, metavar="CYCLE")
        if name == "show":
            a.add_argument("--width", type=_width, default=64, help="columns of the timeline (1..1000)")
            a.add_argument("--changes", type=_count, default=0, metavar="N", help="also list the first N changes")
        if name == "steps":
            a.add_argument("--step-dir", metavar="STEP,DIR",
                           help="decode a step/direction driver instead: its step and dir pins, e.g. 0,1 "
                                "(a step per high pulse of at least 1 us, forward while DIR is high)")
            a.add_argument("--limit", type=_count, default=20, metavar="N", help="show the first N steps")
            a.add_argument("--segments", type=_count, default=40, metavar="N",
                           help="show the first N segments (runs at one speed; default 40)")
            a.add_argument("--pull-in", type=_positive_float, metavar="RATE",
                           help="run the steps through the motor model with this pull-in rate (steps/s) "
                                "and report the steps it misses")
            a.add_argument("--plot", metavar="FILE",
                           help="plot position, speed and acceleration against time (PNG, SVG or PDF)")
    add_decode_parser(ts, [clock])
    tr.set_defaults(func=cmd_trace)


def _add_sidebyside_parser(sub) -> None:
    s = sub.add_parser("sidebyside", help=COMMANDS["sidebyside"],
                       description="Decode the coil patterns of two traces and compare the step sequences.")
    s.add_argument("left")
    s.add_argument("right")
    s.add_argument("--left-pins", required=True, metavar="SPEC", help="coil pins of the left trace, e.g. 4..7")
    s.add_argument("--right-pins", required=True, metavar="SPEC", help="coil pins of the right trace, e.g. 1..4")
    s.add_argument("--left-clock", type=_positive_int, default=CLOCK_DEFAULT,
                   help="cycles per second of the left log (BASIC Stamp logs: 1_000_000)")
    s.add_argument("--right-clock", type=_positive_int, default=CLOCK_DEFAULT)
    s.add_argument("--steps", type=_positive_int, metavar="N", help="compare only the first N steps")
    s.set_defaults(func=cmd_sidebyside)


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser; with ``command``, only that command's options are added
    (building every command's costs a run's start-up a few milliseconds)."""
    p = _Parser(
        prog="spinemu",
        description="Compile, run, trace and translate Propeller 1 Spin programs; run BASIC Stamp 2 PBASIC.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"spinemu {__version__}")
    p.add_argument("--traceback", action="store_true",
                   help="on an internal error (exit status 70), print the Python traceback "
                        "(same as the environment variable SPINEMU_TRACEBACK=1)")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    for name, add in _ADDERS.items():
        if command is None or name == command:
            add(sub)
        else:       # (listed in the help; its options are added only when it is the command given)
            sub.add_parser(name, help=COMMANDS[name])
    return p


#: what adds each command's parser (with all its options)
_ADDERS = {"compile": _add_compile_parser, "run": _add_run_parser, "disasm": _add_disasm_parser,
           "translate": _add_translate_parser, "trace": _add_trace_parser, "sidebyside": _add_sidebyside_parser,
           "debug": _add_debug_parser, "profile": _add_profile_parser}


# ----------------------------------------------------------------------------- entry
def _run_command(argv: Sequence[str] | None, stdout: TextIOBase, stderr: TextIOBase, state: dict) -> int:
    """Parse ``argv`` and run its command; expected errors become statuses 1 and 2.

    ``state`` receives the command's name as soon as it is known (for the guard's message).
    """
    command = next((a for a in argv if not a.startswith("-")), None)     # (no global option takes a value)
    parser = build_parser(command)
    try:
        old = sys.stdout, sys.stderr
        sys.stdout, sys.stderr = stdout, stderr  # argparse prints help/usage there
        try:
            args = parser.parse_args(argv)
        finally:
            sys.stdout, sys.stderr = old
    except SystemExit as e:
        return int(e.code or 0)
    state["command"] = getattr(args, "command", None)
    if getattr(args, "trace_action", None):
        state["command"] += " " + args.trace_action
    if not getattr(args, "command", None):
        parser.print_help(stdout)
        return 2
    if args.command == "trace" and not getattr(args, "trace_action", None):
        stderr.write("spinemu trace: choose an action: compare, show, plot, convert, steps, decode\n")
        return 2
    out = _Out(stdout, stderr, quiet=getattr(args, "quiet", False))
    try:
        return args.func(args, out)
    except UsageError as e:
        stderr.write(f"spinemu {args.command}: {e.message}\n")
        return 2
    except SpinError as e:
        stderr.write(_render_error(e, getattr(args, "target", None)) + "\n")
        return e.exit_status
    except OSError as e:
        stderr.write(f"{getattr(e, 'filename', None) or 'spinemu'}: error: {e.strerror or e}\n")
        return 1
    except KeyboardInterrupt:
        stderr.write("interrupted\n")
        return 130


def _render_error(err: SpinError, target: str | None = None) -> str:
    """The error's diagnostics, with paths under the working directory shown relative to it.

    An image or run-time error that names no file (an image has no source lines) is about
    the command's ``target``.
    """
    from .diagnostics import EmulationError, ImageError

    if target and isinstance(err, (ImageError, EmulationError)):
        err.diagnostics = [d.replace(path=d.path or target) for d in err.diagnostics]
    return "\n".join(_render_error_diagnostic(d) for d in err.diagnostics)


def _short_path(path):
    """``path`` relative to the working directory when it lies under it."""
    if path and os.path.isabs(path):
        rel = os.path.relpath(path, os.getcwd())
        if not rel.startswith(".."):
            return rel
    return path


def _render_error_diagnostic(d) -> str:
    return d.replace(path=_short_path(d.path)).render()


# ----------------------------------------------------------------------------- last-resort guard
#: Exit status of an internal error (BSD sysexits EX_SOFTWARE): never a status bad input gives.
EXIT_INTERNAL = 70
TRACEBACK_ENV = "SPINEMU_TRACEBACK"
_REPORT_HINT = ("this is a bug in spinemu, not in your input; please report it with the command line and "
                "the input files")


def main(argv: Sequence[str] | None = None, stdout: TextIOBase | None = None,
         stderr: TextIOBase | None = None) -> int:
    """Run the command line ``argv`` and return the exit status.

    0: success; 1: an error in the input (rendered ``file:line:col: error: ...``);
    2: a usage error; 70: an internal error.  Any exception other than the
    expected ones is a bug: it is reported as ``spinemu COMMAND: internal error:
    ...`` with a hint to report it, the traceback only with ``--traceback`` (before
    the command) or the environment variable ``SPINEMU_TRACEBACK=1``.
    Tests call this in-process with their own streams.
    """
    stdout = stdout or sys.stdout
    stderr = stderr or sys.stderr
    argv = list(sys.argv[1:] if argv is None else argv)
    state: dict = {"command": None}
    try:
        return _run_command(argv, stdout, stderr, state)
    except Exception as e:  # noqa: BLE001 - the last resort: nothing else may escape as a traceback
        return _internal_error(e, argv, state.get("command"), stderr)


def _internal_error(err: BaseException, argv: Sequence[str], command: str | None, stderr: TextIOBase) -> int:
    """Report an unexpected exception (a bug) and return :data:`EXIT_INTERNAL`."""
    import traceback

    what = f"spinemu {command}" if command else "spinemu"
    cls = type(err)
    name = cls.__qualname__ if cls.__module__ == "builtins" else f"{cls.__module__}.{cls.__qualname__}"
    detail = f"{name}: {err}" if str(err) else name
    show = "--traceback" in argv or os.environ.get(TRACEBACK_ENV, "") not in ("", "0")
    try:
        if show:
            stderr.write("".join(traceback.format_exception(type(err), err, err.__traceback__)))
        stderr.write(f"{what}: internal error: {detail}\n{what}: {_REPORT_HINT}"
                     + ("" if show else f" (run with --traceback or {TRACEBACK_ENV}=1 to see where it failed)")
                     + "\n")
    except Exception:  # noqa: BLE001 - a broken stderr must not hide the status
        pass
    return EXIT_INTERNAL


def entry_point() -> None:
    """Console-script entry point.

    Ends the process with ``os._exit`` once the standard streams are flushed
    and the ``atexit`` handlers have run: tearing down the interpreter's
    objects one by one (a chip's tables of 64 K entries, compiled blocks)
    takes some 15 ms that nobody needs.  With another thread still running,
    or a stream that cannot be flushed, it exits the usual way.
    """
    code = main()
    threading = sys.modules.get("threading")
    if threading is not None and threading.active_count() > 1:
        sys.exit(code)
    try:
        sys.stdout.flush()
        sys.stderr.flush()
        import atexit
        atexit._run_exitfuncs()
    except Exception:  # noqa: BLE001 - e.g. a closed pipe: let the usual exit report it
        sys.exit(code)
    os._exit(code)
