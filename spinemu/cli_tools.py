"""The command line's debugging tools: ``debug``, ``profile``, runtime warnings and compiler hints.

The second half of :mod:`spinemu.cli` (which registers these subcommands and
options and calls these functions): ``spinemu debug`` (spinemu.debugger),
``spinemu profile`` and ``run --profile`` (spinemu.profiler), the runtime
warnings of ``run`` (``--no-warn``, ``-Werror``; spinemu.runtime_warnings) and
the compiler's hints printed by every command that compiles.  It uses
:mod:`spinemu.cli`'s helpers, imported when a command runs.
"""
from __future__ import annotations

from .diagnostics import UsageError

__all__ = ["cmd_debug", "cmd_profile"]


def _cli():
    from . import cli
    return cli


# ----------------------------------------------------------------------------- profile
def _attach_profiler(chip, prog):
    from .profiler import Profiler

    profiler = Profiler(chip, prog.debug_info() if prog is not None else None)
    chip.probe = profiler
    return profiler


def cmd_profile(args, out) -> int:
    """``spinemu profile PROG``: cycles per line and method per cog (spinemu.profiler)."""
    cli = _cli()
    from .chip import Chip
    from .image import FALLBACK_CLOCK_HZ, ImageHeader

    if cli._kind(args.target) == "pbasic":
        raise UsageError("the profiler runs Propeller programs (.spin, .binary, .eeprom)")
    image, source_map, prog = cli._load_target(args.target, args.include, args.define)
    _print_hints(out, prog)
    clock = ImageHeader.parse(image).clkfreq or FALLBACK_CLOCK_HZ
    chip = Chip(image, compat=cli._compat(args), inputs=cli._spin_inputs(args, clock), source_map=source_map,
                debug_info=prog.debug_info() if prog is not None else None, warn=False)
    profiler = _attach_profiler(chip, prog)
    result = chip.run(max_cycles=cli._run_limit(args, clock))
    profile = profiler.finish(args.target)
    written = []
    for path, text in ((args.json, profile.to_json), (args.csv, profile.to_csv), (args.listing, profile.listing)):
        if path:
            cli._write_atomic(path, text(), False)
            written.append(path)
    if not out.quiet:
        out.console.print(f"{args.target}: {result.reason} at cycle {result.end_cycle:,}")
        out.console.print(profile.table(args.top))
        if written:
            out.console.print("wrote " + ", ".join(written))
    return 0


def _add_profile_parser(sub) -> None:
    cli = _cli()
    p = sub.add_parser("profile", help=cli.COMMANDS["profile"],
                       description="Run a program under the cycle profiler: every cycle of every cog is "
                                   "charged to the Spin line (and method) of the bytecode that spent it, as "
                                   "work or as waiting (WAITCNT, WAITPEQ/WAITPNE, WAITVID). Each cog's "
                                   "figures add up to its running time. Compiled blocks and fast-forward are "
                                   "off while profiling, so it runs slower than 'run'.")
    p.add_argument("target", metavar="PROG", help=".spin source (lines and methods) or .binary/.eeprom image")
    lim = p.add_mutually_exclusive_group()
    lim.add_argument("--cycles", type=cli._positive_int, metavar="N", help="stop after N clock cycles")
    lim.add_argument("--seconds", type=cli._positive_float, metavar="S", help="stop after S simulated seconds")
    p.add_argument("--top", type=cli._positive_int, default=15, metavar="N", help="rows per table (default 15)")
    p.add_argument("--json", metavar="FILE", help="write every figure as JSON")
    p.add_argument("--csv", metavar="FILE", help="write one row per cog and line as CSV")
    p.add_argument("--listing", metavar="FILE", help="write the sources annotated with each line's cycles")
    cli._obj_search_option(p)
    cli._define_option(p)
    p.add_argument("--compat", choices=["spinsim", "chip"], help="timing mode, as for run")
    p.add_argument("--inputs", choices=["pulldown", "pullup"], help="what undriven pins read, as for run")
    p.add_argument("--input", dest="stimulus", metavar="SPEC", help="drive input pins, as for run")
    p.add_argument("-q", "--quiet", action="store_true", help="print nothing (write the files only)")
    p.set_defaults(func=cmd_profile)


