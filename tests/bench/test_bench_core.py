"""The bench's machinery: reactive parts against a drive history that gets drives late, the input model a
bench puts on an engine, the wire trace, pin conflicts, and the engine interface on the chip."""
import random
import struct
from pathlib import Path

import pytest

import spinemu
from spinemu.bench import Bench, BenchPinError, Button, I2cEeprom, Led, Part, ReactivePart, Servo
from spinemu.bench.inputs import PinWaveforms, parse_input_spec, InputSpecError
from spinemu.compiler import compile_file

ROOT = Path(__file__).parent.parent.parent


class History:
    """A drive history whose changes arrive in any order (as several cogs record them)."""

    def __init__(self):
        self.arrived = []

    def record(self, cycle, d, o):
        self.arrived.append((cycle, d, o))

    def _sorted(self):
        return sorted(self.arrived, key=lambda x: x[0])

    def driven(self, cycle):
        state = (0, 0)
        for c, d, o in self._sorted():
            if c > cycle:
                break
            state = (d, o)
        return state

    def changes(self, start, end):
        return [x for x in self._sorted() if start <= x[0] < end]

    def recorded_since(self, mark):
        new = self.arrived[mark:]
        return (min(c for c, _, _ in new) if new else None), len(self.arrived)

    def recorded_end(self):
        return max((c for c, _, _ in self.arrived), default=-1) + 1


class Port:
    clock_hz, pin_count = 1_000_000, 32

    def __init__(self, history):
        self.history = history


class Follower(ReactivePart):
    """Outputs on P1 the inverse of P0 ten cycles later, and counts P0's rising edges."""

    kind = "follower"

    def driven_pins(self):
        return (1,)

    def watched_pins(self):
        return (0,)

    def reset(self):
        self.s = [0, 0]                                 # level, rising edges

    def initial_levels(self):
        return 2

    def on_drive(self, cycle, d, o):
        level = o & 1
        if level and not self.s[0]:
            self.s[1] += 1
        self.s[0] = level
        self.output(cycle + 10, 0 if level else 2)


def test_a_reactive_part_works_again_from_a_checkpoint_when_a_drive_comes_late():
    rng = random.Random(1)
    for trial in range(30):
        events = sorted({rng.randrange(0, 5000) for _ in range(80)})
        drives = [(c, 1, rng.randrange(2)) for c in events]
        hist, late = History(), Follower()
        late.connect(Port(hist))
        pending = list(drives)
        rng.shuffle(pending)
        # drives arrive at most 300 cycles out of order; questions come at cycles all drives before are in
        pending.sort(key=lambda x: x[0] + rng.randrange(300))
        for c, d, o in pending:
            hist.record(c, d, o)
            if rng.random() < 0.3:
                late.next_change(rng.randrange(5000))   # works ahead through what is recorded
            arrived = {x[0] for x in hist.arrived}
            safe = min((x[0] for x in drives if x[0] not in arrived), default=6000)
            if safe and rng.random() < 0.5:
                t = rng.randrange(safe)
                late.levels(t)
        late.finish(6000)
        fresh_hist, fresh = History(), Follower()
        for x in drives:
            fresh_hist.record(*x)
        fresh.connect(Port(fresh_hist))
        fresh.finish(6000)
        assert (late._times, late._values, late.s) == (fresh._times, fresh._values, fresh.s), trial


def test_a_late_drive_on_pins_a_part_does_not_watch_changes_nothing():
    hist, part = History(), Follower()
    part.connect(Port(hist))
    hist.record(100, 1, 1)
    part.next_change(0)
    saved = list(part._checkpoints)
    hist.record(50, 1 << 5, 0)                          # a late drive of P5 only
    assert part.levels(120) == 0
    assert list(part._checkpoints) == saved


