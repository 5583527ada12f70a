"""Spin to readable Python that runs on spinemu's chip model (issue 5).

>>> from spinemu import translate
>>> files = translate.translate_file("spin_src/stepper_demo.spin", "/tmp/stepper_py")   # doctest: +SKIP
>>> result = translate.run_translated("spin_src/simple_stepper.spin", max_cycles=200_000)
>>> [change[1:] for change in result.trace.changes[:3]]
[(0, 0), (31, 0), (31, 1)]

One module per Spin object, one class per module, one method per PUB/PRI
(program.py, stmts.py, exprs.py); VAR and DAT live in hub RAM where the
compiled image puts them (spin.py); the generated code runs on the chip
model through a small engine hook (runtime.py), with each statement charged
the cycles of its bytecode (costs.py, weave.py).  docs/translate.md explains
the choices.
"""
from __future__ import annotations

import os
import shutil
import tempfile

from .code import docstring_text
from .program import TranslateError, translate_program
from .weave import load_package

__all__ = ["translate_file", "side_by_side", "run_translated", "run_package", "load_package", "TranslateError"]

_IMAGE_NAME = "spin_image.binary"


def _check_compiles(modules) -> None:
    """Every generated module must be valid Python; anything else is a bug in the translator."""
    for m in modules:
        try:
            compile(m.text, m.module + ".py", "exec")
        except (SyntaxError, ValueError) as e:
            raise RuntimeError(f"the Python generated for {m.spin_path} does not compile: {e}") from e


def _write(modules, compiled, out_dir: str) -> list[str]:
    _check_compiles(modules)
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for m in modules:
        path = os.path.join(out_dir, m.module + ".py")
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(m.text)
        paths.append(path)
    top = modules[0]
    with open(os.path.join(out_dir, "__init__.py"), "w", encoding="utf-8") as fh:
        fh.write(f'"""{docstring_text(os.path.basename(top.spin_path))} translated to Python by spinemu.translate."""\n'
                 f"from .{top.module} import {top.class_name}\n\n"
                 f'TOP = {top.class_name}\nIMAGE = "{_IMAGE_NAME}"\n')
    with open(os.path.join(out_dir, _IMAGE_NAME), "wb") as fh:
        fh.write(compiled.binary)
    return paths


def translate_file(src_path, out_dir, include_dirs=()) -> list[str]:
    """Translate a Spin program to Python modules in ``out_dir``.

    Writes one module per Spin object (the top object first), an
    ``__init__.py`` that makes ``out_dir`` a package (``TOP`` is the top
    class) and the compiled image the modules' addresses refer to.

    Args:
        src_path: the top object's .spin file.
        out_dir: the folder to write to (created if missing).
        include_dirs: more folders to look for OBJ files in.

    Returns:
        The paths of the written modules, the top object's first.

    Raises:
        ParseError, CompileError: the program does not compile.
        TranslateError: a construct the translator does not handle (named, with its line).
    """
    modules, compiled = translate_program(src_path, include_dirs)
    return _write(modules, compiled, os.fspath(out_dir))


def run_package(package, max_cycles=None, compat: str = "spinsim", inputs=None, parts=()):
    """Run a package written by :func:`translate_file` (imported, e.g. with :func:`load_package`) on a chip.

    ``parts``: bench parts attached to the chip before the run (e.g. a
    :class:`spinemu.bench.SerialConsole`).

    Returns:
        a :class:`spinemu.chip.RunResult`, as the bytecode engine gives.
    """
    from .runtime import run_class
    image_path = os.path.join(os.path.dirname(package.__file__), package.IMAGE)
    with open(image_path, "rb") as fh:
        image = fh.read()
    return run_class(package.TOP, image, max_cycles=max_cycles, compat=compat, inputs=inputs, parts=parts)


def run_translated(src_path, include_dirs=(), max_cycles=None, compat: str = "spinsim", inputs=None,
                   parts=()):
    """Translate ``src_path`` and run the Python on the chip model.

    Args:
        src_path: the top object's .spin file.
        include_dirs: more folders to look for OBJ files in.
        max_cycles: stop at this cycle (``None``: until every cog stopped).
        compat, inputs: as for :class:`spinemu.chip.Chip`.
        parts: a :class:`spinemu.bench.Bench` or a list of bench parts, attached
            to the chip before the run, e.g. a :class:`spinemu.bench.SerialConsole`.

    Returns:
        a :class:`spinemu.chip.RunResult` (trace, hub, end cycle, ...).
    """
    from .weave import load_package
    modules, compiled = translate_program(src_path, include_dirs)
    tmp = tempfile.mkdtemp(prefix="spinemu-py-")
    try:
        _write(modules, compiled, tmp)
        package = load_package(tmp)
        return run_package(package, max_cycles=max_cycles, compat=compat, inputs=inputs, parts=parts)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def side_by_side(src_path, include_dirs=()):
    """A rich renderable: each Spin object's source next to its Python, line by line.

    Raises:
        as :func:`translate_file`.
    """
    from .view import side_by_side_view
    modules, _compiled = translate_program(src_path, include_dirs)
    return side_by_side_view(modules)
