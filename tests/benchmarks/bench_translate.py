"""Speed of the Python engine against the bytecode engine on a CPU-bound Spin program (issue 5, item 6).

Run on demand (the default test run leaves tests/benchmarks/ out)::

    python -m pytest -q -s tests/benchmarks/bench_translate.py
    python tests/benchmarks/bench_translate.py

``tests/data/translate/cpu_bench.spin`` computes with arrays, calls and
division and never waits.  Both engines run it to the end (the same end
cycle, checked); each is timed over its run only (compiling and translating
happen before the clock starts), best of three.  Target: the Python engine
at least 3x as fast as the bytecode interpreter.

The bytecode engine also compiles hot runs of bytecode to Python functions
(``spinemu/chip/blocks.py``, on by default), itself a translation of the
bytecode; the benchmark prints the ratio against that too, for the record.
"""
from __future__ import annotations

import os
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

from spinemu.chip import Chip  # noqa: E402
from spinemu.compiler import compile_file  # noqa: E402
from spinemu.translate import _write, run_package  # noqa: E402
from spinemu.translate.program import translate_program  # noqa: E402
from spinemu.translate.weave import load_package  # noqa: E402

PROGRAM = os.path.join(ROOT, "tests", "data", "translate", "cpu_bench.spin")


def measure(repeats: int = 3) -> dict:
    prog = compile_file(PROGRAM)
    modules, compiled = translate_program(PROGRAM)
    tmp = tempfile.mkdtemp(prefix="spinemu-bench-")
    _write(modules, compiled, tmp)
    package = load_package(tmp)
    best_i = best_b = best_p = float("inf")
    for _ in range(repeats):
        t = time.perf_counter()
        ri = Chip(prog.binary, compile_blocks=False).run()
        best_i = min(best_i, time.perf_counter() - t)
        t = time.perf_counter()
        rb = Chip(prog.binary).run()
        best_b = min(best_b, time.perf_counter() - t)
        t = time.perf_counter()
        rp = run_package(package)
        best_p = min(best_p, time.perf_counter() - t)
        assert ri.end_cycle == rb.end_cycle == rp.end_cycle
    return {"cycles": rb.end_cycle, "bytecodes": rb.stats["bytecodes"], "interpreter_s": best_i,
            "blocks_s": best_b, "python_s": best_p,
            "ratio": best_i / best_p, "ratio_blocks": best_b / best_p}


def test_python_engine_is_at_least_three_times_faster():
    m = measure()
    n = m["bytecodes"]
    print(f"\ncpu_bench.spin: {m['cycles']:,} cycles, {n:,} bytecodes\n"
          f"  bytecode interpreter        {m['interpreter_s']:.3f} s ({n / m['interpreter_s']:,.0f} bytecodes/s)\n"
          f"  bytecode engine with blocks {m['blocks_s']:.3f} s ({n / m['blocks_s']:,.0f} bytecodes/s)\n"
          f"  Python engine               {m['python_s']:.3f} s\n"
          f"  speed ratio: {m['ratio']:.2f}x the interpreter, {m['ratio_blocks']:.2f}x the engine with blocks")
    assert m["ratio"] >= 3.0


if __name__ == "__main__":
    test_python_engine_is_at_least_three_times_faster()
