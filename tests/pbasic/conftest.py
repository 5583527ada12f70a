"""Helpers for the PBASIC tests: run a snippet with the usual directives."""
import pytest

from spinemu.pbasic import compile_source, run_file

HEADER = "' {$STAMP BS2}\n' {$PBASIC 2.5}\n"


def bs2(body: str, path: str = "test.bs2"):
    """Compile a PBASIC 2.5 snippet (directives added)."""
    return compile_source(HEADER + body.strip("\n") + "\n", path)


def run(body: str, **kw):
    """Compile and run a snippet; default budget 1 s."""
    kw.setdefault("seconds", 1.0)
    return run_file(bs2(body), **kw)


@pytest.fixture
def pb():
    return run
