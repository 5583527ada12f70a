"""The ``>>>`` examples in the docstrings of the debug-info, runtime-warning, record and tool modules run."""
import doctest
import importlib

import pytest

MODULES = ["spinemu.debuginfo", "spinemu.runtime_warnings", "spinemu.chip.checks", "spinemu.debugger.frames",
           "spinemu.debugger.expr", "spinemu.debugger.commands", "spinemu.records"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0
