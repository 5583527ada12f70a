#!/usr/bin/env python3
"""Library PASM drivers on spinemu and on spinsim: pin traces compared (run on demand).

Usage (needs OpenSpin, spinsim and the Parallax library under /opt/oracles)::

    python tests/benchmarks/pasm_drivers.py [--library DIR] [NAME ...]

Each case is a small top-level program written here that uses one driver
from the Parallax library *where it lies* (FullDuplexSerial, Parallax Serial
Terminal, PWM drivers, LED drivers (24-channel PWM, a WS2812 strip, 74HC595
shift registers), Servo32, frequency synthesisers in software and on the
counters; nothing of the library is copied).  The script compiles it with OpenSpin and with spinemu
(the images must be identical), runs it for a fixed number of cycles on
spinsim 0.99 ``-p`` (pins from its instruction log: a write shows at its
cycle + 4) and on spinemu, and compares the traces by the reference rules
(same sequence of pin states, timing error per change after the first
millisecond, tolerance 0.5 %).  For the serial drivers it also decodes the
TX pin (8N1) and prints the text.  spinsim has no counter modules: drivers
built on them (an AN001-style PWM, Servo32's counter clock, the frequency
synthesiser) are checked against the datasheet's formulas instead.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

from spinemu.analysis.compare import compare_traces  # noqa: E402
from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler import compile_file  # noqa: E402
from spinemu.trace import PinTrace  # noqa: E402

LIB = "/opt/oracles/propeller/libraries/community/p1/All"
OPENSPIN = "/opt/oracles/OpenSpin/build/openspin"
SPINSIM = "/opt/oracles/spinsim/build/spinsim"
CLOCK = 80_000_000
HEAD = "CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"

#: name -> (library folder holding the driver, program, cycles, TX pin and baud or None)
CASES = {
    "fullduplexserial": ("RCTime PASM/RCTime_PASM", HEAD + """OBJ
  ser : "FullDuplexSerial"
PUB main
  ser.start(31, 30, 0, 115200)
  ser.str(string("Hello, world!", 13, 10))
  ser.dec(-1234567)
  ser.tx(13)
  ser.hex($C0FFEE, 6)
  waitcnt(cnt + 400_000)
""", 2_400_000, (30, 115200)),
    "parallax_serial_terminal": ("Stack Length/Stack_Length_Demo_-_Archive__Date_2010.03.19__Time_11.05", HEAD + """OBJ
  pst : "Parallax Serial Terminal"
PUB main
  pst.StartRxTx(31, 30, 0, 115200)
  pst.Str(string("PST says hi", 13))
  pst.Dec(2024)
  pst.Char(32)
  pst.Bin(5, 4)
  waitcnt(cnt + 400_000)
""", 2_200_000, (30, 115200)),
    "pwm_32": ("PWM 32 DEMO", HEAD + """OBJ
  pwm : "PWM_32_v4"
PUB main
  pwm.Start
  pwm.Duty(16, 25, 1000)
  pwm.Duty(17, 60, 400)
  pwm.Servo(18, 1500)
  waitcnt(cnt + 3_000_000)
""", 4_000_000, None),    # software frequency synthesis: eight outputs from one cog, no counters (self-modifying PASM)
    "freqout_x8": ("Frequency Synthesis & PWM X8/FREQOUT_X8_Demo_-_Archive__Date_2011.07.01__Time_11.00_1",
                   HEAD + """OBJ
  freq : "FREQOUT_X8"
VAR
  long pins[8], hz[8]
PUB main
  longfill(@pins, -1, 8)
  pins[0] := 8
  hz[0] := 10_000
  pins[1] := 9
  hz[1] := 25_000
  pins[2] := 10
  hz[2] := 7_000
  freq.start(30, @pins, @hz)
  waitcnt(cnt + 1_500_000)
""", 1_600_000, None),
    # LED PWM: 24 channels, 8 bits each, by successive approximation (P0..P23)
    "pwm_24_led": ("24-channel LED driver with 8 bit per channel PWM/24-channel_PWM_v1.1", HEAD + """OBJ
  pwm : "24-channel PWM"
VAR
  byte level[24]
PUB main | i
  repeat i from 0 to 23
    level[i] := i * 11
  pwm.start(@level)
  waitcnt(cnt + 800_000)
""", 1_000_000, None),
    # addressable LEDs: a WS2812 strip's 800 kHz bit stream on P5
    "ws2812_led": ("WS2812 LED Driver modified by Doug Hilton for RadioShack part number 2760249 Tri-LED strip",
                   HEAD + """OBJ
  strip : "RadioShack_2760249"