def test_the_bench_input_model_puts_parts_over_the_engines_model():
    base = PinWaveforms({3: 1, 5: [(0, 0), (0.001, 1)]}, 1_000_000, base=0xFFFFFFFF)
    button = Button(pin=5, presses=[(0.002, 0.003)])
    bench = Bench([button])

    class Engine:
        clock_hz, pin_count = 1_000_000, 32
        inputs = base
        drive_history = History()

        def add_pin_listener(self, listener, interval_cycles=None):
            self.listener = listener

    engine = Engine()
    bench.attach(engine)
    m = engine.inputs
    assert m.levels(1500) >> 5 & 1 == 0                 # the button, not the stimulus, on P5
    assert m.levels(2500) >> 5 & 1 == 1 and m.levels(0) >> 3 & 1 == 1
    assert m.next_change(0) == 1000 or m.next_change(0) == 2000
    assert m.mask & (1 << 5) and m.mask & (1 << 3)


def test_two_parts_on_one_pin_are_refused():
    bench = Bench([Button(pin=4)])
    with pytest.raises(BenchPinError, match="P4 is driven by two parts: button P4 and EEPROM"):
        bench.add(I2cEeprom(scl=3, sda=4))
    bench.add(Led(pin=4))                               # watching a driven pin is fine


def test_a_part_on_a_pin_the_engine_lacks_is_refused_when_attaching():
    with pytest.raises(BenchPinError, match="P20 does not exist on this engine"):
        spinemu.run_bs2(ROOT / "spin_src" / "bs2" / "stepper_bs2.bs2", seconds=0.1, parts=[Led(pin=20)])


def test_a_part_serves_one_run():
    led = Led(pin=16)
    spinemu.run_spin(ROOT / "spin_src" / "examples" / "blink.spin", seconds=0.01, parts=[led])
    with pytest.raises(RuntimeError, match="attached to a run already"):
        spinemu.run_spin(ROOT / "spin_src" / "examples" / "blink.spin", seconds=0.01, parts=[led])


def test_the_wire_trace_has_the_levels_parts_put_on_the_pins():
    prog = compile_file(str(ROOT / "tests" / "data" / "bench" / "parts" / "eeprom_rw.spin"))
    bench = Bench([I2cEeprom()])
    result = spinemu.run_spin(prog.binary, parts=bench, seconds=0.05)
    wire = bench.wire_trace(result.trace)
    from spinemu.bench.i2c import decode_i2c
    chip_only = decode_i2c(result.trace, 28, 29).transfers
    on_wire = decode_i2c(wire, 28, 29).transfers
    assert not any(t.acked for t in chip_only)          # the chip never drives the ACKs
    assert on_wire[-1].text() == "0x50 R ACK: 07 0A 0D 10 13!"
    assert wire.changes[0] == (0, 3 << 28, 3 << 28)     # both lines pulled up from the start


