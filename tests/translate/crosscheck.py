"""Running a Spin program on both engines and comparing what they leave (shared by the tests and the benchmark).

The bytecode engine is the reference.  Two runs agree when:

* the pin traces go through the same states (``compare_traces``), with a
  worst timing error of at most 2 % (and we report the largest offset in
  cycles, usually 0);
* hub RAM is identical except each Spin cog's stack: from the cog's return
  frame (8 bytes below its first frame) up to four longs past the highest
  stack pointer the bytecode interpreter reached, its busy-loop learner
  included (RUN and the assignment operators leave scratch values just
  above it), and at least what the RUN
  bytecode wrote for a ``cognew`` (frame, arguments, the new cog's
  interpreter words).  The Python engine keeps locals, parameters and
  expression values in Python, so those bytes are dead scratch it does not
  write; everything else (VAR, DAT, the image, free RAM, other cogs'
  data) must match byte for byte.
"""
from __future__ import annotations

from dataclasses import dataclass

from spinemu.analysis.compare import compare_traces
from spinemu.chip import Chip
from spinemu.chip.fastforward import tracking_handlers
from spinemu.compiler import compile_file
from spinemu import translate


@dataclass
class Agreement:
    comparison: object
    hub_differences: list
    bytecode: object
    python: object

    @property
    def ok(self) -> bool:
        return self.comparison.identical and self.comparison.worst_error <= 0.02 and not self.hub_differences

    def describe(self) -> str:
        lines = [self.comparison.render()]
        if self.hub_differences:
            shown = ", ".join(f"${a:04X}: {b} vs {p}" for a, b, p in self.hub_differences[:8])
            lines.append(f"hub RAM differs outside the stacks at {len(self.hub_differences)} bytes: {shown}")
        return "\n".join(lines)


def run_bytecode(src: str, max_cycles: int, compat: str = "spinsim"):
    """The bytecode engine's run and each cog's stack high-water mark."""
    prog = compile_file(src)
    # compiled blocks (spinemu/chip/blocks.py) run bytecode without the handlers watched
    # below; they give the same results (tests/chip/test_blocks.py), so the interpreter
    # alone stands for the bytecode engine here
    chip = Chip(prog.binary, compat=compat, compile_blocks=False)
    high = {}

    def watch(handler):
        def run(c, op, tf):
            rest = handler(c, op, tf)
            if c.sp > high.get(c.id, 0):
                high[c.id] = c.sp
            return rest
        return run

    # every interpreter the chip runs bytecode with: its handlers, the copy it
    # restores after a preemption, and the busy-loop learner's tracking copy
    # (which really runs the cog: a call it makes uses the stack as well)
    chip.handlers[:] = [watch(h) for h in chip.handlers]
    chip._handlers[:] = chip.handlers
    tracking, log = tracking_handlers(chip, chip.timing)
    tracking[:] = [watch(h) for h in tracking]
    chip._tracking = (tracking, log)
    return chip.run(max_cycles), high


def stack_bytes(python_result, high: dict) -> set:
    """Hub addresses allowed to differ (see the module docstring)."""
    allowed = set()
    for cog, first, end in python_result.stats["stacks"]:
        allowed.update(range(first, max(end, high.get(cog, first) + 16)))
    return allowed


def crosscheck(src: str, max_cycles: int, compat: str = "spinsim", bytecode_run=None) -> Agreement:
    """Run ``src`` on both engines for ``max_cycles`` in compat mode ``compat`` and compare.

    ``bytecode_run``: what :func:`run_bytecode` already returned for these arguments, if the
    caller ran it (to see whether it faults); otherwise it is run here.
    """
    python = translate.run_translated(src, max_cycles=max_cycles, compat=compat)
    bytecode, high = bytecode_run or run_bytecode(src, max_cycles, compat)
    cmp = compare_traces(bytecode.trace, python.trace, slack=0, tolerance=0.02)
    allowed = stack_bytes(python, high)
    diffs = [(a, bytecode.hub[a], python.hub[a]) for a in range(len(bytecode.hub))
             if bytecode.hub[a] != python.hub[a] and a not in allowed]
    return Agreement(cmp, diffs, bytecode, python)
