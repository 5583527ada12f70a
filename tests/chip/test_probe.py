"""The instrumented loop a debugger or profiler attaches to (Chip.probe) runs every program
exactly as the fast loops do: same pin changes to the cycle, same hub RAM, same end."""
import glob
import os

import pytest

from spinemu.chip import Chip
from spinemu.compiler import compile_file

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PROGRAMS = sorted(glob.glob(os.path.join(ROOT, "tests", "data", "chip", "programs", "*.spin"))
                  + glob.glob(os.path.join(ROOT, "spin_src", "examples", "*.spin"))
                  + glob.glob(os.path.join(ROOT, "spin_src", "warnings", "*.spin")))
BUDGET = 3_000_000


class CountingProbe:
    """A probe that only counts what it is shown."""

    def __init__(self):
        self.before_calls = self.after_calls = 0

    def before(self, chip, cog):
        self.before_calls += 1

    def after(self, chip, cog, pc, t):
        self.after_calls += 1


@pytest.mark.parametrize("compat", ["spinsim", "chip"])
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: os.path.relpath(p, ROOT))
def test_a_probed_run_is_the_same_run(path, compat):
    image = compile_file(path).binary
    plain = Chip(image, compat=compat).run(max_cycles=BUDGET)
    chip = Chip(image, compat=compat)
    chip.probe = probe = CountingProbe()
    probed = chip.run(max_cycles=BUDGET)
    assert probed.trace.changes == plain.trace.changes
    assert probed.hub == plain.hub and probed.end_cycle == plain.end_cycle and probed.reason == plain.reason
    assert probe.after_calls == probed.stats["bytecodes"] == plain.stats["bytecodes"]
    assert probe.before_calls >= probe.after_calls


def test_a_probe_can_stop_the_run_between_two_bytecodes_and_it_goes_on_unchanged():
    from spinemu.chip.control import Halted

    image = compile_file(os.path.join(ROOT, "spin_src", "examples", "two_cogs.spin")).binary
    plain = Chip(image).run(max_cycles=50_000_000)

    class StopEvery:
        def __init__(self):
            self.n = 0

        def before(self, chip, cog):
            self.n += 1
            if self.n % 7 == 0:
                raise Halted("pause")

        def after(self, chip, cog, pc, t):
            pass

    chip = Chip(image)
    chip.probe = StopEvery()
    stops = 0
    while chip.advance(50_000_000) == "pause":
        stops += 1
    assert stops > 3
    result = chip.result("cycle limit")
    assert result.trace.changes == plain.trace.changes and result.hub == plain.hub
