"""Bench files: the parts around a program, in TOML (``spinemu run PROGRAM --bench board.toml``).

A bench file is a list of ``[[part]]`` tables.  Each has a ``type`` -- a
built-in part (:data:`spinemu.bench.PART_KINDS`: ``led``, ``button``, ``rc``,
``pot``, ``servo``, ``lcd``, ``serial-lcd``, ``eeprom``, ``stepper``,
``console``, ``i2c``, ``spi``, ``pwm``) or a user's part class written
``"file.py:Class"`` (a Python file next to the bench file) or
``"package.module:Class"`` -- and the keyword arguments of that class::

    # the demo board: a button, an LED, a servo and a 2 x 16 LCD
    [[part]]
    type = "button"
    pin = 0
    presses = [[0.10, 0.15], [0.30, 0.35]]
    bounce = 0.002

    [[part]]
    type = "led"
    pin = 16

    [[part]]
    type = "servo"
    pin = 17

    [[part]]
    type = "lcd"
    rs = 8
    e = 9
    data = [4, 5, 6, 7]

Mistakes are reported with the file, line and column (a caret under the
value): a TOML syntax error, an unknown part type or parameter, a missing
parameter, a pin the engine does not have, two parts that drive one pin, a
value the part refuses.  Relative file names in a part's parameters
(``data`` of an EEPROM) are relative to the bench file.
"""
from __future__ import annotations

import importlib
import importlib.util
import os
import re
import sys
from typing import Optional

from ..diagnostics import SpinError
from .board import Bench, BenchPinError

__all__ = ["load_bench", "read_bench"]


def _toml():
    """The TOML reader (imported when a bench file is read: most runs have none)."""
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    return tomllib

#: parameters whose string values are file names, relative to the bench file
PATH_PARAMETERS = ("data",)

# the messages, in one place
M_SYNTAX = "this is not a valid bench file: {0}"
M_TOP = "a bench file holds [[part]] tables only; '{0}' is not one"
M_NO_TYPE = "this part has no 'type' (e.g. type = \"led\")"
M_UNKNOWN_TYPE = "there is no part of type '{0}'; the built-in parts are {1} (or 'file.py:Class' for your own)"
M_BAD_TYPE = "'type' must be a text such as \"led\""
M_UNKNOWN_PARAM = "a {0} has no parameter '{1}'; its parameters are {2}"
M_MISSING = "a {0} needs '{1}'"
M_PIN = "{0}: pin {1!r} does not exist on {2} (pins are 0..{3})"
M_REFUSED = "{0}: {1}"
M_USER_CLASS = "cannot load the part class '{0}': {1}"
M_NOT_A_PART = "'{0}' is not a part (a subclass of spinemu.bench.Part)"
M_FILE = "{0}: cannot read '{1}': {2}"
M_DEFAULT_PIN = "{0}: P{1} does not exist on {2} (pins are 0..{3}): give this part its pins"


class _Lines:
    """Where each ``[[part]]`` table and each of its keys is in the file's text."""

    _HEADER = re.compile(r"^\s*\[\[\s*part\s*\]\]")
    _TABLE = re.compile(r"^\s*\[")
    _KEY = re.compile(r"""^\s*("[^"]*"|'[^']*'|[A-Za-z0-9_-]+)\s*=\s*""")

    def __init__(self, text: str):
        self.lines = text.splitlines()
        self.parts: list[tuple[int, dict]] = []     # (header line, {key: (line, column, length)})
        self.top: dict = {}
        current = None
        depth = 0
        for n, line in enumerate(self.lines, 1):
            if depth:
                depth += line.count("[") - line.count("]")
                continue
            if self._HEADER.match(line):
                current = {}
                self.parts.append((n, current))
                continue
            if self._TABLE.match(line):
                name = line.strip().strip("[]").strip()
                self.top.setdefault(name, (n, line.index("[") + 1, len(line.strip())))
                current = None
                continue
            m = self._KEY.match(line)
            if m:
                key = m.group(1).strip("\"'")
                value = line[m.end():].split("#")[0].rstrip()
                where = (n, m.end() + 1, max(1, len(value)))
                if current is not None:
                    current.setdefault(key, where)
                else:
                    self.top.setdefault(key, (n, m.start(1) + 1, len(m.group(1))))
                depth = value.count("[") - value.count("]")

    def text(self, line: int) -> Optional[str]:
        return self.lines[line - 1] if 0 < line <= len(self.lines) else None


def _error(path: str, lines: _Lines, message: str, where) -> SpinError:
    line, col, length = where if where else (None, None, 1)
    return SpinError(message, path=path, line=line, column=col,
                     source_line=lines.text(line) if line else None, length=length)


