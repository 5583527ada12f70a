"""The pytest plugin of spinemu (registered under the ``pytest11`` entry point).

It gives tests a fixture named ``spin``: ``spin.load(path, ...)`` is
:func:`spinemu.testing.load`, and every bench a test loads this way is shown
when the test fails: the cycle it reached, the last pin changes and where
each cog is (``file:line`` with the call stack), plus any runtime warnings::

    def test_the_motor_steps(spin):
        motor = spin.load("stepper.spin")
        assert motor.call("start", 0, 5)
"""
from __future__ import annotations

import os

import pytest

from .bench import SpinBench, load

__all__ = ["SpinFixture", "spin"]

_BENCHES = pytest.StashKey[list]()


class SpinFixture:
    """What the ``spin`` fixture gives a test: ``load`` (and the benches loaded so far)."""

    def __init__(self, benches: list):
        self.benches = benches

    def load(self, path, include_dirs=(), **options) -> SpinBench:
        """:func:`spinemu.testing.load`; the bench is reported if the test fails."""
        bench = load(path, include_dirs, **options)
        self.benches.append(bench)
        return bench


def pytest_addoption(parser):
    group = parser.getgroup("spinemu")
    group.addoption("--spin-changes", type=int, default=12, metavar="N",
                    help="pin changes to show for each Spin bench of a failing test (default 12)")


@pytest.fixture
def spin(request) -> SpinFixture:
    """Load Spin objects to test (``spin.load(path)``); a failing test shows their pins and cogs."""
    benches: list = []
    request.node.stash[_BENCHES] = benches
    return SpinFixture(benches)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.when != "call" or not report.failed:
        return
    changes = item.config.getoption("--spin-changes")
    for bench in item.stash.get(_BENCHES, []):
        try:
            text = bench.report(changes)
        except Exception as exc:  # the report must never hide the test's own failure
            text = f"(no report: {type(exc).__name__}: {exc})"
        report.sections.append((f"spinemu bench {os.path.basename(bench.path)}", text))