def test_a_user_part_written_in_python_drives_a_pin_the_program_reads(tmp_path):
    class Clock(Part):
        """A 1 kHz square wave on P2."""
        kind = "clock"

        def driven_pins(self):
            return (2,)

        def levels(self, cycle):
            return (cycle // 40_000 % 2) << 2

        def next_change(self, cycle):
            return (cycle // 40_000 + 1) * 40_000

    src = tmp_path / "follow.spin"
    src.write_text("CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\nPUB main\n  dira[9]~~\n"
                   "  repeat\n    waitpeq(4, 4, 0)\n    outa[9]~~\n    waitpne(4, 4, 0)\n    outa[9]~\n")
    result = spinemu.run_spin(src, parts=[Clock()], seconds=0.01)
    follows = [c for c, _ in result.trace.pin_levels(9)[2:]]        # after 'z' and the first low
    assert len(follows) == 19 and all(0 < c - k * 40_000 < 2_000 for k, c in zip(range(1, 20), follows))


def test_listeners_get_a_call_every_interval_while_the_cogs_sleep_in_waitcnt():
    from spinemu.chip import Chip
    prog = compile_file(str(ROOT / "spin_src" / "examples" / "blink.spin"))
    calls = []
    chip = Chip(prog.binary)
    chip.add_pin_listener(lambda changes, upto, present: calls.append(upto), interval_cycles=800_000)
    chip.run(max_cycles=80_000_000)
    gaps = [b - a for a, b in zip(calls, calls[1:-1])]
    assert len(calls) >= 100 and max(gaps) <= 2 * 800_000      # blink sleeps 25 intervals at a time


def test_input_specs_are_read_the_same_for_every_engine():
    assert parse_input_spec("P3=1; 5=0@0,1@0.5") == {3: 1, 5: [(0.0, 0), (0.5, 1)]}
    for bad in ("P3", "3=2", "x=1", "3=1@-1", "3=1@soon"):
        with pytest.raises(InputSpecError, match="expected e.g."):
            parse_input_spec(bad)
    w = PinWaveforms({2: [(0.0, 1), (0.25, 0)], 7: lambda s: s > 0.5}, 1_000_000, base=0, pin_count=16, poll_cycles=1)
    assert w.levels(0) == 4 and w.levels(250_000) == 0 and w.levels(600_000) == 0x80
    assert w.pins == 0x84 and w.mask == 0x04
    with pytest.raises(ValueError, match="does not exist"):
        PinWaveforms({16: 1}, 1_000_000, pin_count=16)


def test_a_servo_part_on_the_bench_gets_the_same_pulses_on_both_spin_engines():
    src = ROOT / "tests" / "data" / "bench" / "parts" / "servo_sweep.spin"
    a, b = Servo(pin=17), Servo(pin=17)
    spinemu.run_spin(src, parts=[a], seconds=0.6)
    spinemu.run_translated(str(src), max_cycles=48_000_000, parts=[b])
    assert a.pulses == b.pulses and a.moves == b.moves


def test_the_boot_eeprom_holds_a_count_that_the_var_area_restores():
    prog = compile_file(str(ROOT / "tests" / "data" / "bench" / "parts" / "boot_count.spin"))
    vbase = struct.unpack_from("<H", prog.binary, 8)[0]
    eeprom = I2cEeprom(data=prog.eeprom())
    spinemu.run_spin(prog.eeprom(), parts=[eeprom], seconds=0.05)
    assert struct.unpack_from("<i", eeprom.memory, vbase)[0] == 1


PASM_RC = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long measured
PUB main
  cognew(@measure, @measured)
  repeat until measured
DAT
        org 0
measure or      outa, mask              ' charge the capacitor: drive P5 high for 1 ms
        or      dira, mask
        mov     t0, cnt
        add     t0, ms
        waitcnt t0, #0
        andn    dira, mask              ' let go...
        mov     t0, cnt
        waitpne mask, mask              ' ... and wait for the pin to fall
        mov     t1, cnt
        sub     t1, t0
        wrlong  t1, par
        cogid   t0
        cogstop t0
mask    long    |< 5
ms      long    80_000
t0      res     1
t1      res     1
"""


def test_a_pasm_cog_waiting_on_an_rc_part_wakes_when_the_voltage_crosses(tmp_path):
    import math
    from spinemu.bench import RcCircuit
    src = tmp_path / "pasm_rc.spin"
    src.write_text(PASM_RC)
    prog = compile_file(str(src))
    rc = RcCircuit(pin=5, r=10e3, c=0.1e-6)
    result = spinemu.run_spin(prog.binary, parts=[rc], seconds=0.01)
    vbase = struct.unpack_from("<H", prog.binary, 8)[0]
    measured = struct.unpack_from("<i", result.hub, vbase)[0]
    decay = 10e3 * 0.1e-6 * math.log(3.3 * 10e3 / 10.22e3 / 1.65) * 80e6
    (release, crossing), = rc.decays
    assert crossing - release == math.floor(decay) + 1
    assert 0 <= measured - (crossing - release) <= 16            # the MOV after the release, the wake-up
