"""PBASIC interpreter speed (not part of the default run: ``pytest tests/benchmarks -s``).

Prints PBASIC instructions per second and the real-time factor against a
BS2 (which runs about 3000-4000 instructions per second).
"""
import time
from pathlib import Path

from spinemu.pbasic import compile_file, compile_source, run_file

ROOT = Path(__file__).resolve().parents[2]
BUSY = """' {$STAMP BS2}
' {$PBASIC 2.5}
x VAR Word
y VAR Word
DO
  x = x + 1
  y = x * 3 // 7
  IF y > 3 THEN HIGH 1 ELSE LOW 1
LOOP
"""


def _measure(prog, seconds, timing):
    t0 = time.perf_counter()
    res = run_file(prog, seconds=seconds, timing=timing)
    wall = time.perf_counter() - t0
    return res, wall


def test_busy_loop_speed():
    prog = compile_source(BUSY)
    res, wall = _measure(prog, 60, "realistic")
    rate = res.instructions / wall
    print(f"\nbusy loop: {res.instructions} instructions in {wall:.3f} s = {rate:,.0f} instr/s, "
          f"{60 / wall:.0f}x real time")
    assert res.reason == "time"


def test_stepper_demo_speed():
    prog = compile_file(ROOT / "spin_src" / "bs2" / "stepper_bs2.bs2")
    for timing in ("exact", "realistic"):
        res, wall = _measure(prog, 60, timing)
        print(f"\nstepper demo 60 s {timing}: {wall * 1000:.1f} ms wall, {60 / wall:,.0f}x real time")
