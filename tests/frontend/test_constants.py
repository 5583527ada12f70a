"""Constant folding gives the values OpenSpin gives (tests/data/compiler/constants.json)."""
import json
import os

import pytest

from spinemu.frontend import parse_source
from spinemu.frontend.constants import Const, ConstError, KCONST_VALUES, encode_clock, evaluate

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "tests", "data", "compiler", "constants.json")) as fh:
    OPENSPIN = json.load(fh)


def fold(text):
    node = parse_source(f"CON\n  C0 = {text}\n").cons[0].value
    return evaluate(node, lambda n: None)


@pytest.mark.parametrize("text", sorted(OPENSPIN))
def test_constant_expression_folds_to_openspins_value(text):
    expected = OPENSPIN[text]
    if expected is None:
        with pytest.raises(ConstError):
            fold(text)
    else:
        assert fold(text).bits == expected


def test_floats_are_flagged_and_keep_ieee_single_bits():
    assert fold("1.5") == Const(0x3FC00000, True)
    assert KCONST_VALUES["pi"] == Const(0x40490FDB, True)


@pytest.mark.parametrize("mode,register", [
    ("rcfast", 0x00), ("rcslow", 0x01), ("xinput", 0x22), ("xtal1", 0x2A), ("xtal1 + pll16x", 0x6F),
    ("xtal2 + pll8x", 0x76), ("xtal3 + pll1x", 0x7B), ("xinput + pll4x", 0x65),
])
def test_clock_mode_register_values(mode, register):
    assert encode_clock(fold(mode).bits) == register


@pytest.mark.parametrize("mode", ["xtal1 + xtal2", "pll16x", "rcfast + pll2x", "xtal1 + pll1x + pll2x"])
def test_invalid_clock_modes_are_refused(mode):
    assert encode_clock(fold(mode).bits) is None
