"""grammars/spin.lark: conflict-free LALR(1), analysed once and cached."""
import pytest

from spinemu.frontend import lalr


def test_grammar_has_no_lalr_conflicts_under_strict_checking():
    tables = lalr._build_tables(lalr.grammar_path().read_text(encoding="utf-8"))
    assert set(lalr.START_RULES) <= set(tables.start_states)


def test_strict_checking_refuses_an_ambiguous_grammar():
    from lark.exceptions import GrammarError
    ambiguous = """
%declare NUM PLUS
con_line: e
var_line: e
obj_line: e
dat_line: e
method: e
e: e PLUS e | NUM
"""
    with pytest.raises(GrammarError, match="[Cc]onflict"):
        lalr._build_tables(ambiguous)


def test_analysed_tables_are_cached_and_reused(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    first = lalr.load_tables()
    cached = list((tmp_path / "spinemu").glob("spin-*.lalr.pickle"))
    assert len(cached) == 1

    def no_analysis(text):
        raise AssertionError("the grammar was analysed again")

    monkeypatch.setattr(lalr, "_build_tables", no_analysis)
    second = lalr.load_tables()
    assert second.states == first.states and second.rules == first.rules


TINY = "%declare NUM\ncon_line: NUM\nvar_line: NUM\nobj_line: NUM\ndat_line: NUM\nmethod: NUM\n"


def test_a_changed_grammar_gets_new_tables(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    grammar = tmp_path / "spin.lark"
    grammar.write_text(TINY)
    lalr.load_tables(grammar)
    grammar.write_text(grammar.read_text() + "\n// a comment changes the key\n")
    lalr.load_tables(grammar)
    assert len(list((tmp_path / "spinemu").glob("spin-*.lalr.pickle"))) == 2


def test_an_unwritable_cache_still_parses(tmp_path, monkeypatch):
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocked))
    assert lalr.load_tables().states
