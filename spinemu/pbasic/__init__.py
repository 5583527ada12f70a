"""BASIC Stamp 2 (BS2) / PBASIC 2.5: compile and run programs, record pin traces.

The column's BS2 stepper demo (spin_src/bs2/stepper_bs2.bs2) runs here
beside its Spin translation, so that both pin traces can be compared
(see :mod:`spinemu.analysis.stepper`).  Semantics follow Parallax's BASIC
Stamp Syntax and Reference Manual v2.2 and the project's reference notes;
compile errors, variable allocation and DATA layout were checked against
Parallax's own tokenizer (docs/pbasic.md).

>>> prog = compile_source("' {$STAMP BS2}\\n' {$PBASIC 2.5}\\n"
...                       "x VAR Nib\\nx = 15 + 1\\nHIGH 4\\nPAUSE 2\\nLOW 4\\n")
>>> res = run_file(prog)
>>> res.reason, res.var("x"), res.trace.pin_levels(4)
('end', 0, [(0, 'z'), (0, '1'), (2000, '0')])

This package is self-contained: it shares only :mod:`spinemu.diagnostics`,
:mod:`spinemu.trace` and the bench (:mod:`spinemu.bench`: input levels,
parts on the pins, serial framing) with the rest of spinemu.
"""
from __future__ import annotations

from typing import Optional, Union

from .compiler import Program, compile_program
from .interp import RunResult, run_program
from .machine import CLOCK_HZ
from ..bench.inputs import parse_input_spec
from .syntax import parse_source, read_source
from .timing import Timing, get_timing

__all__ = ["compile_file", "compile_source", "run_file", "Program", "RunResult", "CLOCK_HZ",
           "Timing", "get_timing", "parse_input_spec"]


def compile_source(text: str, path: str = "<input>") -> Program:
    """Compile PBASIC source text.

    Raises:
        ParseError: syntax errors, missing ``{$STAMP BS2}``.
        CompileError: unknown names, bad structure, limits (file:line:col).
    """
    return compile_program(parse_source(text, path))


def compile_file(path) -> Program:
    """Compile a ``.bs2`` file (see :func:`compile_source`)."""
    return compile_source(read_source(str(path)), str(path))


def run_file(program: Union[str, "Program"], *, seconds: Optional[float] = None,
             cycles: Optional[int] = None, timing: Union[str, Timing] = "exact",
             inputs: Optional[dict] = None, debug_in: Union[str, bytes] = "",
             serial_in: Optional[dict] = None, float_level: int = 0,
             gosub_model: str = "ring", end_glitch: bool = False,
             max_instructions: Optional[int] = None,
             initial_ram: Optional[bytes] = None, parts=()) -> RunResult:
    """Compile (if given a path) and run a BS2 program.

    Args:
        program: a path to a ``.bs2`` file or a compiled :class:`Program`.
        seconds: simulated time budget (default: 10 s unless ``cycles`` is given).
        cycles: budget in BS2 trace cycles (1 cycle = 1 us).
        timing: ``"exact"`` (only stated durations take time) or ``"realistic"``
            (per-instruction costs, :mod:`spinemu.pbasic.timing`), or a Timing.
        inputs: levels applied to input pins, ``{pin: 0|1 | [(time_s, level), ...] |
            callable(time_s)}``.
        debug_in: what is typed into the Debug Terminal (DEBUGIN, SERIN 16).
        serial_in: ``{pin: bytes}`` a device sends when SERIN listens on that pin.
        float_level: what an undriven, unstimulated input reads ([OPEN] default 0).
        gosub_model: ``"ring"`` (default: a RETURN with nothing pending uses the
            ring slot, the program start if never written) or ``"restart"``.
        end_glitch: model the watchdog glitch (outputs released 18 ms every 2.3 s)
            after END, NAP and SLEEP.
        max_instructions: stop after this many instructions (default 5,000,000).
        initial_ram: for experiments, 32 bytes whose words 3-15 (the user RAM)
            replace the zeros a real BS2 starts with.
        parts: bench parts on the pins (a :class:`spinemu.bench.Bench` or a
            list of parts), the same as on the Propeller; they read and
            drive P0..P15 (1 cycle = 1 us).

    Returns:
        RunResult: trace, DEBUG text, SEROUT bytes, warnings, RAM, EEPROM...

    Raises:
        ParseError, CompileError: bad PBASIC.
    """
    prog = program if isinstance(program, Program) else compile_file(program)
    kw = {} if max_instructions is None else {"max_instructions": max_instructions}
    return run_program(prog, seconds=seconds, cycles=cycles, timing=timing, inputs=inputs,
                       debug_in=debug_in, serial_in=serial_in, float_level=float_level,
                       gosub_model=gosub_model, end_glitch=end_glitch,
                       initial_ram=initial_ram, parts=parts, **kw)
