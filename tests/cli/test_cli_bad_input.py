"""Command lines that used to end in a Python traceback (found by tests/fuzz/robust) now end in a message.

Each test is the smallest input of one cause: numbers were not checked where
they were parsed (nan, inf, huge), a pin range was built before it was
checked, options the library rejects with ValueError reached it unchecked,
and devices were read as if they were files.
"""
import io
import os
import time
from pathlib import Path

import pytest

from spinemu.analysis.view import parse_pins
from spinemu.cli import main
from spinemu.bench.inputs import parse_input_spec

ROOT = Path(__file__).parent.parent.parent
BLINK = ROOT / "spin_src" / "examples" / "blink.spin"
STOP = "PUB main\n  dira[0..3] := %1111\n  outa[0..3] := %1010\n"
LOG = "4 00000000 00000000\n1000 0000001e 00000002\n2000 0000001e 00000006\n3000 0000001e 0000000c\n"


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def log(tmp_path):
    path = tmp_path / "a.log"
    path.write_text(LOG)
    return path


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "1e300", "0", "-1"])
def test_seconds_must_be_a_finite_positive_number(value):
    code, _, err = run("run", BLINK, "--seconds", value)
    assert code == 2 and "argument --seconds: expected" in err


@pytest.mark.parametrize("value", ["1" * 5000, "\u0661\u0662", "0", "-5", "nan"])
def test_cycles_must_be_a_plain_whole_number_above_0(value):
    code, _, err = run("run", BLINK, "--cycles", value)
    assert code == 2 and "argument --cycles: expected" in err


@pytest.mark.parametrize("spec", ["P3=1@nan", "P3=1@inf", "P3=0@0,1@1e308", "P3=1@-1", "P3=2", "P3=x",
                                  "99999999999999999999=1", "=1", "P3"])
def test_stimulus_times_levels_and_pins_are_checked(tmp_path, spec):
    src = tmp_path / "stop.spin"
    src.write_text(STOP)
    code, _, err = run("run", src, "--input", spec, "--no-progress")
    assert code == 2 and err.startswith("spinemu run: --input: ")


def test_a_stimulus_time_of_nan_is_refused_where_it_is_parsed():
    with pytest.raises(ValueError, match="cannot read 'P5=0@0,1@nan'"):
        parse_input_spec("P5=0@0,1@nan")
    with pytest.raises(ValueError, match="cannot read 'P5=1@2e9'"):
        parse_input_spec("P5=1@2e9")        # later than any run: about 63 years


def test_a_billion_pin_range_is_refused_before_it_is_built(log):
    t0 = time.perf_counter()
    code, _, err = run("trace", "show", log, "--pins", "0..1000000000")
    assert code == 2 and "--pins: pins must be 0..31, got '0..1000000000'" in err
    assert time.perf_counter() - t0 < 5
    with pytest.raises(ValueError):
        parse_pins("5..99999999999999")


@pytest.mark.parametrize("spec", ["0", "1..3", "3,3,3,3", "1..5"])
def test_stepper_tools_need_four_different_coil_pins(log, spec):
    code, _, err = run("trace", "steps", log, "--pins", spec)
    assert code == 2 and "a stepper has four coil pins" in err
    code, _, err = run("sidebyside", log, log, "--left-pins", "1..4", "--right-pins", spec)
    assert code == 2 and "--right-pins: a stepper has four coil pins" in err


@pytest.mark.parametrize("name", ["b.xyz", "b", "b.log"])
def test_a_plot_to_a_file_type_matplotlib_cannot_write_is_a_usage_error(log, tmp_path, name):
    pytest.importorskip("matplotlib")
    code, _, err = run("trace", "plot", log, "-o", tmp_path / name)
    assert code == 2 and "cannot tell the image format" in err and ".png" in err
    assert not (tmp_path / name).exists()


def test_a_plot_to_a_png_still_works(log, tmp_path):
    pytest.importorskip("matplotlib")
    code, _, err = run("trace", "plot", log, "-o", tmp_path / "a.png")
    assert code == 0, err
    assert (tmp_path / "a.png").read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize("option,value", [("--width", "0"), ("--width", "1000000000"), ("--start", "-5"),
                                          ("--changes", "-1")])
def test_trace_show_numbers_are_checked(log, option, value):
    code, _, err = run("trace", "show", log, option, value)
    assert code == 2 and f"argument {option}: expected" in err


@pytest.mark.parametrize("option,value", [("--tolerance", "nan"), ("--tolerance", "-1"), ("--slack", "-1")])
def test_trace_compare_numbers_are_checked(log, option, value):
    code, _, err = run("trace", "compare", log, log, option, value)
    assert code == 2 and f"argument {option}: expected" in err


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_a_device_is_not_read_as_a_file():
    code, _, err = run("trace", "show", "/dev/zero")
    assert code == 1 and err.startswith("/dev/zero: error: cannot read file: not a regular file")


def test_a_folder_as_input_is_an_error_in_the_input(tmp_path):
    code, _, err = run("trace", "show", tmp_path)
    assert code == 1 and "error: cannot read file" in err


@pytest.mark.parametrize("window", [[], ["--start", "500", "--end", "100"], ["--start", "99999999999999999999"]])
def test_a_plot_of_an_empty_window_draws_without_a_python_warning(tmp_path, window):
    pytest.importorskip("matplotlib")
    import warnings

    one = tmp_path / "one.log"
    one.write_text("0 00000001 00000001\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        code, _, err = run("trace", "plot", one, "-o", tmp_path / "one.png", *window)
    assert code == 0, err
    assert not [w for w in caught if issubclass(w.category, UserWarning)]