# ----------------------------------------------------------------------------- compiler hints
def _print_hints(out, prog) -> None:
    """The compiler's hints (spinemu.compiler.hints) on stderr, file:line:col with a caret."""
    cli = _cli()
    for d in (prog.warnings if prog is not None else ()):
        out.warn(cli._render_error_diagnostic(d))


# ----------------------------------------------------------------------------- runtime warnings
def _runtime_warning_log(args, out, prog):
    """The WarningLog for a Spin run: printed to stderr as they happen; None with --no-warn."""
    cli = _cli()
    if args.no_warn:
        return None
    from .runtime_warnings import WarningLog

    def show(w):
        out.warn(cli._render_error_diagnostic(w.diagnostic()))

    if prog is not None:
        info = prog.debug_info()
        return WarningLog(info.position, info.source_line, werror=args.werror == "error", sink=show)
    return WarningLog(werror=args.werror == "error", sink=show)


def _runtime_warning_rows(warnings) -> list:
    """Summary rows: one per warning place, ``file:line: kind (N times)``."""
    cli = _cli()
    rows = []
    for i, w in enumerate(warnings):
        where = cli._short_path(w.path) + f":{w.line}" if w.path else f"cog {w.cog}" + (
            f" at ${w.addr:04X}" if w.addr >= 0 else "")
        times = f" ({w.count} times)" if w.count > 1 else ""
        rows.append(("warnings" if i == 0 else "", f"{where}: {w.kind}{times}"))
    return rows


def _warning_options(p) -> None:
    p.add_argument("--no-warn", action="store_true",
                   help="no runtime warnings (waitcnt for a passed count, a stack past its cognew array, "
                        "cognew with no free cog, pin conflicts between cogs, writes outside hub RAM or "
                        "into the code, locals read before they are assigned; docs/warnings.md)")
    p.add_argument("-W", dest="werror", choices=["error"], metavar="error",
                   help="-Werror: a runtime warning stops the run as an error (exit status 1)")



# ----------------------------------------------------------------------------- debug
def cmd_debug(args, out) -> int:
    """``spinemu debug PROG``: the debugger's command loop (spinemu.debugger.commands)."""
    cli = _cli()
    from .debugger.commands import CommandLoop
    from .debugger.session import Debugger

    if cli._kind(args.program) != "spin":
        raise UsageError(f"'{args.program}' is not a .spin source (the debugger needs its names and lines)")
    dbg = Debugger(args.program, list(args.include or ()), compat=cli._compat(args), inputs=args.inputs,
                   warn=not args.no_warn, defines=list(args.define or ()))
    _print_hints(out, dbg.program)
    loop = CommandLoop(dbg, out.console, echo=args.commands is not None)
    loop.say(f"{args.program}: {len(dbg.program.binary)} bytes; cog 0 at {dbg.cog(0).place()} "
             f"(help lists the commands)")
    if args.commands is not None:
        text = cli._read_bytes(args.commands).decode("utf-8", "replace")
        loop.run_lines(text.splitlines())
        return 0
    import signal

    old = signal.signal(signal.SIGINT, lambda *_: dbg.interrupt())
    try:
        loop.interactive(lambda prompt: out.console.input(prompt))
    finally:
        signal.signal(signal.SIGINT, old)
    return 0


def _add_debug_parser(sub) -> None:
    cli = _cli()
    d = sub.add_parser("debug", help=cli.COMMANDS["debug"],
                       description="Run a Spin program under the debugger: step a cog by Spin line or "
                                   "bytecode, a PASM cog by instruction; stop on a line, a DAT label or "
                                   "a PASM cog address, a pin change, a write to a variable (by Spin or "
                                   "PASM) or a condition; see every cog's call stack with parameters, "
                                   "locals and results, a PASM cog's registers by DAT label, and VAR/DAT "
                                   "by name. Type 'help' at the prompt.")
    d.add_argument("program", metavar="PROG.spin")
    d.add_argument("--commands", metavar="FILE",
                   help="read the commands from FILE (one per line, '#' comments) instead of the terminal")
    cli._obj_search_option(d)
    cli._define_option(d)
    d.add_argument("--compat", choices=["spinsim", "chip"], help="timing mode, as for run")
    d.add_argument("--inputs", choices=["pulldown", "pullup"], help="what undriven pins read, as for run")
    d.add_argument("--no-warn", action="store_true", help="no runtime warnings")
    d.set_defaults(func=cmd_debug)


