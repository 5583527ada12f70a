"""PASM ALU semantics against the vectors measured on spinsim (tests/data/pasm/alu_vectors.txt).

``alu`` below is a plain reference model of the Propeller Manual v1.2
descriptions (one line per instruction: result, C, Z).  Every measured
vector must agree with it, so the data file is a checked specification for a
PASM engine, and the model is where to read what each instruction does.
"""
from __future__ import annotations

from pathlib import Path

from spinemu import pasm

VECTORS = Path(__file__).resolve().parents[1] / "data" / "pasm" / "alu_vectors.txt"
M = 0xFFFFFFFF


def _s(v):                       # signed view of a long
    return v - (1 << 32) if v & 0x80000000 else v


def _parity(v):
    return bin(v).count("1") & 1


def _add(d, s, c=0):             # result, unsigned carry, signed overflow
    r = d + s + c
    return r & M, int(r > M), int(not -(1 << 31) <= _s(d) + _s(s) + c < (1 << 31))


def _sub(d, s, c=0):             # result, unsigned borrow, signed overflow
    r = d - s - c
    return r & M, int(r < 0), int(not -(1 << 31) <= _s(d) - _s(s) - c < (1 << 31))


def _abs(v):
    return (-_s(v)) & M if v & 0x80000000 else v


def _rev(d, n):
    return int(f"{d:032b}"[::-1], 2) >> n


def alu(mn: str, d: int, s: int, c: int, z: int):
    """(result, C, Z) of one ALU instruction.

    movs/movd/movi set C to ``D < S`` (unsigned), as measured on spinsim.
    """
    n = s & 31
    ones_hi = (M << (32 - n)) & M if n else 0
    table = {
        "ror": lambda: (((d >> n) | (d << (32 - n))) & M, d & 1),
        "rol": lambda: (((d << n) | (d >> (32 - n))) & M, d >> 31),
        "shr": lambda: (d >> n, d & 1),
        "shl": lambda: ((d << n) & M, d >> 31),
        "rcr": lambda: ((d >> n) | (ones_hi if c else 0), d & 1),
        "rcl": lambda: (((d << n) & M) | ((1 << n) - 1 if c else 0), d >> 31),
        "sar": lambda: ((_s(d) >> n) & M, d & 1),
        "rev": lambda: (_rev(d, n), d & 1),
        "mins": lambda: (s if _s(d) < _s(s) else d, int(_s(d) < _s(s))),
        "maxs": lambda: (s if _s(d) > _s(s) else d, int(_s(d) < _s(s))),
        "min": lambda: (s if d < s else d, int(d < s)),
        "max": lambda: (s if d > s else d, int(d < s)),
        "movs": lambda: ((d & ~0x1FF & M) | (s & 0x1FF), int(d < s)),
        "movd": lambda: ((d & ~(0x1FF << 9) & M) | ((s & 0x1FF) << 9), int(d < s)),
        "movi": lambda: ((d & ~(0x1FF << 23) & M) | ((s & 0x1FF) << 23), int(d < s)),
        "and": lambda: (d & s, _parity(d & s)),
        "andn": lambda: (d & ~s & M, _parity(d & ~s & M)),
        "or": lambda: (d | s, _parity(d | s)),
        "xor": lambda: (d ^ s, _parity(d ^ s)),
        "muxc": lambda: _mux(d, s, c),
        "muxnc": lambda: _mux(d, s, 1 - c),
        "muxz": lambda: _mux(d, s, z),
        "muxnz": lambda: _mux(d, s, 1 - z),
        "add": lambda: _add(d, s)[:2],
        "sub": lambda: _sub(d, s)[:2],
        # D + |S| is done as D - S when S < 0, so C is then the borrow (and the other way round)
        "addabs": lambda: _sub(d, s)[:2] if s >> 31 else _add(d, s)[:2],
        "subabs": lambda: _add(d, s)[:2] if s >> 31 else _sub(d, s)[:2],
        "sumc": lambda: (_sub if c else _add)(d, s)[::2],
        "sumnc": lambda: (_add if c else _sub)(d, s)[::2],
        "sumz": lambda: (_sub if z else _add)(d, s)[::2],
        "sumnz": lambda: (_add if z else _sub)(d, s)[::2],
        "mov": lambda: (s, s >> 31),
        "neg": lambda: ((-s) & M, s >> 31),
        "abs": lambda: (_abs(s), s >> 31),
        "absneg": lambda: ((-_abs(s)) & M, s >> 31),
        "negc": lambda: ((-s) & M if c else s, s >> 31),
        "negnc": lambda: (s if c else (-s) & M, s >> 31),
        "negz": lambda: ((-s) & M if z else s, s >> 31),
        "negnz": lambda: (s if z else (-s) & M, s >> 31),
        "cmps": lambda: (_sub(d, s)[0], int(_s(d) < _s(s))),
        "addx": lambda: _add(d, s, c)[:2],
        "subx": lambda: _sub(d, s, c)[:2],
        "cmpsx": lambda: (_sub(d, s, c)[0], int(_s(d) < _s(s) + c)),
        "adds": lambda: _add(d, s)[::2],
        "subs": lambda: _sub(d, s)[::2],
        "addsx": lambda: _add(d, s, c)[::2],
        "subsx": lambda: _sub(d, s, c)[::2],
        "cmpsub": lambda: (d - s, 1) if d >= s else (d, 0),
    }
    alias = {"test": "and", "testn": "andn", "cmp": "sub", "cmpx": "subx"}
    result, c_out = table[alias.get(mn, mn)]()
    z_out = int(result == 0)
    if mn in ("mins", "maxs", "min", "max"):
        z_out = int(s == 0)       # the limit is zero, whatever the result
    if mn == "cmpsub":
        z_out = int(d == s)
    if mn in ("addx", "subx", "cmpx", "addsx", "subsx", "cmpsx"):
        z_out &= z                # extended ops: Z stays set only if it was set
    return result, c_out, z_out


def _mux(d, s, bit):
    r = (d & ~s & M) | (s if bit else 0)
    return r, _parity(r)


def load():
    for line in VECTORS.read_text().splitlines():
        if line.startswith("#"):
            continue
        mn, d, s, c, z, _, r, c_out, z_out = line.split()
        yield mn, int(d, 16), int(s, 16), int(c), int(z), (None if r.startswith("-") else int(r, 16)), \
            int(c_out), int(z_out)


def test_vectors_cover_every_alu_instruction_with_all_flag_inputs():
    rows = list(load())
    assert len(rows) > 6000
    alu_mnemonics = {m for m, ins in pasm.INSTRUCTIONS.items() if ins.kind == "alu"}
    assert {r[0] for r in rows} == alu_mnemonics
    # flags are given both ways for every instruction
    for m in alu_mnemonics:
        assert {(r[3], r[4]) for r in rows if r[0] == m} >= {(0, 0), (1, 1)}


def test_results_not_written_only_by_nr_instructions():
    for mn, *_, r, _c, _z in load():
        assert (r is None) == (not pasm.INSTRUCTIONS[mn].writes), mn


def test_reference_model_agrees_with_every_measured_vector():
    bad = []
    for mn, d, s, c, z, r, c_out, z_out in load():
        result, want_c, want_z = alu(mn, d, s, c, z)
        got = (r, c_out, z_out)
        want = (result if r is not None else None, want_c, want_z)
        if got != want:
            bad.append(f"{mn} {d:08X} {s:08X} c={c} z={z}: measured {got}, model {want}")
    assert not bad, f"{len(bad)} disagreements, first: " + "; ".join(bad[:6])
