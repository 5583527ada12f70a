"""The cycle profiler (spinemu.profiler, spinemu profile, run --profile): every cycle of every
cog lands on a line, work and waits apart, and the figures add up to the run's cycles."""
import csv
import io
import json
from pathlib import Path

from spinemu.chip import Chip
from spinemu.cli import main
from spinemu.compiler import compile_file, compile_source
from spinemu.profiler import Profiler, profile_program

ROOT = Path(__file__).parent.parent
DEMO = ROOT / "spin_src" / "corrected" / "stepper_demo.spin"
TWO_COGS = ROOT / "spin_src" / "examples" / "two_cogs.spin"


def check_sums(profile):
    for c in profile.cogs:
        lines = [s for s in profile.lines if s.cog == c.cog]
        methods = [m for m in profile.methods if m.cog == c.cog]
        assert c.work + c.wait + c.start + c.pasm == c.cycles
        assert sum(s.cycles for s in lines) + c.start + c.pasm == c.cycles
        assert sum(m.cycles for m in methods) + c.start + c.pasm == c.cycles
        assert sum(s.bytecodes for s in lines) == c.bytecodes


def test_the_figures_add_up_to_the_runs_cycles():
    profile, result = profile_program(str(DEMO), cycles=40_000_000)
    check_sums(profile)
    cog0, cog1 = profile.cogs
    assert cog0.lives == [(0, 40_000_000)] and cog0.cycles == result.end_cycle == 40_000_000
    start1 = next(t for t, cog, kind, _ in result.cog_events if cog == 1 and kind == "start")
    assert cog1.lives == [(start1, 40_000_000)]
    assert profile.end_cycle == 40_000_000


def test_cogs_that_stop_are_counted_to_their_stop():
    profile, result = profile_program(str(TWO_COGS))
    check_sums(profile)
    stops = {cog: t for t, cog, kind, _ in result.cog_events if kind == "stop"}
    assert [c.lives[-1][1] for c in profile.cogs] == [stops[0], stops[1]]
    assert profile.cogs[0].cycles == result.end_cycle


def test_waitcnt_time_is_a_wait_on_its_line():
    profile, _ = profile_program(str(TWO_COGS))
    lines = {(s.cog, s.line): s for s in profile.lines}
    main_wait = lines[(0, 26)]                     # waitcnt(t += clkfreq / 4)
    assert main_wait.wait > 0.99 * profile.cogs[0].cycles
    assert lines[(1, 37)].wait > 0.99 * profile.cogs[1].cycles   # waitcnt(t += half)
    assert all(s.wait == 0 for s in profile.lines if s.line not in (26, 37))


def test_a_pin_wait_is_a_wait_on_its_line():
    src = ("VAR\n  long stack[16]\nPUB main\n  cognew(release, @stack)\n  waitpeq(|< 3, |< 3, 0)\n"
           "  dira[0]~~\n"
           "PRI release\n  waitcnt(cnt + 50_000)\n  dira[3]~~\n  outa[3]~~\n")
    prog = compile_source(src)
    chip = Chip(prog.binary, debug_info=prog.debug_info(), inputs="pulldown")
    profiler = Profiler(chip, prog.debug_info())
    chip.probe = profiler
    chip.run(max_cycles=200_000)
    profile = profiler.finish()
    check_sums(profile)
    wait_line = next(s for s in profile.lines if s.cog == 0 and s.line == 5)
    assert 45_000 < wait_line.wait < 55_000 and wait_line.work < 1_000   # (the line pushes 6 bytecodes)


def test_the_profiler_does_not_change_the_run():
    profile, profiled = profile_program(str(TWO_COGS))
    plain = Chip(compile_file(str(TWO_COGS)).binary).run()
    assert profiled.trace.changes == plain.trace.changes and profiled.hub == plain.hub
    assert profiled.end_cycle == plain.end_cycle


def test_an_image_without_source_is_profiled_by_address(tmp_path):
    image = tmp_path / "two.binary"
    image.write_bytes(compile_file(str(TWO_COGS)).binary)
    profile, result = profile_program(str(image))
    check_sums(profile)
    assert all(s.path is None and s.addr is not None for s in profile.lines)


# ----------------------------------------------------------------------------- the command line
def cli(*argv):
    out, err = io.StringIO(), io.StringIO()
    code = main([str(a) for a in argv], out, err)
    assert code == 0, err.getvalue()
    return out.getvalue()


def test_profile_writes_json_csv_and_an_annotated_listing(tmp_path):
    out = cli("profile", TWO_COGS, "--json", tmp_path / "p.json", "--csv", tmp_path / "p.csv",
              "--listing", tmp_path / "p.lst")
    assert "cycles per cog" in out and "cog 0: hottest lines" in out and "cog 1: methods (self cycles)" in out
    data = json.loads((tmp_path / "p.json").read_text())
    for cog in data["cogs"]:
        rows = [r for r in data["lines"] if r["cog"] == cog["cog"]]
        assert sum(r["cycles"] for r in rows) + cog["start"] == cog["cycles"]
    assert data["cogs"][0]["cycles"] == data["end_cycle"]
    rows = list(csv.DictReader(io.StringIO((tmp_path / "p.csv").read_text())))
    assert sum(int(r["cycles"]) for r in rows) == sum(c["cycles"] - c["start"] for c in data["cogs"])
    listing = (tmp_path / "p.lst").read_text()
    assert "waitcnt(t += clkfreq / 4)" in listing
    line26 = next(line for line in listing.splitlines() if "|   26|" in line)
    assert int(line26.split()[1].replace(",", "")) > 0            # its wait column


def test_run_profile_prints_the_tables_after_the_summary():
    out = cli("run", TWO_COGS, "--profile", "--no-progress")
    assert out.index("ended") < out.index("cycles per cog") < out.index("cog 1: hottest lines")


def test_a_pasm_cog_counts_as_pasm_and_the_figures_still_add_up():
    src = ("PUB main\n  cognew(@code, 0)\n  waitcnt(cnt + 50_000)\n  cogstop(1)\n  waitcnt(cnt + 10_000)\n"
           "DAT\ncode  nop\nloop  jmp #loop\n")
    prog = compile_source(src)
    chip = Chip(prog.binary, debug_info=prog.debug_info())
    profiler = Profiler(chip, prog.debug_info())
    chip.probe = profiler
    result = chip.run()
    profile = profiler.finish()
    check_sums(profile)
    cog1 = profile.cogs[1]
    assert cog1.pasm == cog1.cycles > 45_000 and cog1.bytecodes == 0
    assert profile.cogs[0].cycles == result.end_cycle
