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


def _checked_installs(monkeypatch):
    """Every block installed must be what generating it afresh, at that moment, gives; returns the count."""
    from spinemu.chip.blocks import BlockCompiler

    installed = []
    real = BlockCompiler._install

    def install(self, start, end, private, src, loops, foot, locs, ro, privatable):
        fresh = self._generate(start, private)
        assert fresh is not None and fresh[:-1] == (src, end, loops, foot, locs, ro, privatable), hex(start)
        installed.append(start)
        return real(self, start, end, private, src, loops, foot, locs, ro, privatable)

    monkeypatch.setattr(BlockCompiler, "_install", install)
    return installed


def _count(cache) -> int:
    return sum(len(lst) for made in cache.blocks.values() for lst in made.values())


def _programs():
    from chip_helpers import PROGRAMS
    names = sorted(n for n in os.listdir(PROGRAMS) if n.endswith(".binary"))
    return [os.path.join(PROGRAMS, n) for n in names] + [DEMO]


def test_blocks_taken_from_the_cache_are_the_blocks_the_generator_makes(tmp_path, monkeypatch):
    """Generated blocks are kept by what they were generated from (the bytes read, the block starts met,
    the settings); a kept one must equal a fresh generation, and a run from the cache the run without."""
    installed = _checked_installs(monkeypatch)
    reused = 0
    for path in _programs():
        image = read_bytes(path)
        cache_file = str(tmp_path / (os.path.basename(path) + ".marshal"))
        want = run(image, None)
        first = CodeCache(cache_file)
        assert run(image, first) == want
        first.save()
        again = CodeCache(cache_file)
        kept = _count(again)
        before = len(installed)
        assert run(image, again) == want
        assert _count(again) == kept                                    # every block came from the cache
        reused += len(installed) - before
    assert reused > 400


def test_a_cached_block_is_not_taken_when_a_byte_it_read_differs(tmp_path):
    from spinemu.chip.blocks import BlockCompiler

    image = read_bytes(DEMO)
    cache = CodeCache(str(tmp_path / "c.marshal"))
    chip = Chip(image)
    chip.code_cache = cache
    chip.run(max_cycles=20_000_000)
    (key, entries), *_ = [(k, v) for made in cache.blocks.values() for k, v in made.items() if v]
    inputs, made = entries[0]
    compiler = BlockCompiler.__new__(BlockCompiler)
    compiler.mem, compiler.boundaries = bytearray(chip.mem), set()
    pc, last = key[0], inputs[0]
    assert compiler._inputs(pc, last)[1] == inputs[1]
    compiler.mem[last] ^= 1                             # the last byte the generator read
    assert compiler._inputs(pc, last) != inputs


def test_a_new_block_start_inside_a_cached_block_is_generated_afresh(tmp_path):
    """A busy-loop head becomes a block start (add_boundary): the block through it, kept in the cache,
    must not come back; the one generated now stops there."""
    from spinemu.chip.blocks import BlockCompiler

    image = read_bytes(DEMO)
    chip = Chip(image)
    chip.code_cache = CodeCache(str(tmp_path / "c.marshal"))
    compiler = BlockCompiler(chip, chip._blocks, chip._block_stub)
    start = next(pc for pc in range(0x10, 0x400) if compiler.compile(pc) is not None
                 and compiler.compiled[pc][0] - pc >= 4)
    end = compiler.compiled[start][0]
    from spinemu.bytecode import instruction_length
    middle = start + instruction_length(chip.mem, start)           # the block's second bytecode
    assert middle < end
    compiler.add_boundary(middle)
    again = compiler.compile(start)
    assert compiler.compiled[start][0] == middle
    assert again.source == compiler._generate(start, False)[0]


def test_blocks_of_another_generator_are_dropped_when_the_cache_is_saved(tmp_path):
    """After spinemu's block generator changed, its old blocks (and their code objects) can never be
    taken again: the next save drops them instead of loading them on every run."""
    image = read_bytes(DEMO)
    path = str(tmp_path / "demo.marshal")
    first = CodeCache(path)
    run(image, first)
    first.save()
    old = CodeCache(path)
    (gen,) = old.blocks
    stale = {gen + 1: {key: lists for key, lists in old.blocks[gen].items()}}
    old.blocks.update(stale)
    old.codes[("x = 1\n", "<stale>")] = compile("x = 1\n", "<stale>", "exec")
    old._dirty = True
    old.save()
    again = CodeCache(path)
    assert set(again.blocks) == {gen, gen + 1}
    run(image, again)                       # this generator only: the other one's go
    again.save()
    final = CodeCache(path)
    assert set(final.blocks) == {gen} and ("x = 1\n", "<stale>") not in final.codes
    assert final.codes and all(k[0] in {m[0] for v in final.blocks[gen].values() for _, m in v} for k in final.codes)
