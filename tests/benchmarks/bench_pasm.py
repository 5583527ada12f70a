"""Speed of PASM cogs (run on demand: ``python tests/benchmarks/bench_pasm.py``).

Prints PASM instructions per second and real-time factors (simulated time
over wall time, and over CPU time: the machine may be shared) for:

* a CPU-bound loop (ALU instructions and ``djnz``: nothing shared, so the
  cog runs ahead of the scheduler, a compiled block at a time);
* a loop that toggles a pin every pass (a shared access every 6 instructions);
* two PASM cogs passing a counter back and forth through hub RAM;
* when the Parallax library is at ``--library``: a FullDuplexSerial hello
  world (the Spin main prints one line and ends; the driver's cog then polls
  RX and its buffer until the end: an idle loop, skipped) and the PWM_32
  driver driving three pins (a busy loop that changes the pins every pass:
  compiled blocks), each end to end (``spinemu run PROG --seconds S`` in a
  new process: start-up, compiling, running) and the run alone (``Chip.run``
  in this process).  Without the library, a PASM serial transmitter and a
  software PWM loop written here stand in for them.

Targets: the serial hello world at least 10x real time end to end, the busy
PWM driver at least 1x.  ``--no-speedups`` runs everything with the idle-loop
skipper and the compiled blocks off (every PASM instruction through its
handler), for comparison (the run alone only).
"""
from __future__ import annotations

import argparse
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
try:                    # an installed spinemu (measure a regular ``pip install .``), else this worktree's
    import spinemu  # noqa: F401
except ImportError:
    sys.path.insert(0, ROOT)

from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler import compile_file, compile_source  # noqa: E402

LIB = "/opt/oracles/propeller/libraries/community/p1/All"
HEAD = "CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"

CPU_LOOP = HEAD + """PUB main
  cognew(@entry, 0)
DAT
        org 0
entry   mov     x, #100
inner   add     y, x
        xor     y, #7 wc
        rcl     z, #1
        sub     w, y
        djnz    x, #inner
        jmp     #entry
x long 0
y long 0
z long 0
w long 0
"""
PIN_LOOP = HEAD + """PUB main
  cognew(@entry, 0)
DAT
        org 0
entry   mov     dira, #1
loop    add     y, #3
        ror     y, #1 wc
        muxc    outa, #1
        sub     x, y
        and     x, y wz
        jmp     #loop
x long 0
y long 0
"""
PING_PONG = HEAD + """VAR
  long ball
PUB main
  cognew(@ping, @ball)
  cognew(@pong, @ball)
DAT
        org 0
ping    rdlong  v, par
        test    v, #1 wz
  if_nz jmp     #ping
        add     v, #1
        wrlong  v, par
        jmp     #ping
v       long 0
        org 0
pong    rdlong  u, par
        test    u, #1 wz
  if_z  jmp     #pong
        add     u, #1
        wrlong  u, par
        jmp     #pong
u       long 0
"""
SERIAL = HEAD + """OBJ
  ser : "FullDuplexSerial"
PUB main
  ser.start(31, 30, 0, 115200)
  ser.str(string("Hello, world!", 13, 10))
  waitcnt(cnt + clkfreq / 100)
"""
PWM = HEAD + """OBJ
  pwm : "PWM_32_v4"
PUB main
  pwm.Start
  pwm.Duty(16, 25, 1000)
  pwm.Duty(17, 60, 400)
  pwm.Servo(18, 1500)
  repeat
    waitcnt(cnt + clkfreq)
"""
# without the library: a PASM transmitter that polls a hub mailbox (8N1, 115200 baud at 80 MHz) ...
OWN_SERIAL = HEAD + """VAR
  long box
PUB main | p
  cognew(@tx, @box)
  p := string("Hello, world!", 13, 10)
  repeat strsize(p)
    repeat while box
    box := byte[p++] | $100
  repeat while box
  waitcnt(cnt + clkfreq / 100)
DAT
        org 0
tx      or      outa, pin
        or      dira, pin
wait    rdlong  data, par wz
  if_z  jmp     #wait
        shl     data, #1
        mov     bits, #10
        mov     t, cnt
        add     t, #16
bit     shr     data, #1 wc
        muxc    outa, pin
        add     t, period
        waitcnt t, #0
        djnz    bits, #bit
        wrlong  zero, par
        jmp     #wait
pin     long    1 << 30
period  long    80_000_000 / 115_200
zero    long    0
data    long    0
bits    long    0
t       long    0
"""
# ... and a software PWM loop that recomputes three pins every pass
OWN_PWM = HEAD + """PUB main
  cognew(@pwm, 0)
  repeat
    waitcnt(cnt + clkfreq)
DAT
        org 0
pwm     mov     dira, #%111
loop    add     ph0, fr0
        cmp     ph0, duty0 wc
        muxc    out, #%001
        add     ph1, fr1
        cmp     ph1, duty1 wc
        muxc    out, #%010
        add     ph2, fr2
        cmp     ph2, duty2 wc
        muxc    out, #%100
        mov     outa, out
        jmp     #loop
ph0     long    0
ph1     long    0
ph2     long    0
fr0     long    1 << 24
fr1     long    3 << 22
fr2     long    5 << 21
duty0   long    $4000_0000
duty1   long    $8000_0000
duty2   long    $C000_0000
out     long    0
"""


