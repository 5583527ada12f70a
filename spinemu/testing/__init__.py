"""Unit tests for Spin objects, without hardware: drive an object from Python as its parent would.

>>> import spinemu.testing
>>> bench = spinemu.testing.load("spin_src/corrected/stepper.spin")       # doctest: +SKIP
>>> bench.call("start", 0, 5)                                            # doctest: +SKIP
-1

:func:`load` gives a :class:`SpinBench` (``call``, ``run``, ``var``/``set_var``,
``pins``, ``trace``, ``where``, ``console``); :mod:`spinemu.testing.plugin` is the pytest
plugin with the ``spin`` fixture.  See docs/testing.md.
"""
from .bench import CallTimeout, HarnessError, SpinAbort, SpinBench, load

__all__ = ["load", "SpinBench", "SpinAbort", "CallTimeout", "HarnessError"]
