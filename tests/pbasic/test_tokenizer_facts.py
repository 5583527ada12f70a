"""spinemu's PBASIC front end against facts observed with Parallax's tokenizer.

tests/data/pbasic/tokenizer_cases.txt holds the programs (ours);
tokenizer_facts.json what Parallax's tokenizer said about each (provenance in
tests/data/README.md): accepted or not, error line and column, variable
counts, EEPROM DATA bytes.  Pairs of programs that tokenize to identical
bytes must behave identically here, and pairs that do not must differ (both
are run from the same scrambled RAM so that every RAM view shows).
"""
import json
import random
from pathlib import Path

import pytest

from spinemu.diagnostics import SpinError
from spinemu.pbasic import compile_file, compile_source, run_file

DATA = Path(__file__).resolve().parents[1] / "data" / "pbasic"
FACTS = json.loads((DATA / "tokenizer_facts.json").read_text())
HEADER = "' {$STAMP BS2}\n' {$PBASIC 2.5}\n"

#: Where spinemu reports an error at a different column than Parallax's
#: tokenizer, and why (the line always agrees).
COLUMN_DEVIATIONS = {
    "alloc_overflow_by_a_bit": "spinemu points at the variable's name, the tokenizer at its type",
    "alloc_overflow_byte": "spinemu points at the variable's name, the tokenizer at the array size",
    "string_as_value": "spinemu points at the string, the tokenizer at its second character",
    "unsupported_bs2p_command": "same column; spinemu says which Stamp has the command",
    "inline_if_nested": "spinemu points at the inner IF, the tokenizer at the outer one",
    "conditional_error": "same column",
}


def parse_cases(text):
    cases, pairs, cur = {}, {}, None
    for line in text.split("\n"):
        if line.startswith("#") and cur is None:
            continue
        if line.startswith("== "):
            cur = cases.setdefault(line[3:].strip(), [[]])
            continue
        if line.startswith("~~ "):
            cur = pairs.setdefault(line[3:].strip(), [[]])
            continue
        if line.strip() == "~~" and cur is not None:
            cur.append([])
            continue
        if cur is not None:
            cur[-1].append(line)
    return cases, pairs


def source(lines):
    body = "\n".join(lines).strip("\n") + "\n"
    return body if body.startswith("'") else HEADER + body


CASES, PAIRS = parse_cases((DATA / "tokenizer_cases.txt").read_text())


def test_every_case_has_an_observed_fact():
    assert set(CASES) == set(FACTS["cases"])
    assert set(PAIRS) == set(FACTS["pairs"])


@pytest.mark.parametrize("name", sorted(FACTS["cases"]))
def test_case_agrees_with_parallax_tokenizer(name):
    fact = FACTS["cases"][name]
    src = source(CASES[name][0])
    if fact["ok"]:
        prog = compile_source(src, f"{name}.bs2")
        assert prog.var_counts == fact["vars"]
        data = {str(i): prog.eeprom[i] for i in range(2048) if prog.defined[i]}
        assert data == fact["data"]
        reserved = [i for i in range(2048) if prog.symbols.reserved_bytes[i]]
        assert reserved == fact["reserved"]
        return
    with pytest.raises(SpinError) as info:
        compile_source(src, f"{name}.bs2")
    err = info.value
    want = fact["error"]
    assert err.path == f"{name}.bs2"
    assert err.line == want["line"], err.render()
    if name not in COLUMN_DEVIATIONS:
        assert err.column == want["column"], err.render()
    assert err.render().startswith(f"{name}.bs2:{err.line}:{err.column}: error: ")


def _behaviour(src):
    """What the program does from cleared, all-ones and scrambled user RAM."""
    rng = random.Random(1234)
    out = []
    prog = compile_source(src)
    for ram in (bytes(32), b"\xff" * 32, bytes(rng.randrange(256) for _ in range(32))):
        res = run_file(prog, seconds=0.05, initial_ram=ram)
        out.append((res.ram, res.trace.changes, res.eeprom, res.debug_bytes))
    return out


@pytest.mark.parametrize("name", sorted(FACTS["pairs"]))
def test_pair_behaves_alike_exactly_when_tokens_are_identical(name):
    a, b = (source(body) for body in PAIRS[name])
    same = _behaviour(a) == _behaviour(b)
    assert same == FACTS["pairs"][name]["same_tokens"]


@pytest.mark.parametrize("path", sorted(FACTS["programs"]))
def test_example_program_agrees_with_parallax_tokenizer(path):
    fact = FACTS["programs"][path]
    prog = compile_file(Path(__file__).resolve().parents[2] / path)
    assert fact["ok"]
    assert prog.var_counts == fact["vars"]
    assert {str(i): prog.eeprom[i] for i in range(2048) if prog.defined[i]} == fact["data"]
