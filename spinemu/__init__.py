"""spinemu: run, compile, trace and translate Parallax Propeller 1 Spin programs, and run BASIC Stamp 2 PBASIC.

The public API (see docs/api.md):

>>> import spinemu
>>> result = spinemu.run_spin("spin_src/simple_stepper.spin", seconds=0.05)   # doctest: +SKIP
>>> result.trace.edge_counts()                                                # doctest: +SKIP

* :func:`compile_spin` - Spin source to a :class:`~spinemu.compiler.CompiledProgram`
  (``.binary``, ``.eeprom()``, ``.listing()``), byte-identical with OpenSpin.
* :class:`Chip` - the Propeller 1 emulator; :func:`run_spin` compiles (if needed) and runs.
* :func:`run_bs2` - run a BASIC Stamp 2 PBASIC program.
* :class:`PinTrace`, :func:`read_log` - pin traces and their files.
* :func:`compare_traces`, :func:`decode_steps`, :func:`decode_step_dir`,
  :func:`compare_stepper_traces`, :func:`render_timeline`, :func:`plot_trace`,
  :func:`plot_motion`, :func:`disassemble_image` - analysis.
* :class:`StepperMotor`, :func:`motor_from_trace` - the bench's stepper motor: shaft
  position, speed and acceleration from coil patterns or step/dir pulses.
* :func:`translate_spin`, :func:`run_translated` - Spin to readable Python, and running it
  on the same chip model.
* :class:`SerialConsole` - a serial terminal on a run's TX/RX pins (``parts=[console]``).
* :class:`Bench`, :func:`load_bench` - parts on the pins (LEDs, buttons, an EEPROM, servos,
  LCDs...) for any engine (``parts=bench``); the parts are in :mod:`spinemu.bench`.
* :class:`SpinError` - every error about bad input.

Everything but the error and trace types is imported on first use, so
``import spinemu`` stays fast.
"""
from __future__ import annotations

import importlib

from .diagnostics import SpinError
from .trace import PinTrace, read_log

__version__ = "0.1.0"

__all__ = [
    "SpinError", "PinTrace", "read_log", "compile_spin", "Chip", "run_spin", "run_bs2",
    "compare_traces", "decode_steps", "decode_step_dir", "compare_stepper_traces", "render_timeline",
    "plot_trace", "plot_motion", "StepperMotor", "motor_from_trace",
    "disassemble_image", "translate_spin", "run_translated", "SerialConsole", "Bench", "load_bench", "__version__",
]

_LAZY = {
    "Chip": ("spinemu.chip", "Chip"),
    "compare_traces": ("spinemu.analysis.compare", "compare_traces"),
    "decode_steps": ("spinemu.analysis.stepper", "decode_steps"),
    "decode_step_dir": ("spinemu.analysis.stepper", "decode_step_dir"),
    "plot_motion": ("spinemu.analysis.plot", "plot_motion"),
    "StepperMotor": ("spinemu.bench.stepper_motor", "StepperMotor"),
    "motor_from_trace": ("spinemu.bench.stepper_motor", "motor_from_trace"),
    "compare_stepper_traces": ("spinemu.analysis.stepper", "compare_stepper_traces"),
    "render_timeline": ("spinemu.analysis.view", "render_timeline"),
    "plot_trace": ("spinemu.analysis.plot", "plot_trace"),
    "disassemble_image": ("spinemu.analysis.disasm", "disassemble_image"),
    "translate_spin": ("spinemu.translate", "translate_file"),
    "run_translated": ("spinemu.translate", "run_translated"),
    "SerialConsole": ("spinemu.bench", "SerialConsole"),
    "Bench": ("spinemu.bench", "Bench"),
    "load_bench": ("spinemu.bench.benchfile", "load_bench"),
}


def __getattr__(name: str):
    if name in _LAZY:
        module, attr = _LAZY[name]
        value = getattr(importlib.import_module(module), attr)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'spinemu' has no attribute {name!r}")


def compile_spin(path, include_dirs=()):
    """Compile a Spin program (and its OBJ children) to a Propeller image.

    Args:
        path: the top object's ``.spin`` file.
        include_dirs: folders searched for OBJ files after the source's own folder.

    Returns:
        A ``CompiledProgram``: ``.binary`` (bytes), ``.eeprom()``, ``.listing()``,
        ``.line_table``, ``.layout``.

    Raises:
        SpinError: with file, line and column, for any error in the source.
    """
    from .compiler import compile_file

    return compile_file(str(path), include_dirs=list(include_dirs))


def run_spin(target, *, cycles: int | None = None, seconds: float | None = None,
             compat: str = "spinsim", inputs=None, include_dirs=(), parts=()):
    """Compile (if ``target`` is a ``.spin`` file) and run a Propeller program.

    Args:
        target: a ``.spin`` source, a ``.binary``/``.eeprom`` file, or image bytes (a
            32 KB EEPROM image is loaded whole, as the boot loader does).
        cycles, seconds: where to stop (default: when every cog has stopped).
        compat: ``"spinsim"`` (default: the reference simulator, cycle for cycle) or ``"chip"``
            (the silicon's cog load time, lock numbering and hub windows; see docs/timing.md).
        inputs: what undriven pins read (``"pulldown"``, ``"pullup"`` or a stimulus).
        include_dirs: OBJ search folders for a ``.spin`` target.
        parts: a :class:`spinemu.bench.Bench`, or a list of bench parts, attached to the
            chip before the run, e.g. a :class:`SerialConsole` (``console.text`` then holds
            what the program printed) or ``[Led(pin=16), Servo(pin=17)]``.

    Returns:
        The chip's ``RunResult``: ``.trace``, ``.hub``, ``.end_cycle``, ``.reason``,
        ``.cog_events``, ``.warnings``.
    """
    from .chip import Chip
    from .image import FALLBACK_CLOCK_HZ, ImageHeader, load_image

    labels = None
    if isinstance(target, (bytes, bytearray)):
        data, name = bytes(target), "<image>"
    elif str(target).lower().endswith(".spin"):
        prog = compile_spin(target, include_dirs)
        data, name, labels = prog.binary, str(target), prog.dat_labels()
    else:
        with open(target, "rb") as f:
            data, name = f.read(), str(target)
    image = load_image(data, name)
    if len(data) == 32768:
        image = data                # a whole EEPROM boots whole (data stored past the program included)
    limit = cycles
    if seconds is not None:
        limit = int(round(seconds * (ImageHeader.parse(image).clkfreq or FALLBACK_CLOCK_HZ)))
    chip = Chip(image, compat=compat, inputs=inputs, labels=labels)
    if parts:
        from .bench import Bench
        (parts if isinstance(parts, Bench) else Bench(parts)).attach(chip)
    return chip.run(max_cycles=limit)


def run_bs2(path, *, seconds: float = 10.0, timing: str = "exact", **options):
    """Run a BASIC Stamp 2 PBASIC program (see :func:`spinemu.pbasic.run_file`).

    Options include ``inputs`` (levels on the pins), ``parts`` (a bench, as for
    :func:`run_spin`), ``debug_in``.

    Returns:
        A PBASIC ``RunResult``: ``.trace`` (1 cycle = 1 us), ``.debug_output``,
        ``.warnings``, ``.ram``, ``.eeprom``.
    """
    from .pbasic import run_file

    return run_file(str(path), seconds=seconds, timing=timing, **options)
