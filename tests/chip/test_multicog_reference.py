"""Generated multi-cog programs end with the hub RAM the reference simulator leaves.

``tests/data/chip/multicog_reference.json`` holds, for the seeds of
tests/chip/multicog_programs.py that end by themselves, the SHA-256 of the hub
RAM spinsim 0.99 ``-p`` left when every cog had stopped (the workers' stack
arrays apart), recorded by ``tests/benchmarks/multicog_reference.py
--record``.  The results depend on every cog's timing: CNT values, INA
samples of pins other cogs drive, who wins a race for a lock or a variable.
"""
import hashlib
import json
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "benchmarks"))

from multicog_reference import spinemu_outcome  # noqa: E402

with open(os.path.join(ROOT, "tests", "data", "chip", "multicog_reference.json")) as fh:
    RECORD = json.load(fh)


@pytest.mark.parametrize("seed", sorted(int(s) for s in RECORD["sha256"]))
def test_the_program_leaves_the_hub_ram_the_reference_left(seed):
    _, compared = spinemu_outcome(seed, RECORD["cycles"])
    assert compared is not None, "the program no longer ends by itself"
    assert hashlib.sha256(compared).hexdigest() == RECORD["sha256"][str(seed)]