def _factors(sim: float, wall: float, cpu: float) -> str:
    return f"{sim / wall:.2f}x real time ({sim / cpu:.2f}x by CPU)"


def measure(name: str, image: bytes, cycles, repeat: int, speedups: bool = True):
    """Run ``image`` in this process (best CPU time of ``repeat``); print and return the result."""
    best = None
    for _ in range(repeat):
        chip = Chip(image, fast_forward=speedups, compile_blocks=speedups)
        t0, c0 = time.perf_counter(), time.process_time()
        result = chip.run(max_cycles=cycles)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        if best is None or cpu < best[1]:
            best = (wall, cpu, result)
    wall, cpu, result = best
    n = result.stats["pasm_instructions"]
    sim = result.end_cycle / result.trace.clock_hz
    print(f"{name}, the run alone: {n:,} PASM instructions, {sim:.3f} s simulated in {wall:.3f} s wall "
          f"({cpu:.3f} s CPU): {n / cpu:,.0f} instructions/s by CPU, {_factors(sim, wall, cpu)}")
    return result


def end_to_end(name: str, path: str, include: list, seconds: float) -> None:
    """``spinemu run PATH --seconds S`` in a new process: start-up, compiling and the run."""
    import resource
    import subprocess
    import spinemu
    # the spinemu this script imported (run from its folder: ``python -m`` puts the working folder first)
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(spinemu.__file__)))
    cmd = [sys.executable, "-m", "spinemu", "run", path, "--seconds", str(seconds), "-q", "--no-progress"]
    for folder in include:
        cmd += ["-L", folder]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, env=env, cwd=os.path.dirname(path))
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    print(f"{name}, end to end (spinemu run --seconds {seconds:g}): {wall:.2f} s wall ({cpu:.2f} s CPU): "
          f"{_factors(seconds, wall, cpu)}")


def _serial_text(result) -> bytes:
    from spinemu.bench.uart import UartFormat, decode_uart
    return bytes(f.value for f in decode_uart(result.trace, 30, UartFormat(115_200)))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--library", default=LIB)
    ap.add_argument("--serial-seconds", type=float, default=10.0, help="simulated seconds of the serial run")
    ap.add_argument("--pwm-seconds", type=float, default=4.0, help="simulated seconds of the PWM run")
    ap.add_argument("--no-speedups", action="store_true", help="idle-loop skipping and compiled blocks off")
    ap.add_argument("--only", choices=["loops", "drivers"], help="run only the small loops or only the drivers")
    a = ap.parse_args(argv)
    fast = not a.no_speedups
    import spinemu
    print(f"(spinemu from {os.path.dirname(spinemu.__file__)})")
    if a.only != "drivers":
        measure("CPU-bound PASM loop", compile_source(CPU_LOOP).binary, 40_000_000, a.repeat, fast)
        measure("PASM loop toggling a pin", compile_source(PIN_LOOP).binary, 20_000_000, a.repeat, fast)
        measure("two PASM cogs, hub ping-pong", compile_source(PING_PONG).binary, 20_000_000, a.repeat, fast)
    if a.only == "loops":
        return
    import tempfile
    serial_dir = os.path.join(a.library, "RCTime PASM", "RCTime_PASM")
    pwm_dir = os.path.join(a.library, "PWM 32 DEMO")
    have = os.path.isdir(serial_dir) and os.path.isdir(pwm_dir)
    if not have:
        print(f"(no Parallax library at {a.library}: a PASM transmitter and a software PWM loop of our own)")
    cases = [("FullDuplexSerial hello world" if have else "PASM serial hello world",
              SERIAL if have else OWN_SERIAL, [serial_dir] if have else [], a.serial_seconds),
             ("PWM_32 on three pins" if have else "software PWM on three pins",
              PWM if have else OWN_PWM, [pwm_dir] if have else [], a.pwm_seconds)]
    with tempfile.TemporaryDirectory() as tmp:
        for name, src, include, seconds in cases:
            path = os.path.join(tmp, "main.spin")
            with open(path, "w") as f:
                f.write(src)
            image = compile_file(path, include_dirs=include).binary
            cycles = int(seconds * 80_000_000)
            result = measure(name, image, cycles, a.repeat, fast)
            if "serial" in name.lower():
                print(f"  the serial line says {_serial_text(result)!r}")
            if fast:
                end_to_end(name, path, include, seconds)


if __name__ == "__main__":
    main()
