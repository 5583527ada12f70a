"""The Spin grammar's LALR(1) tables, cached, and a small parser that runs them.

``grammars/spin.lark`` is analysed by Lark (``strict`` conflict checking: any
shift/reduce or reduce/reduce conflict is an error) the first time it is
needed; the resulting tables are pickled into the user's cache directory
(``$XDG_CACHE_HOME/spinemu`` or ``~/.cache/spinemu``, keyed by the grammar's
CRC-32, Adler-32 and length), so later runs neither analyse the grammar nor import Lark at all:
importing Lark alone costs about 75 ms, loading the pickled tables about 3 ms.

:class:`Parser` is a plain LALR driver over those tables.  It shapes results
the way Lark's tree builder does (tokens named ``_X`` are dropped, rules named
``_x`` are inlined, ``?rule`` with one child collapses) and hands each reduced
rule's children to a builder method named after the rule's alias.
"""
from __future__ import annotations

import os
import pickle
from typing import Callable, Optional

__all__ = ["Tables", "Parser", "ParseFailure", "grammar_path", "load_tables", "START_RULES"]

START_RULES = ["con_line", "var_line", "obj_line", "dat_line", "method"]
_FORMAT = 2  # bump when the pickled layout changes


def _grammar_file() -> str:
    """Where spin.lark is: installed next to the package, or in the checkout."""
    pkg = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    for cand in (os.path.join(pkg, "grammars", "spin.lark"),
                 os.path.join(os.path.dirname(pkg), "grammars", "spin.lark")):
        if os.path.exists(cand):
            return cand
    raise FileNotFoundError("grammars/spin.lark not found")


def grammar_path():
    """:func:`_grammar_file` as a ``pathlib.Path`` (pathlib is imported only here: it is slow to import)."""
    from pathlib import Path
    return Path(_grammar_file())


def _cache_dir() -> str:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "spinemu")


class Tables:
    """Parse tables: ``states[s][symbol]`` is ``>= 0`` (shift/goto) or ``-1 - rule``.

    ``rules[r]`` is ``(origin, size, callback, expand1, inline, recipe, append_none)``
    where ``recipe`` lists ``(child index, splice, nones before)`` for the kept children.
    """

    def __init__(self, states, rules, start_states, end_states, terminals):
        self.states = states
        self.rules = rules
        self.start_states = start_states
        self.end_states = end_states
        self.terminals = terminals


def _build_tables(text: str) -> Tables:
    """Analyse the grammar with Lark (slow: only on a cache miss)."""
    from lark.load_grammar import load_grammar
    from lark.common import ParserConf
    from lark.parsers.lalr_analysis import LALR_Analyzer, IntParseTable

    grammar, _ = load_grammar(text, "spin.lark", [], False)
    _terms, rules, _ignore = grammar.compile(START_RULES, set())
    analyzer = LALR_Analyzer(ParserConf(rules, None, START_RULES), strict=True)
    analyzer.compute_lalr()
    table = IntParseTable.from_ParseTable(analyzer.parse_table)
    rule_index = {rule: i for i, rule in enumerate(rules)}
    out_rules = []
    for rule in rules:
        recipe = []
        empties = list(rule.options.empty_indices) if rule.options.empty_indices else []
        if empties:
            s = "".join(str(int(b)) for b in empties)
            nones = [len(ones) for ones in s.split("0")]
        else:
            nones = [0] * (len(rule.expansion) + 1)
        pending = 0
        for i, sym in enumerate(rule.expansion):
            pending += nones[i]
            if sym.is_term and (sym.filter_out or sym.name.startswith("_")):
                continue
            splice = (not sym.is_term) and sym.name.startswith("_")
            recipe.append((i, splice, pending))
            pending = 0
        pending += nones[len(rule.expansion)]
        name = rule.origin.name
        name = name.value if hasattr(name, "value") else str(name)
        callback = rule.alias or name
        callback = callback.value if hasattr(callback, "value") else str(callback)
        out_rules.append((name, len(rule.expansion), callback,
                          bool(rule.options.expand1) and not rule.alias,
                          name.startswith("_"), tuple(recipe), pending))
    states = []
    terminals = set()
    for s in range(len(table.states)):
        acts = {}
        for sym, (action, arg) in table.states[s].items():
            if action.name == "Shift":
                acts[sym] = arg
            else:
                acts[sym] = -1 - rule_index[arg]
            if sym.isupper() or sym.startswith("_") and sym[1:2].isupper() or sym == "$END":
                terminals.add(sym)
        states.append(acts)
    return Tables(states, out_rules, dict(table.start_states), dict(table.end_states),
                  frozenset(terminals))


