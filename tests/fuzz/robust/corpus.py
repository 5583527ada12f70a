"""The repository's own inputs that the robustness fuzzers start from.

Spin sources (``spin_src/`` and ``tests/data/``), BASIC Stamp programs (the
``.bs2`` files in ``spin_src/bs2`` and the snippets of
``tests/data/pbasic/tokenizer_cases.txt``), images (``.binary``/``.eeprom``
under ``tests/data``) and pin-trace logs (``tests/data/article/*.trace``).
Everything is read once per process and kept in memory; the lists are sorted
so that a seed picks the same file on every machine.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

__all__ = ["ROOT", "spin_sources", "pbasic_programs", "images", "trace_logs"]


def _rel(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


@lru_cache(maxsize=None)
def spin_sources() -> tuple:
    """``(relative path, bytes)`` of every ``.spin`` file in the repository."""
    paths = sorted(p for base in ("spin_src", "tests/data") for p in (ROOT / base).rglob("*.spin"))
    return tuple((_rel(p), p.read_bytes()) for p in paths)


@lru_cache(maxsize=None)
def pbasic_programs() -> tuple:
    """``(name, text)`` of every BASIC Stamp program: the ``.bs2`` files and the tokenizer snippets."""
    out = [(_rel(p), p.read_text(encoding="utf-8", errors="replace"))
           for p in sorted((ROOT / "spin_src").rglob("*.bs2"))]
    cases = ROOT / "tests" / "data" / "pbasic" / "tokenizer_cases.txt"
    if cases.exists():
        name, body = None, []

        def flush():
            if name and body:
                text = "\n".join(body).strip("\n") + "\n"
                if not text.startswith("'"):
                    text = "' {$STAMP BS2}\n' {$PBASIC 2.5}\n" + text
                out.append((f"tokenizer_cases.txt:{name}", text))

        for line in cases.read_text(encoding="utf-8").splitlines():
            if line.startswith("== "):
                flush()
                name, body = line[3:].strip(), []
            elif line.startswith("#") and name is None:
                continue
            elif line.startswith("~~"):
                flush()
                name, body = None, []
            elif name is not None:
                body.append(line)
        flush()
    return tuple(out)


@lru_cache(maxsize=None)
def images() -> tuple:
    """``(relative path, bytes)`` of every ``.binary`` and ``.eeprom`` image in the repository."""
    paths = sorted(p for p in (ROOT / "tests" / "data").rglob("*")
                   if p.suffix.lower() in (".binary", ".eeprom") and p.is_file())
    return tuple((_rel(p), p.read_bytes()) for p in paths)


@lru_cache(maxsize=None)
def trace_logs() -> tuple:
    """``(relative path, text)`` of the reference pin-trace logs."""
    paths = sorted((ROOT / "tests" / "data" / "article").glob("*.trace"))
    return tuple((_rel(p), p.read_text(encoding="utf-8")) for p in paths)
