"""The serial console on real runs: Spin programs that bit-bang serial, on both engines.

The programs are spinemu's own (``spin_src/examples/bitbang_serial.spin``:
WAITCNT-timed 8N1 in Spin, which keeps up with 19200 baud; the examples
``serial_hello`` and ``serial_echo``; ``tests/data/bench/serial_two_cogs``).
Their images are OpenSpin's; the text of ``serial_hello`` is what spinsim 0.99
printed on its serial port; what ``serial_echo`` answers follows from the
numbers it is sent.
"""
from __future__ import annotations

import os
import random

import pytest

from spinemu.bench import SerialConsole, UartFormat, decode_uart
from spinemu.bench.board import BenchInputs
from spinemu.chip import Chip
from spinemu.chip.inputs import PinStimulus
from spinemu.compiler import compile_file
from spinemu.trace import PinTrace
from spinemu.translate import run_translated

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCH = os.path.join(ROOT, "tests", "data", "bench")
EXAMPLES = os.path.join(ROOT, "spin_src", "examples")
ARTICLE = os.path.join(ROOT, "tests", "data", "article")
CLOCK = 80_000_000
#: where each program and OpenSpin's image of it are
PROGRAMS = {"serial_hello": (EXAMPLES, "examples"), "serial_echo": (EXAMPLES, "examples"),
            "serial_two_cogs": (BENCH, "bench"), "nco_serial": (BENCH, "bench")}


def src(name: str) -> str:
    return os.path.join(PROGRAMS[name][0], name + ".spin")


@pytest.fixture(scope="module")
def images():
    return {name: compile_file(src(name), include_dirs=[EXAMPLES]).binary for name in PROGRAMS}


def run(name, images, console, engine="bytecode", compat="spinsim", cycles=CLOCK, inputs=None):
    """Run a bench program with ``console`` attached; returns (result, chip or None)."""
    if engine == "python":
        return run_translated(src(name), include_dirs=[EXAMPLES], max_cycles=cycles, compat=compat, inputs=inputs,
                              parts=[console]), None
    chip = Chip(images[name], compat=compat, inputs=inputs)
    console.attach(chip)
    return chip.run(max_cycles=cycles), chip


@pytest.mark.parametrize("name", ["serial_hello", "serial_echo", "serial_two_cogs", "nco_serial"])
def test_spinemu_compiles_the_serial_programs_as_openspin_does(images, name):
    with open(os.path.join(ROOT, "tests", "data", PROGRAMS[name][1], name + ".binary"), "rb") as f:
        assert images[name] == f.read()


@pytest.mark.parametrize("engine", ["bytecode", "python"])
@pytest.mark.parametrize("compat", ["spinsim", "chip"])
def test_the_console_prints_exactly_what_the_reference_simulator_printed(images, engine, compat):
    with open(os.path.join(BENCH, "serial_hello.spinsim.out"), "rb") as f:
        expected = f.read()
    console = SerialConsole(baud=19200)
    result, chip = run("serial_hello", images, console, engine, compat)
    assert result.reason == "all cogs stopped"
    assert console.data == expected == b"Hello from Spin!\r7 14 21 \r"
    assert console.text == "Hello from Spin!\n7 14 21 \n"
    assert console.errors == []
    assert [c for c, _ in console.received] == sorted(c for c, _ in console.received)
    if chip is not None:
        assert chip.late_pin_events == 0


