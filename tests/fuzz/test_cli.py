"""``python -m tests.fuzz``: printing a seed's program, and refusing to run without the reference tools."""
from __future__ import annotations

import pytest

from tests.fuzz import generate
from tests.fuzz.__main__ import main


def test_a_seed_prints_its_program_and_each_checks_verdict(capsys, monkeypatch):
    import tests.fuzz.__main__ as cli
    monkeypatch.setitem(cli.CHECKS, "fake", lambda program, ctx: None)
    assert main(["--seed", "5", "--check", "fake"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(generate(5).text())
    assert "--- fake: agree" in out


def test_a_disagreement_is_printed_and_gives_status_1(capsys, monkeypatch):
    import tests.fuzz.__main__ as cli
    monkeypatch.setitem(cli.CHECKS, "fake", lambda program, ctx: "images differ somewhere")
    assert main(["--seed", "5", "--check", "fake"]) == 1
    assert "--- fake: DISAGREE\nimages differ somewhere" in capsys.readouterr().out


def test_a_check_whose_reference_tool_is_missing_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit):
        main(["--seed", "1", "--check", "compile", "--openspin", str(tmp_path / "no-openspin")])
    assert "needs OpenSpin, not found at" in capsys.readouterr().err
