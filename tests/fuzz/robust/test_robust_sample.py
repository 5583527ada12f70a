"""A seeded sample of the robustness campaign: every command ends in a clear message, never a crash.

The full campaign (``python -m tests.fuzz.robust --seed 1 --cases 10000 --jobs 2``)
runs by hand; this sample runs in the default test suite.  A failure names
each crash signature with the command that reproduces its first case.
"""
from collections import Counter

from .campaign import BAD_KINDS, run_campaign, run_case
from .cases import KINDS, make_case

SAMPLE_SEED = 20_240_601
SAMPLE_CASES = 240


def _report(camp) -> str:
    lines = []
    for sig, group in camp.signatures().items():
        f = group[0]
        if f.kind in BAD_KINDS:
            lines.append(f"[{len(group)}x] {sig}\n  {f.reproduce()}\n  " + f.detail.strip()[-600:])
    return "\n".join(lines)


def test_a_seeded_sample_of_the_campaign_finds_no_crash():
    camp = run_campaign(SAMPLE_SEED, SAMPLE_CASES, budget_s=60)
    assert camp.cases == SAMPLE_CASES
    assert not camp.bad, _report(camp)
    # the sample reaches every generator and both clean outcomes
    assert set(camp.kinds) == set(KINDS)
    assert camp.statuses[0] > 0 and camp.statuses[1] > 0 and camp.statuses[2] > 0


def test_a_case_is_the_same_for_the_same_seed():
    a, b = make_case(4711), make_case(4711)
    assert (a.kind, a.origin, a.files, a.commands) == (b.kind, b.origin, b.files, b.commands)
    forced = make_case(4711, "image")
    assert forced.kind == "image" and forced.forced and not a.forced


def test_the_runner_sees_an_internal_error(monkeypatch):
    """The campaign must notice a crash: a command that raises is a finding with its signature."""
    from spinemu import cli

    def boom(args, out):
        raise ZeroDivisionError("planted")
    monkeypatch.setattr(cli, "cmd_disasm", boom)
    case = make_case(1, "image")
    case.commands = [["disasm", "{dir}/" + next(iter(case.files))]]
    findings, statuses = run_case(case)
    assert statuses == [70]
    assert [f.kind for f in findings] == ["internal"]
    assert findings[0].signature == "internal: ZeroDivisionError at spinemu/cli.py:boom" or \
        findings[0].signature.startswith("internal: ZeroDivisionError")


def test_the_runner_sees_a_wrong_quoted_line(tmp_path):
    from .campaign import _wrong_source_lines

    (tmp_path / "a.spin").write_text("PUB main\n  x := 1\n")
    err = f"{tmp_path}/a.spin:2:3: error: unknown symbol 'x'\nPUB main\n  ^\n"
    assert _wrong_source_lines(err, str(tmp_path))
    good = f"{tmp_path}/a.spin:2:3: error: unknown symbol 'x'\n  x := 1\n  ^\n"
    assert not _wrong_source_lines(good, str(tmp_path))


def test_the_kinds_are_drawn_in_proportion():
    counts = Counter(make_case(s).kind for s in range(400))
    assert set(counts) == set(KINDS)


def test_the_runner_accepts_a_long_line_shown_around_the_column(tmp_path):
    from spinemu.compiler import compile_source
    from spinemu.diagnostics import SpinError

    from .campaign import _wrong_source_lines

    src = "PUB main | x\n  x := " + " + ".join(["x"] * 80) + " + y\n"
    (tmp_path / "a.spin").write_text(src)
    try:
        compile_source(src, str(tmp_path / "a.spin"))
    except SpinError as e:
        rendered = e.render()
    assert "..." in rendered.splitlines()[1]
    assert not _wrong_source_lines(rendered, str(tmp_path))


#: seeds of past campaigns whose causes were fixed: each case must now end cleanly
#: (45742: a random image whose method table points past the hub, marked as code for the
#: write-into-code check; 49008: a console output file opened before a bad --input was refused)
FIXED_SEEDS = (45742, 49008)


def test_the_cases_of_fixed_findings_end_cleanly():
    for seed in FIXED_SEEDS:
        findings, _statuses = run_case(make_case(seed), budget_s=60)
        assert not [f for f in findings if f.kind in BAD_KINDS], f"seed {seed}: {findings}"
