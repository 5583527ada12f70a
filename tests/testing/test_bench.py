"""spinemu.testing: calls, aborts, timeouts, variables, pins and the pytest plugin's failure report."""
from pathlib import Path

import pytest

import spinemu.testing
from spinemu.testing import CallTimeout, HarnessError, SpinAbort

CALC = Path(__file__).parent.parent / "data" / "testing" / "calc.spin"
STEPPER = Path(__file__).parent.parent.parent / "spin_src" / "corrected" / "stepper.spin"
SERIAL = Path(__file__).parent.parent.parent / "spin_src" / "examples" / "bitbang_serial.spin"

pytest_plugins = ["pytester"]


@pytest.fixture
def calc():
    return spinemu.testing.load(CALC)


def test_a_call_returns_the_result_as_a_signed_long(calc):
    assert calc.call("plus", 2, 3) == 5
    assert calc.call("negate", 7) == -7
    assert calc.call("plus", 0x7FFFFFFF, 1) == -0x80000000
    assert calc.call("plus", -1, -1) == -2


def test_method_names_are_case_insensitive_and_listed(calc):
    assert calc.call("PLUS", 1, 1) == 2
    assert calc.methods[:3] == ["plus", "negate", "check"]


def test_true_and_false_are_spins_minus_one_and_zero(calc):
    assert calc.call("negate", True) == 1 and calc.call("negate", False) == 0


def test_a_string_argument_is_passed_by_address(calc):
    assert calc.call("length", "propeller") == 9
    assert calc.call("length", b"") == 0


def test_an_abort_raises_with_its_value_and_the_bench_goes_on(calc):
    with pytest.raises(SpinAbort) as e:
        calc.call("check", -5)
    assert e.value.value == -5 and e.value.method == "check"
    assert calc.call("check", 4) == 8


def test_an_abort_from_a_nested_call_reaches_the_caller(calc):
    with pytest.raises(SpinAbort) as e:
        calc.call("deep", 0)
    assert e.value.value == 99
    assert calc.call("deep", 3) == 3


def test_a_call_that_never_returns_names_the_line_it_is_stuck_on(calc):
    with pytest.raises(CallTimeout) as e:
        calc.call("hang", limit=100_000)
    err = e.value
    assert err.path.endswith("calc.spin") and err.line in (35, 36)
    assert "hang()" in err.message and "no return within 100,000 cycles" in err.message
    assert "calc.spin:3" in err.message
    with pytest.raises(HarnessError, match="still inside"):
        calc.call("plus", 1, 2)


def test_a_call_takes_the_cycles_the_method_takes(calc):
    took = []
    for cycles in (100_000, 200_000):
        t0 = calc.now
        calc.call("delay", cycles)
        took.append(calc.now - t0)
    assert took[1] - took[0] == 100_000                   # the wait, to the cycle
    assert took[0] - 100_000 < 10_000                     # plus the harness's own call and dispatch


def test_run_advances_time_by_exactly_what_was_asked(calc):
    t0 = calc.now
    calc.run(ms=2)
    calc.run(cycles=1000)
    calc.run(seconds=0.001)
    assert calc.now - t0 == 160_000 + 1000 + 80_000


def test_wrong_arguments_and_unknown_names_are_explained(calc):
    with pytest.raises(HarnessError, match="plus takes 2 arguments, not 1"):
        calc.call("plus", 1)
    with pytest.raises(HarnessError, match="no PUB method 'mul'"):
        calc.call("mul", 1, 2)
    with pytest.raises(HarnessError, match="no VAR or DAT variable 'nosuch'"):
        calc.var("nosuch")
    with pytest.raises(HarnessError, match="index outside 0..3"):
        calc.var("history", 4)
    with pytest.raises(HarnessError, match="exactly one"):
        calc.run(ms=1, cycles=5)


def test_var_reads_var_and_dat_by_name_and_index(calc):
    calc.call("plus", 4, 5)
    assert calc.var("total") == 9 and calc.var("history", 0) == 4
    assert calc.var("table", 2) == 30 and calc.var("greeting", 1) == ord("e")
    calc.set_var("level", 0x1FFFF)
    calc.set_var("code", -1)
    assert calc.var("level") == 0xFFFF and calc.var("code") == 0xFF     # words and bytes unsigned
    calc.set_var("history", -3, 2)
    assert calc.var("history", 2) == -3


def test_set_var_is_seen_at_once_by_a_cog_spinning_on_it(calc):
    calc.call("watcher")
    calc.run(ms=5)                                   # the watcher's loop gets parked (fast-forward)
    assert calc.var("done") == 0
    calc.set_var("flag", 41)
    calc.run(ms=1)
    assert calc.var("done") == 42


def test_pins_and_trace_show_what_the_object_drives(calc):
    calc.call("setPin", 6)
    assert calc.pin(6) == 1 and calc.outputs[0] >> 6 & 1
    assert calc.trace.changes[-1][2] >> 6 & 1
    calc.run(ms=1)
    assert calc.pin(6) == 1                          # cog 0 keeps driving it between calls


def test_where_tells_what_each_cog_is_doing(calc):
    calc.call("watcher")
    calc.run(ms=1)
    lines = calc.where()
    assert lines[0] == "cog 0: idle (the harness, between calls)"
    assert lines[1].startswith("cog 1 (") and "watch() at" in lines[1] and "calc.spin:4" in lines[1]


def test_without_a_console_the_bench_says_how_to_attach_one(calc):
    with pytest.raises(HarnessError, match="console=True"):
        calc.console


def test_the_serial_console_reads_what_the_object_sends_and_sends_it_input():
    from spinemu.bench import SerialConsole

    port = spinemu.testing.load(SERIAL, console=SerialConsole(tx=30, rx=31, baud=9600))
    port.call("start", 31, 30, 9600)
    port.call("str", "Hi ")
    port.call("dec", -42)
    assert port.console.text == "Hi -42"
    port.console.send(b"123\r", at_cycle=port.now + 20_000)     # once getdec waits for it
    assert port.call("getdec") == 123


def test_a_missing_file_or_a_broken_object_is_a_spin_error(tmp_path):
    with pytest.raises(spinemu.SpinError, match="no such file"):
        spinemu.testing.load(tmp_path / "nope.spin")
    bad = tmp_path / "bad.spin"
    bad.write_text("PUB go\n  x := 1\n")
    with pytest.raises(spinemu.SpinError) as e:
        spinemu.testing.load(bad)
    assert e.value.path == str(bad) and e.value.line == 2


def test_a_failing_test_shows_the_last_pin_changes_and_where_each_cog_is(pytester):
    pytester.makepyfile(f"""
        def test_motor(spin):
            m = spin.load({str(STEPPER)!r})
            m.call("start", 0, 5)
            m.call("setMode", 0b0011)
            m.run(ms=20)
            assert m.call("getMode") == 99
    """)
    result = pytester.runpytest()
    result.assert_outcomes(failed=1)
    out = result.stdout.str()
    assert "spinemu bench stepper.spin" in out and "last pin changes:" in out
    assert "P0=1" in out                                           # the enable pin went high
    assert "cog 0: idle (the harness, between calls)" in out
    assert "cog 1 (running): runStepper(m1=1) at" in out and "stepper.spin:14" in out


def test_a_passing_test_shows_nothing(pytester):
    pytester.makepyfile(f"""
        def test_motor(spin):
            m = spin.load({str(STEPPER)!r})
            assert m.call("start", 0, 5) == -1
    """)
    result = pytester.runpytest()
    result.assert_outcomes(passed=1)
    assert "spinemu bench" not in result.stdout.str()