PUB main
  strip.start(5, 8)
  strip.set(0, strip#RED)
  strip.set(3, strip#CYAN)
  strip.set(7, $12_34_56)
  waitcnt(cnt + 600_000)
""", 800_000, None),
    # LEDs on 74HC595 shift registers: software PWM per output, shifted out by a PASM cog
    "hc595_pwm_led": ("74HC595 Regular and MultiPWM Shift Register Driver", HEAD + """OBJ
  sr : "74HC595_MultiPWM"
PUB main
  sr.Start(0, 1, 2)
  sr.SetPWM(3, 1000, 25)
  sr.SetPWM(7, 400, 60)
  sr.High(12)
  waitcnt(cnt + 1_500_000)
""", 1_600_000, None),
}

#: drivers built on the counter modules, which spinsim does not have: checked against what
#: the datasheet's formulas and the driver's documentation say the pins must do
#: name -> (folder, program, cycles, {pin: (high cycles or None for a 50 % NCO output, period cycles)})
COUNTER_CASES = {
    # AN001-style PWM: an NCO whose PHS is set to -duty every period (80 kHz, 25 %)
    "pwmasm": ("Dedicated pwm generator", HEAD + """OBJ
  pwm : "pwmAsm"
PUB main
  pwm.Start(5)                  ' 80 kHz: the cog reads the period once, when it starts
  pwm.SetDuty(25)
  waitcnt(cnt + 400_000)
""", 600_000, {5: (250, 1000)}),
    # Servo32: counter A in LOGIC-always as its clock; pulses of the set widths every 20 ms
    "servo32": ("Servo32 V9", HEAD + """OBJ
  servo : "Servo32v9"
PUB main
  servo.Set(8, 1500)
  servo.Set(9, 1000)
  servo.Set(10, 2000)
  servo.Start
  waitcnt(cnt + 12_000_000)
""", 12_000_000, {8: (1500 * 80, None), 9: (1000 * 80, None), 10: (2000 * 80, None)}),
    # frequency synthesis: NCO outputs at 10 kHz and 123.456 kHz
    "synth": ("FrequencySynth v1.1", HEAD + """OBJ
  freq : "Synth"
PUB main
  freq.Synth("A", 3, 10_000)
  freq.Synth("B", 4, 123_456)
  waitcnt(cnt + 2_000_000)
""", 2_400_000, {3: (None, CLOCK / 10_000), 4: (None, CLOCK / 123_456)}),
}

LINE = re.compile(r"^Cog (\d):\s+(\d+) [0-9a-f]{3} ([0-9a-f]{8}) ([WXI ]) .*?(?:R=([0-9a-f]{8}))?$")


def compile_both(folder: str, program: str, tmp: str) -> bytes:
    path = os.path.join(tmp, "main.spin")
    with open(path, "w") as f:
        f.write(program)
    out = os.path.join(tmp, "main.binary")
    r = subprocess.run([OPENSPIN, "-q", "-L", folder, "-b", path, "-o", out], capture_output=True, text=True)
    if r.returncode:
        raise SystemExit(f"OpenSpin: {r.stdout}{r.stderr}")
    image = open(out, "rb").read()
    ours = compile_file(path, include_dirs=[folder]).binary
    if ours != image:
        raise SystemExit("spinemu's image differs from OpenSpin's")
    return image


def spinsim_trace(image_path: str, cycles: int) -> PinTrace:
    """Pin changes from spinsim's instruction log (streamed), up to ``cycles``."""
    proc = subprocess.Popen([SPINSIM, "-p", "-l", "/dev/stdout", f"-{cycles}", image_path],
                            stdout=subprocess.PIPE, text=True, errors="replace")
    drive: dict = {}
    trace = PinTrace(CLOCK)
    trace.record(0, 0, 0)
    for line in proc.stdout:
        m = LINE.match(line)
        if not m:
            continue
        cog, cyc, ins, flag, r = m.groups()
        cyc = int(cyc)
        if cyc > cycles:
            break
        if flag != " " or r is None:
            continue
        word = int(ins, 16)
        dest = (word >> 9) & 0x1FF
        if dest in (0x1F4, 0x1F6) and word & (1 << 23):
            d = drive.setdefault(cog, [0, 0])
            d[0 if dest == 0x1F6 else 1] = int(r, 16)
            dirs = outs = 0
            for dd, oo in drive.values():
                dirs |= dd
                outs |= dd & oo
            trace.record(cyc + 4, dirs, outs)
    proc.kill()
    proc.wait()
    return trace


def uart_text(trace: PinTrace, pin: int, baud: int) -> bytes:
    """The bytes an 8N1 receiver decodes from ``pin`` (idle high)."""
    bit = trace.clock_hz / baud
    changes = [(t, (o >> pin) & 1) for t, d, o in trace.changes if (d >> pin) & 1]

    def level(t):
        v = 1
        for tc, lv in changes:
            if tc > t:
                break
            v = lv
        return v
    out = bytearray()
    k = 0
    while k < len(changes):
        t, lv = changes[k]
        if lv == 0 and level(t - 1) == 1:
            value = 0
            for b in range(8):
                value |= level(t + (1.5 + b) * bit) << b
            out.append(value)
            stop = t + 9.5 * bit
            while k < len(changes) and changes[k][0] <= stop:
                k += 1
            continue
        k += 1
    return bytes(out)


def run_case(name: str, folder: str, program: str, cycles: int, uart) -> bool:
    with tempfile.TemporaryDirectory() as tmp:
        image = compile_both(folder, program, tmp)
        image_path = os.path.join(tmp, "main.binary")
        t0 = time.perf_counter()
        ref = spinsim_trace(image_path, cycles)
        t_ref = time.perf_counter() - t0
    t0 = time.perf_counter()
    result = Chip(image).run(max_cycles=cycles)
    t_ours = time.perf_counter() - t0
    cand = PinTrace(CLOCK, [c for c in result.trace.changes if c[0] <= cycles])
    ref = PinTrace(CLOCK, [c for c in ref.changes if c[0] <= cycles])     # a write at the limit shows 4 later
    cmp = compare_traces(ref, cand)
    rate = result.stats["pasm_instructions"] / t_ours if t_ours else 0
    print(f"{name}: {len(ref.changes)} pin changes on spinsim, {len(cand.changes)} on spinemu; "
          f"{'identical' if cmp.identical else 'DIFFERENT'} sequence, worst timing error "
          f"{cmp.worst_error:.4%}, largest offset {cmp.largest_offset} cycles; "
          f"spinemu {cycles / CLOCK / t_ours:.2f}x real time ({rate:,.0f} PASM instructions/s), "
          f"spinsim {cycles / CLOCK / t_ref:.2f}x")
    if uart is not None:
        pin, baud = uart
        print(f"  TX P{pin} at {baud} baud decodes as {uart_text(cand, pin, baud)!r} "
              f"(spinsim: {uart_text(ref, pin, baud)!r})")
    return cmp.identical and cmp.worst_error <= 0.005


def pulses(trace, pin: int) -> list:
    """``(rise cycle, high cycles)`` of every complete high pulse on ``pin`` while driven."""
    out, prev, up = [], 0, None
    for t, d, o in trace.changes:
        v = (o >> pin) & 1 if (d >> pin) & 1 else 0
        if v and not prev:
            up = t
        elif prev and not v and up is not None:
            out.append((up, t - up))
        prev = v
    return out


def run_counter_case(name: str, folder: str, program: str, cycles: int, expect: dict) -> bool:
    with tempfile.TemporaryDirectory() as tmp:
        image = compile_both(folder, program, tmp)
    result = Chip(image).run(max_cycles=cycles)
    ok = True
    for pin, (high, period) in expect.items():
        p = pulses(result.trace, pin)
        p = p[len(p) // 2:-1]                       # settled (the driver may start with defaults); the
        #                                             last may be cut when the program ends
        if len(p) < 2:
            print(f"{name} P{pin}: no pulses")
            ok = False
            continue
        highs = {w for _, w in p}
        periods = [b[0] - a[0] for a, b in zip(p, p[1:])]
        mean = sum(periods) / len(periods)
        good = (high is None or highs == {high}) and (period is None or abs(mean - period) / period < 1e-4)
        if high is None:            # an NCO: high half the period (within a clock)
            good &= max(highs) - min(highs) <= 1 and abs(2 * min(highs) - mean) <= 2
        print(f"{name} P{pin}: {len(p)} pulses, high {sorted(highs)[:3]} cycles, period {mean:,.2f} cycles "
              f"({CLOCK / mean:,.3f} Hz); expected high {high}, period {period}: {'ok' if good else 'WRONG'}")
        ok &= good
    return ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", default=LIB)
    ap.add_argument("names", nargs="*")
    a = ap.parse_args(argv)
    names = a.names or list(CASES) + list(COUNTER_CASES)
    ok = True
    for name in names:
        if name in COUNTER_CASES:
            folder, program, cycles, expect = COUNTER_CASES[name]
            ok &= run_counter_case(name, os.path.join(a.library, folder), program, cycles, expect)
            continue
        folder, program, cycles, uart = CASES[name]
        ok &= run_case(name, os.path.join(a.library, folder), program, cycles, uart)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