def load_tables(path=None, use_cache: bool = True) -> Tables:
    """The tables for ``path`` (a str or Path; default: spin.lark), from the cache when possible."""
    with open(path or _grammar_file(), encoding="utf-8") as fh:
        text = fh.read()
    data = f"{_FORMAT}\0{text}".encode()
    from ..fileio import cache_name
    cache = os.path.join(_cache_dir(), "spin-" + cache_name(data, ".lalr.pickle"))
    if use_cache:
        try:
            with open(cache, "rb") as fh:
                return pickle.load(fh)
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
            pass
    tables = _build_tables(text)
    if use_cache:
        from ..fileio import write_cache_file

        try:
            write_cache_file(cache, pickle.dumps(tables, protocol=pickle.HIGHEST_PROTOCOL))
        except OSError:
            pass
    return tables


class ParseFailure(Exception):
    """The token ``token`` does not fit; ``expected`` lists the token kinds that would."""

    def __init__(self, token, expected):
        super().__init__(token)
        self.token = token
        self.expected = expected


class _End:
    __slots__ = ("type", "value", "line", "col")

    def __init__(self, after):
        self.type = "$END"
        self.value = ""
        self.line = after.line if after is not None else 1
        self.col = (after.col + len(after.value)) if after is not None else 1


class Parser:
    """Runs the tables over a token list, calling ``builder.<callback>(children)``."""

    def __init__(self, tables: Tables, builder):
        self.tables = tables
        self.callbacks: list[Optional[Callable]] = []
        # unit rules (``?a: b`` reducing one child to itself) only change state: the
        # expression grammar's precedence chain makes most reductions of this kind
        self.unit: list[bool] = []
        for (_origin, size, callback, expand1, inline, recipe, append_none) in tables.rules:
            fn = None if inline else getattr(builder, callback, None)
            self.callbacks.append(fn)
            self.unit.append(size == 1 and expand1 and not inline and not append_none
                             and recipe == ((0, False, 0),))

    def parse(self, tokens: list, start: str):
        """Parse ``tokens`` from rule ``start``; raise :class:`ParseFailure` on a bad token."""
        tables = self.tables
        states = tables.states
        rules = tables.rules
        callbacks = self.callbacks
        unit = self.unit
        state_stack = [tables.start_states[start]]
        end_state = tables.end_states[start]
        value_stack: list = []
        end = _End(tokens[-1] if tokens else None)
        for tok in [*tokens, end]:
            ttype = tok.type
            while True:
                action = states[state_stack[-1]].get(ttype)
                if action is None:
                    raise ParseFailure(tok, self.expected(state_stack[-1]))
                if action >= 0:
                    state_stack.append(action)
                    value_stack.append(tok)
                    break
                r = -1 - action
                if unit[r]:
                    state_stack[-1] = states[state_stack[-2]][rules[r][0]]
                    if ttype == "$END" and state_stack[-1] == end_state:
                        return value_stack[-1]
                    continue
                origin, size, _cb, expand1, inline, recipe, append_none = rules[r]
                if size:
                    children = value_stack[-size:]
                    del value_stack[-size:]
                    del state_stack[-size:]
                else:
                    children = []
                kept: list = []
                for idx, splice, nones in recipe:
                    if nones:
                        kept.extend([None] * nones)
                    if splice:
                        kept.extend(children[idx])
                    else:
                        kept.append(children[idx])
                if append_none:
                    kept.extend([None] * append_none)
                if inline:
                    value = kept
                elif expand1 and len(kept) == 1:
                    value = kept[0]
                else:
                    fn = callbacks[r]
                    if fn is None:
                        raise RuntimeError(f"no builder method for rule {_cb!r}")
                    value = fn(kept)
                state_stack.append(states[state_stack[-1]][origin])
                value_stack.append(value)
                if ttype == "$END" and state_stack[-1] == end_state:
                    return value
        raise AssertionError("unreachable")  # pragma: no cover

    def expected(self, state: int) -> list:
        return sorted(s for s in self.tables.states[state] if s in self.tables.terminals)
