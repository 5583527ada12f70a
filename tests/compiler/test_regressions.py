"""Compiler bugs the random program generator found, each kept as a small program.

``tests/data/compiler/regressions/NAME.spin`` must compile to OpenSpin's image
(its SHA-256 in ``openspin.json``, recorded by make_regressions.py) and, where
the program has a DAT table ``folded`` .. ``folded_end``, its constant
expressions must fold to the values OpenSpin gave them.
"""
import hashlib
import json
import os

import pytest

from spinemu.compiler import compile_file

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REGRESSIONS = os.path.join(ROOT, "tests", "data", "compiler", "regressions")
with open(os.path.join(REGRESSIONS, "openspin.json")) as _fh:
    OPENSPIN = json.load(_fh)


@pytest.mark.parametrize("name", sorted(OPENSPIN))
def test_regression_program_compiles_to_openspins_image(name):
    prog = compile_file(os.path.join(REGRESSIONS, name))
    assert len(prog.binary) == OPENSPIN[name]["size"]
    assert hashlib.sha256(prog.binary).hexdigest() == OPENSPIN[name]["sha256"]


@pytest.mark.parametrize("name", sorted(n for n in OPENSPIN if "folded" in OPENSPIN[n]))
def test_regression_constants_fold_to_openspins_values(name):
    prog = compile_file(os.path.join(REGRESSIONS, name))
    lay = prog.layout
    start, end = lay.pbase + lay.dat["folded"][0], lay.pbase + lay.dat["folded_end"][0]
    got = [f"${int.from_bytes(prog.binary[a:a + 4], 'little'):08X}" for a in range(start, end, 4)]
    assert got == OPENSPIN[name]["folded"]


@pytest.mark.parametrize("expr,name,index", [
    ("$FFFF_FFFF ** $FFFF_FFFF", "mul_high_carry.spin", 0),
    ("round(-680.0)", "round_negative.spin", 0),
    ("$8000_0001 >< 33", "rev_counts.spin", 1),
    ("5 >< 256", "rev_counts.spin", 7),
    ("2 * NOT 0 + 1", "not_operand.spin", 0),
])
def test_the_quirks_the_docs_quote_fold_as_openspin_folded_them(expr, name, index):
    from spinemu.frontend import parse_source
    from spinemu.frontend.constants import evaluate
    value = evaluate(parse_source(f"CON\n  X = {expr}\n").cons[0].value, lambda n: None)
    assert f"${value.bits:08X}" == OPENSPIN[name]["folded"][index]
