"""spinemu.pasm against OpenSpin 1.00.81: every probe long must be byte-identical.

The probes (tests/data/pasm/*.spin, made by make_probes.py) were compiled by
OpenSpin with ``-q -c`` (DAT only) into the ``.dat`` files next to them.
"""
from __future__ import annotations

import importlib.util
import json
import struct
from pathlib import Path

import pytest

from spinemu import pasm

DATA = Path(__file__).resolve().parents[1] / "data" / "pasm"
SYMBOLS = {"lab": 0x123, "lab_ret": 0x1EE}
HEADER_LONGS = 2  # lab, lab_ret
SETS = ["instructions", "conditions", "operands", "words"]


def probe_cases(name: str) -> list[tuple[str, int]]:
    """(PASM line, OpenSpin's long) for every case of one probe set."""
    lines = (DATA / f"{name}.spin").read_text().splitlines()
    body = [ln.strip() for ln in lines[5:]]
    cases = [ln for ln in body if ln and not ln.lower().startswith(("org ", "pub "))]
    dat = (DATA / f"{name}.dat").read_bytes()
    words = struct.unpack(f"<{len(dat) // 4}I", dat)
    assert len(words) == HEADER_LONGS + len(cases), "probe and OpenSpin output disagree in length"
    return list(zip(cases, words[HEADER_LONGS:]))


def _load_generator():
    spec = importlib.util.spec_from_file_location("make_probes", DATA / "make_probes.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _report(bad: list) -> str:
    return f"{len(bad)} mismatches, first: " + "; ".join(map(str, bad[:8]))


@pytest.mark.parametrize("name", SETS)
def test_every_probe_line_assembles_to_the_long_openspin_made(name):
    bad = []
    for line, word in probe_cases(name):
        try:
            ours = pasm.assemble_line(line, SYMBOLS)
        except pasm.PasmError as exc:
            bad.append((line, f"{word:08X}", str(exc)))
            continue
        if ours != word:
            bad.append((line, f"openspin {word:08X}", f"ours {ours:08X}"))
    assert not bad, _report(bad)


@pytest.mark.parametrize("name", ["instructions", "conditions", "operands"])
def test_encode_arguments_give_the_long_openspin_made(name):
    # The generator pairs every probe line with the encode() call it stands for,
    # the call a compiler makes after parsing that line.
    made = _load_generator().SETS[name]()
    probes = probe_cases(name)
    assert [line for line, _ in made] == [line for line, _ in probes], "probe file is stale: rerun make_probes.py"
    bad = []
    for (line, kw), (_, word) in zip(made, probes):
        kw = dict(kw)
        mnemonic = kw.pop("mnemonic")
        ours = pasm.encode(mnemonic, **kw)
        if ours != word:
            bad.append((line, f"openspin {word:08X}", f"ours {ours:08X}"))
    assert not bad, _report(bad)


def test_disassembly_text_is_what_openspin_reassembles_to_the_same_long():
    # words.spin holds spinemu's disassembly of chosen and random longs;
    # OpenSpin turned that text back into words.dat.
    bad = []
    for line, word in probe_cases("words"):
        ours = " ".join(pasm.disassemble(word).split())
        if ours != line:
            bad.append((f"{word:08X}", line, ours))
    assert not bad, _report(bad)
    assert len(probe_cases("words")) > 2000


def test_probes_cover_every_instruction_and_condition():
    mnemonics = {line.split()[0].lower() for line, _ in probe_cases("instructions")}
    assert set(pasm.INSTRUCTIONS) <= mnemonics
    conds = {line.split()[0].lower() for line, _ in probe_cases("conditions")}
    assert set(pasm.CONDITIONS) == conds


def test_probes_cover_every_opcode_and_zcri_value():
    fields = {(w >> 22) for _, w in probe_cases("words")}
    assert len(fields) == 64 * 16


@pytest.mark.parametrize("case", json.loads((DATA / "errors.json").read_text()),
                         ids=lambda c: c["line"])
def test_constructs_openspin_rejects_raise_pasm_error(case):
    assert case["openspin_exit"] != 0 and case["openspin"]
    kw = dict(case["encode"])
    with pytest.raises(pasm.PasmError) as info:
        pasm.encode(kw.pop("mnemonic"), **kw)
    assert str(info.value) == case["message"]
    assert isinstance(info.value, ValueError)
