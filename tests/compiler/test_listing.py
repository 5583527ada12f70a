"""Listings are compared with golden files (no oracle exists for them).

Run ``python -m pytest --update-golden tests/compiler/test_listing.py`` to
rewrite the goldens after a deliberate change, and review the diff.  A
failing comparison writes ``NAME.actual.lst`` next to the golden file.
"""
import os

import pytest

from spinemu.compiler import compile_file

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GOLDEN = os.path.join(ROOT, "tests", "data", "compiler", "listings")

PROGRAMS = {
    "simple_stepper": "spin_src/simple_stepper.spin",
    "stepper_demo": "spin_src/stepper_demo.spin",
    "corrected_stepper_demo": "spin_src/corrected/stepper_demo.spin",
    "control": "tests/data/compiler/probes/control.spin",
    "builtins": "tests/data/compiler/probes/builtins.spin",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_listing_matches_golden_file(name, request):
    text = compile_file(os.path.join(ROOT, PROGRAMS[name])).listing(addresses=False)
    golden = os.path.join(GOLDEN, name + ".lst")
    actual = os.path.join(GOLDEN, name + ".actual.lst")
    if request.config.getoption("--update-golden", default=False):
        with open(golden, "w", encoding="utf-8") as fh:
            fh.write(text)
    with open(golden, encoding="utf-8") as fh:
        expected = fh.read()
    if text != expected:
        with open(actual, "w", encoding="utf-8") as fh:
            fh.write(text)
        pytest.fail(f"listing differs from {golden}; see {actual}")
    if os.path.exists(actual):
        os.remove(actual)


def test_listing_with_addresses_shows_hub_addresses_and_sizes():
    text = compile_file(os.path.join(ROOT, "spin_src/simple_stepper.spin")).listing()
    assert text.startswith("; object simple_stepper.spin at $0010 (size $0098)")
    assert "$0028  37 01" in text and "REG_RANGE" in text


def test_line_table_maps_hub_addresses_to_source_lines():
    prog = compile_file(os.path.join(ROOT, "spin_src/simple_stepper.spin"))
    path, line = prog.line_table(0x0028)            # first bytecode of main: dira[M4..EN]~~
    assert os.path.basename(path) == "simple_stepper.spin" and line == 29
    assert prog.line_table.get(0x0024)[1] == 70     # the DAT table
    assert prog.line_table(0x0005) is None          # the header belongs to no line