@pytest.mark.parametrize("engine", ["bytecode", "python"])
def test_numbers_sent_to_rx_come_back_as_the_program_computes_them(images, engine):
    rng = random.Random(3)
    numbers = [rng.randrange(-10**6, 10**6), rng.randrange(10**8)]
    console = SerialConsole(baud=9600)
    console.send(f"{numbers[0]}\r", at_seconds=0.02)
    console.send(f"{numbers[1]}\r".encode(), at_seconds=0.12)
    result, _ = run("serial_echo", images, console, engine, cycles=CLOCK // 2)
    assert result.reason == "all cogs stopped"
    assert console.text == "".join(f"Number? Twice {n} is {2 * n}\n" for n in numbers)
    assert [b for _, b in console.sent] == list(f"{numbers[0]}\r{numbers[1]}\r".encode())
    assert console.sent[0][0] == int(0.02 * CLOCK)


def test_a_byte_handler_can_answer_the_program_as_it_runs(images):
    console = SerialConsole(baud=9600)
    answers = iter([b"17\r", b"-5\r"])

    def on_byte(cycle, byte):
        if console.data.endswith(b"? "):
            console.send(next(answers))
            assert console.sent[-3][0] > cycle          # sent after what the chip has reached

    console.on_byte = on_byte
    result, _ = run("serial_echo", images, console)
    assert result.reason == "all cogs stopped"
    assert console.text == "Number? Twice 17 is 34\nNumber? Twice -5 is -10\n"


def test_the_console_decodes_one_pin_while_other_cogs_interleave(images):
    console = SerialConsole(tx=0, rx=1, baud=19200)
    result, chip = run("serial_two_cogs", images, console, compat="chip")
    assert console.data == b"1,2,3,4,5,6,7,8,9,10,11,12,\r"
    assert 5 in result.trace.driven_pins()
    assert chip.late_pin_events == 0


@pytest.mark.parametrize("engine", ["bytecode", "python"])
def test_the_console_reads_what_a_counter_sends_as_the_run_goes(images, engine):
    """TX is a counter's output (NCO, FRQA = 0: the program writes PHSA, OUTA stays 0) while another
    counter blinks P4: the console reads the line live, as a decoder of the finished trace does."""
    console = SerialConsole(baud=9600)
    seen = []
    console.on_byte = lambda cycle, byte: seen.append(console.now)      # how far the chip had got
    result, chip = run("nco_serial", images, console, engine, compat="chip", cycles=CLOCK // 10)
    assert result.reason == "all cogs stopped"
    assert console.data == b"Sent by a counter!\r" and console.errors == []
    offline = decode_uart(result.trace, 30, UartFormat(9600), hold_last=True)
    assert [f.value for f in offline] == list(console.data)
    assert seen[0] < result.end_cycle // 4              # handed over as it went, not at the end
    if chip is not None:
        assert chip.late_pin_events == 0


def test_bytes_sent_back_to_back_with_no_gap_are_lost_by_a_busy_spin_receiver(images):
    """The program prints after each number, so a second number sent at once arrives while it is not listening."""
    console = SerialConsole(baud=9600)
    console.send(b"21\r-3\r", at_seconds=0.02)
    console.send(b"5\r", at_seconds=0.2)
    run("serial_echo", images, console)
    assert console.text.startswith("Number? Twice 21 is 42\nNumber? ")
    assert "Twice 5 is 10" in console.text


def test_a_waiting_program_ends_in_a_deadlock_unless_keys_may_still_come(images):
    quiet = SerialConsole(baud=9600)
    result, _ = run("serial_echo", images, quiet, cycles=None)
    assert result.reason == "deadlock" and quiet.data == b"Number? "
    live = SerialConsole(baud=9600, live_input=True)
    result, _ = run("serial_echo", images, live, cycles=CLOCK // 10)
    assert result.reason == "cycle limit" and live.data == b"Number? "


def _reader_image(tmp_path, wait_first=False):
    """A program that copies P31 to P0 (and P7, which a stimulus drives, to P1) every 4,000 cycles for 40,000."""
    path = tmp_path / "reader.spin"
    path.write_text("CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"
                    "PUB main | t\n  dira[0..1] := %11\n"
                    + ("  waitpeq(0, |< 31, 0)\n  outa[2] := 1\n  dira[2] := 1\n" if wait_first else "")
                    + "  t := cnt\n  repeat 10\n    outa[0] := ina[31]\n    outa[1] := ina[7]\n"
                      "    waitcnt(t += 4_000)\n")
    return compile_file(str(path)).binary


def test_rx_idles_high_while_a_console_is_attached_over_a_pulldown_model(tmp_path):
    image = _reader_image(tmp_path)
    bare = Chip(image, compat="chip").run()                  # chip mode: undriven pins read 0
    assert bare.trace.state_at(bare.end_cycle - 1)[1] & 1 == 0
    chip = Chip(image, compat="chip", inputs=PinStimulus([(0, 1 << 7, 1 << 7)]))
    SerialConsole().attach(chip)
    result = chip.run()
    assert result.trace.state_at(result.end_cycle - 1)[1] & 3 == 3   # P31 high (console), P7 high (stimulus)
    assert isinstance(chip.inputs, BenchInputs)


def test_a_waitpeq_on_rx_wakes_exactly_at_the_start_bit_as_with_an_equal_stimulus(tmp_path):
    """The console's RX waveform tells the chip its next change exactly: same trace as a stimulus with that edge."""
    image = _reader_image(tmp_path, wait_first=True)
    console = SerialConsole(baud=9600)
    console.send(b"\x00", at_cycle=123_457)
    chip = Chip(image)
    console.attach(chip)
    with_console = chip.run()
    edges = [(123_457, 1 << 31, 0), (123_457 + (9 * CLOCK) // 9600, 1 << 31, 1 << 31)]
    with_stimulus = Chip(image, inputs=PinStimulus(edges, initial=0xFFFFFFFF)).run()
    assert with_console.trace.changes == with_stimulus.trace.changes
    woke = next(c for c, d, o in with_console.trace.changes if o & 4)
    assert 123_457 < woke < 123_457 + 3000


@pytest.mark.parametrize("name, cycles", [("corrected_stepper_demo", 400_000_000),
                                          ("as_printed_simple_stepper", 100_000_000)])
def test_a_pin_listener_changes_nothing_and_sees_the_trace_in_time_order(name, cycles):
    with open(os.path.join(ARTICLE, name + ".binary"), "rb") as f:
        image = f.read()
    plain = Chip(image).run(max_cycles=cycles)
    chip = Chip(image)
    seen, uptos = [], []

    def listener(changes, upto, present):
        assert all(c < upto for c, _, _ in changes)
        assert not seen or not changes or changes[0][0] >= seen[-1][0]
        assert not uptos or upto >= uptos[-1]
        seen.extend(changes)
        uptos.append(upto)

    chip.add_pin_listener(listener, interval_cycles=200_000)
    listened = chip.run(max_cycles=cycles)
    assert listened.trace.changes == plain.trace.changes
    assert (listened.end_cycle, listened.hub) == (plain.end_cycle, plain.hub)
    rebuilt = PinTrace(CLOCK, [(0, 0, 0)])
    for change in seen:
        rebuilt.record(*change)
    assert rebuilt.changes == plain.trace.changes
    assert chip.late_pin_events == 0
    assert len(uptos) > cycles // 2_000_000             # it was told as the run went, not only at the end


def test_pin_listeners_are_added_before_the_run_and_a_console_attaches_once(images):
    chip = Chip(images["serial_hello"])
    console = SerialConsole(baud=19200)
    console.attach(chip)
    with pytest.raises(RuntimeError):
        console.attach(Chip(images["serial_hello"]))
    chip.run(max_cycles=1000)
    with pytest.raises(RuntimeError):
        chip.add_pin_listener(lambda changes, upto, present: None)


@pytest.mark.parametrize("kw, word", [({"tx": 32}, "tx"), ({"rx": -1}, "rx"), ({"tx": 5, "rx": 5}, "different"),
                                      ({"baud": 0}, "baud"), ({"stop_bits": 3}, "stop")])
def test_bad_console_settings_are_refused(kw, word):
    with pytest.raises(ValueError, match=word):
        SerialConsole(**kw)


@pytest.mark.parametrize("kw", [{"at_seconds": -1}, {"at_seconds": float("nan")}, {"at_seconds": float("inf")},
                                {"at_cycle": -5}, {"at_cycle": 1.5}, {"at_seconds": 1, "at_cycle": 1}])
def test_bad_send_times_are_refused(kw):
    with pytest.raises(ValueError):
        SerialConsole().send(b"x", **kw)


class FakeEngine:
    """The bench's engine interface, nothing else: pins driven from a waveform of our own."""

    pin_count = 32

    def __init__(self, clock_hz):
        from spinemu.bench.history import TraceHistory
        self.clock_hz = clock_hz
        self.inputs = PinStimulus([], initial=0)
        self.drive_history = TraceHistory([])
        self.listeners = []

    def add_pin_listener(self, listener, interval_cycles=None):
        self.listeners.append(listener)


@pytest.mark.parametrize("inverted", [False, True])
def test_the_console_works_on_any_engine_with_the_bench_interface_inverted_or_not(inverted):
    from spinemu.bench.uart import UartFormat, UartWaveform

    engine = FakeEngine(1_000_000)
    console = SerialConsole(tx=4, rx=9, baud=10_000, inverted=inverted)
    console.send(b"ok", at_cycle=500)
    console.attach(engine)
    idle = 0 if inverted else 1
    assert (engine.inputs.levels(0) >> 9) & 1 == idle
    assert engine.inputs.next_change(0) == 500
    tx = UartWaveform(UartFormat(10_000, inverted=inverted), 1_000_000)
    tx.add(300, b"Hey\n")
    changes, t = [], 0
    while (t := tx.next_change(t)) is not None:
        changes.append((t, 1 << 4, tx.level(t) << 4))
    (listener,) = engine.listeners
    listener(changes[:10], changes[10][0], changes[10][0])
    listener(changes[10:], tx.end + 200, tx.end + 200)
    assert console.data == b"Hey\n" and console.text == "Hey\n"


def test_run_spin_attaches_the_parts_it_is_given():
    import spinemu

    console = spinemu.SerialConsole(baud=19200)
    result = spinemu.run_spin(src("serial_hello"), parts=[console])
    assert result.reason == "all cogs stopped" and console.text == "Hello from Spin!\n7 14 21 \n"


def test_the_python_example_of_the_console_docs_runs_as_shown(monkeypatch):
    import re

    with open(os.path.join(ROOT, "docs", "console.md")) as f:
        doc = f.read()
    block = re.search(r"```python\n(import spinemu\n.*?)```", doc, re.S).group(1)
    monkeypatch.chdir(ROOT)
    namespace: dict = {}
    exec(block, namespace)
    shown = re.search(r"console\.text +# '(.*?)'", block).group(1).encode().decode("unicode_escape")
    assert namespace["console"].text == shown == "Number? Twice 42 is 84\nNumber? "