def read_bench(text: str, path: str = "<bench>", *, pin_count: int = 32, engine: str = "the Propeller") -> Bench:
    """Build a :class:`~spinemu.bench.Bench` from the text of a bench file.

    Args:
        text: the TOML text.
        path: the file's name (for messages and relative file names).
        pin_count: the engine's pins (32, or 16 on the BASIC Stamp).
        engine: the engine's name, for messages.

    Raises:
        SpinError: with file, line and column, for every mistake listed in the module docstring.
    """
    from . import PART_KINDS

    lines = _Lines(text)
    try:
        doc = _toml().loads(text)
    except _toml().TOMLDecodeError as e:
        msg = str(e)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        where = (int(m.group(1)), int(m.group(2)), 1) if m else None
        raise _error(path, lines, M_SYNTAX.format(re.sub(r"\s*\(at line.*\)$", "", msg)), where) from None
    for key in doc:
        if key != "part":
            raise _error(path, lines, M_TOP.format(key), lines.top.get(key))
    tables = doc.get("part", [])
    if not isinstance(tables, list):
        raise _error(path, lines, M_TOP.format("part"), lines.top.get("part"))
    bench = Bench(name=os.path.basename(path))
    folder = os.path.dirname(os.path.abspath(path)) if path != "<bench>" else os.getcwd()
    for k, table in enumerate(tables):
        header, keys = lines.parts[k] if k < len(lines.parts) else (None, {})
        head = (header, 1, len(lines.text(header) or "x")) if header else None
        cls = _part_class(table, path, lines, keys, head, folder, PART_KINDS)
        kwargs = {key: value for key, value in table.items() if key != "type"}
        _check_parameters(cls, kwargs, path, lines, keys, head)
        for key, value in kwargs.items():
            if key in cls.pin_parameters and value is not None:
                for pin in value if isinstance(value, list) else [value]:
                    if isinstance(pin, bool) or not isinstance(pin, int) or not 0 <= pin < pin_count:
                        raise _error(path, lines, M_PIN.format(cls.kind, pin, engine, pin_count - 1), keys.get(key, head))
            elif key in PATH_PARAMETERS and isinstance(value, str):
                kwargs[key] = os.path.join(folder, value)
        try:
            part = cls(**kwargs)
        except OSError as e:
            key = next((k for k in PATH_PARAMETERS if k in table), None)
            raise _error(path, lines, M_FILE.format(cls.kind, table.get(key, e.filename), e.strerror or e),
                         keys.get(key, head)) from None
        except (ValueError, TypeError) as e:
            where = next((keys[key] for key in keys if key != "type" and re.search(rf"\b{re.escape(key)}\b", str(e))),
                         head)
            raise _error(path, lines, M_REFUSED.format(cls.kind, e), where) from None
        part.origin = (path, keys, head)
        for pin in sorted(set(part.driven_pins()) | set(part.watched_pins())):
            if not 0 <= pin < pin_count:                # a default pin (an EEPROM's P28/P29)
                raise _error(path, lines, M_DEFAULT_PIN.format(part.name, pin, engine, pin_count - 1), head)
        try:
            bench.add(part)
        except BenchPinError as e:
            where = next((keys[key] for key in cls.pin_parameters if key in keys and _has_pin(table[key], e.pin)),
                         head)
            raise _error(path, lines, str(e), where) from None
    return bench


def load_bench(path: str, *, pin_count: int = 32, engine: str = "the Propeller") -> Bench:
    """:func:`read_bench` on a file.

    Raises:
        SpinError: for a file that cannot be read, or any mistake in it.
    """
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise SpinError(f"cannot read the bench file: {e.strerror or e}", path=path) from None
    except UnicodeDecodeError:
        raise SpinError("the bench file is not UTF-8 text", path=path) from None
    return read_bench(text, path, pin_count=pin_count, engine=engine)


def _has_pin(value, pin) -> bool:
    return pin in value if isinstance(value, list) else value == pin


def _part_class(table: dict, path: str, lines: _Lines, keys: dict, head, folder: str, kinds: dict):
    from .part import Part

    kind = table.get("type")
    if kind is None:
        raise _error(path, lines, M_NO_TYPE, head)
    if not isinstance(kind, str):
        raise _error(path, lines, M_BAD_TYPE, keys.get("type", head))
    if ":" not in kind:
        if kind not in kinds:
            raise _error(path, lines, M_UNKNOWN_TYPE.format(kind, ", ".join(sorted(kinds))), keys.get("type", head))
        return kinds[kind]
    where, _, name = kind.rpartition(":")
    try:
        if where.endswith(".py"):
            file = where if os.path.isabs(where) else os.path.join(folder, where)
            spec = importlib.util.spec_from_file_location(f"spinemu_bench_user_{abs(hash(file))}", file)
            if spec is None or spec.loader is None:
                raise ImportError(f"no such file: {where}")
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
        else:
            module = importlib.import_module(where)
        cls = getattr(module, name)
    except FileNotFoundError:
        raise _error(path, lines, M_USER_CLASS.format(kind, f"no such file {where!r}"), keys.get("type", head)) from None
    except Exception as e:          # the user's module may raise anything while it loads
        raise _error(path, lines, M_USER_CLASS.format(kind, f"{type(e).__name__}: {e}"), keys.get("type", head)) from None
    if not (isinstance(cls, type) and issubclass(cls, Part)):
        raise _error(path, lines, M_NOT_A_PART.format(kind), keys.get("type", head))
    return cls


def _check_parameters(cls, kwargs: dict, path: str, lines: _Lines, keys: dict, head) -> None:
    import inspect                  # (here: it is slow to import, and only bench files need it)

    sig = inspect.signature(cls.__init__)
    params = [p for p in list(sig.parameters.values())[1:] if p.kind in (p.KEYWORD_ONLY, p.POSITIONAL_OR_KEYWORD)]
    names = [p.name for p in params]
    if not any(p.kind == p.VAR_KEYWORD for p in sig.parameters.values()):
        for key in kwargs:
            if key not in names:
                raise _error(path, lines, M_UNKNOWN_PARAM.format(cls.kind, key, ", ".join(names)), keys.get(key, head))
    for p in params:
        if p.default is p.empty and p.name not in kwargs:
            raise _error(path, lines, M_MISSING.format(cls.kind, p.name), head)
