"""The ``>>>`` examples in the PBASIC and stepper modules' docstrings run."""
import doctest
import importlib

import pytest

MODULES = ["spinemu.pbasic", "spinemu.pbasic.exprs", "spinemu.pbasic.serial",
           "spinemu.pbasic.timing",
           "spinemu.pbasic.words", "spinemu.pbasic.commands", "spinemu.analysis.stepper"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0
