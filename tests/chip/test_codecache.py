"""The cache of compiled blocks between runs (spinemu/chip/codecache.py)."""
from __future__ import annotations

import os

from spinemu.chip import Chip
from spinemu.chip.codecache import CodeCache, cache_dir, for_image

from chip_helpers import ARTICLE, read_bytes

DEMO = os.path.join(ARTICLE, "corrected_stepper_demo.binary")


def run(image, cache):
    chip = Chip(image)
    chip.code_cache = cache
    r = chip.run(max_cycles=200_000_000)
    return (r.trace.changes, r.hub, r.end_cycle, r.stats["bytecodes_per_cog"])


def test_a_second_run_takes_its_blocks_from_the_cache_and_runs_the_same(tmp_path):
    image = read_bytes(DEMO)
    path = str(tmp_path / "demo.marshal")
    first = CodeCache(path)
    want = run(image, first)
    assert first.misses > 10 and first.hits == 0
    first.save()
    again = CodeCache(path)
    assert run(image, again) == want == run(image, None)
    assert again.hits == first.misses and again.misses == 0


def test_a_damaged_cache_file_counts_as_empty(tmp_path):
    path = tmp_path / "bad.marshal"
    path.write_bytes(b"\x00garbage")
    cache = CodeCache(str(path))
    assert cache.codes == {}
    code = cache.compile("x = 1\n", "<t>")
    ns: dict = {}
    exec(code, ns)
    assert ns["x"] == 1 and cache.misses == 1


def test_the_cache_lives_where_the_environment_says_and_can_be_turned_off(tmp_path, monkeypatch):
    monkeypatch.setenv("SPINEMU_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("SPINEMU_CACHE", raising=False)
    assert cache_dir().startswith(str(tmp_path))
    assert for_image(b"\x00" * 32).path.startswith(str(tmp_path))
    monkeypatch.setenv("SPINEMU_CACHE", "0")
    assert cache_dir() is None and for_image(b"\x00" * 32) is None
