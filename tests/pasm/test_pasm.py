"""spinemu.pasm: the instruction table, encode/decode/disassemble and their round trips."""
from __future__ import annotations

import doctest
import random

import pytest

from spinemu import bytecode, pasm


def test_doctests_pass():
    result = doctest.testmod(pasm, optionflags=doctest.IGNORE_EXCEPTION_DETAIL)
    assert result.attempted >= 10 and result.failed == 0


def test_table_holds_every_propeller_manual_mnemonic():
    manual = """abs absneg add addabs adds addsx addx and andn call clkset cmp cmps cmpsub cmpsx
        cmpx cogid coginit cogstop djnz hubop jmp jmpret lockclr locknew lockret lockset max maxs
        min mins mov movd movi movs muxc muxnc muxnz muxz neg negc negnc negnz negz nop or rcl rcr
        rdbyte rdlong rdword ret rev rol ror sar shl shr sub subabs subs subsx subx sumc sumnc sumnz
        sumz test testn tjnz tjz waitcnt waitpeq waitpne waitvid wrbyte wrlong wrword xor""".split()
    assert sorted(pasm.INSTRUCTIONS) == sorted(manual)


def test_conditions_have_32_names_over_16_codes():
    assert len(pasm.CONDITIONS) == 32
    assert sorted(set(pasm.CONDITIONS.values())) == list(range(16))
    assert pasm.CONDITIONS["if_a"] == pasm.CONDITIONS["if_nc_and_nz"] == 0b0001
    assert pasm.CONDITIONS["if_be"] == pasm.CONDITIONS["if_z_or_c"] == 0b1110
    assert pasm.CONDITION_NAMES[0b1010] == "if_z"


def test_register_names_agree_with_the_bytecode_table():
    assert pasm.REGISTER_NAMES == bytecode.REGISTER_NAMES
    assert pasm.REGISTERS["OUTA"] == 0x1F4


def test_default_effects_follow_the_r_bit():
    writes = {m for m, ins in pasm.INSTRUCTIONS.items() if ins.writes}
    assert {"mov", "and", "sub", "djnz", "waitcnt", "rdlong", "cogid", "locknew", "call", "jmpret"} <= writes
    assert not writes & {"test", "testn", "cmp", "cmps", "cmpx", "cmpsx", "tjz", "tjnz", "jmp", "ret",
                         "wrlong", "waitpeq", "waitvid", "coginit", "clkset", "hubop"}
    assert pasm.INSTRUCTIONS["cmp"].default_effect == "nr"


def test_fields_rebuild_the_word():
    rng = random.Random(1)
    for _ in range(2000):
        w = rng.getrandbits(32)
        d = pasm.decode(w)
        assert d.opcode << 26 | d.zcri << 22 | d.cond << 18 | d.dest << 9 | d.src == w


def test_every_long_disassembles_to_text_that_assembles_back():
    rng = random.Random(7)
    words = [rng.getrandbits(32) for _ in range(20000)]
    words += [(op << 26) | (zcri << 22) | (c << 18) for op in range(64) for zcri in range(16) for c in (0, 15)]
    for w in words:
        assert pasm.assemble_line(pasm.disassemble(w)) == w, pasm.disassemble(w)


def test_aliases_disassembly_chooses():
    assert pasm.disassemble(0).strip() == "nop"
    assert pasm.decode(pasm.encode("and", dest=1, src=2, effects=["nr"])).mnemonic == "test"
    assert pasm.decode(pasm.encode("sub", dest=1, src=2, effects=["nr"])).mnemonic == "cmp"
    assert pasm.decode(pasm.encode("jmpret", dest=0, src=5, immediate=True, effects=["nr"])).mnemonic == "jmp"
    assert pasm.decode(pasm.encode("jmp", src=0, immediate=True)).mnemonic == "ret"
    assert pasm.decode(pasm.encode("hubop", dest=3, src=1, immediate=True, effects=["wr"])).mnemonic == "cogid"
    assert " ".join(pasm.disassemble(pasm.encode("mov", dest=1, src=2, effects=["nr", "wz"])).split()) \
        == "mov $001, $002 wz, nr"
    assert " ".join(pasm.disassemble(pasm.encode("mov", condition="if_never", dest=1, src=2)).split()) \
        == "if_never mov $001, $002"


def test_opcodes_without_mnemonic_show_as_long_data():
    w = (0b000101 << 26) | 0x1234
    assert pasm.decode(w).instr is pasm.DATA_LONG
    assert pasm.disassemble(w).split() == ["long", "$14001234"]


def test_symbols_name_registers_jump_targets_and_calls():
    syms = {0x10: "loop", 0x11: "count", 0x20: "send", 0x21: "send_ret"}
    djnz = pasm.encode("djnz", dest=0x11, src=0x10, immediate=True)
    assert pasm.disassemble(djnz, symbols=syms).split() == ["djnz", "count,", "#loop"]
    assert pasm.disassemble(djnz, 0x10, syms).split()[0] == "loop"
    call = pasm.encode("call", dest=0x21, src=0x20, immediate=True)
    assert pasm.disassemble(call, symbols=syms).split() == ["call", "#send"]
    assert pasm.disassemble(call).split() == ["jmpret", "$021,", "#$020"]
    # an immediate that is not a jump target stays a number
    mov = pasm.encode("mov", dest=0x11, src=0x10, immediate=True)
    assert pasm.disassemble(mov, symbols=syms).split() == ["mov", "count,", "#$010"]


def test_decoded_jump_target():
    assert pasm.decode(pasm.encode("tjz", dest=1, src=9, immediate=True)).jump_target == 9
    assert pasm.decode(pasm.encode("jmp", src=9)).jump_target is None      # indirect
    assert pasm.decode(pasm.encode("ret")).jump_target is None
    assert pasm.decode(pasm.encode("add", dest=1, src=9, immediate=True)).jump_target is None


def test_negative_operands_are_or_ed_in_like_openspin():
    assert pasm.encode("mov", dest=5, src=-1, immediate=True) == 0xFFFFFFFF
    assert pasm.encode("mov", dest=-2, src=5) == 0xFFFFFC05


@pytest.mark.parametrize("kw, part", [
    (dict(mnemonic="mov", dest=1, src=2, condition="if_maybe"), "condition"),
    (dict(mnemonic="mov", dest=1, src=2, effects=["wz", "xx"]), "effect"),
    (dict(mnemonic="mov", dest=0x200, src=2), "dest"),
    (dict(mnemonic="mov", dest=1, src=0x200, immediate=True), "src"),
    (dict(mnemonic="frob", dest=1, src=2), "mnemonic"),
])
def test_errors_say_which_part_is_wrong(kw, part):
    with pytest.raises(pasm.PasmError) as info:
        pasm.encode(kw.pop("mnemonic"), **kw)
    assert info.value.part == part
    if part == "effect":
        assert info.value.index == 1


def test_assemble_line_resolves_call_labels_and_comments():
    syms = {"blink": 7, "blink_ret": 8}
    assert pasm.assemble_line("call #blink  ' go", syms) == 0x5CFC1007
    with pytest.raises(pasm.PasmError, match="unknown symbol 'blonk'"):
        pasm.assemble_line("jmp #blonk", syms)


def test_docs_examples_run():
    from pathlib import Path
    doc = Path(__file__).resolve().parents[2] / "docs" / "pasm.md"
    result = doctest.testfile(str(doc), module_relative=False,
                              optionflags=doctest.IGNORE_EXCEPTION_DETAIL | doctest.ELLIPSIS)
    assert result.attempted >= 15 and result.failed == 0


def test_ret_long_can_be_shown_as_jmp_to_zero():
    ret = pasm.encode("ret", condition="if_c")
    assert ret == pasm.encode("jmp", condition="if_c", src=0, immediate=True)
    assert pasm.disassemble(ret).split() == ["if_c", "ret"]
    assert pasm.disassemble(ret, ret_as_jmp=True).split() == ["if_c", "jmp", "#$000"]
    assert pasm.disassemble(ret, symbols={0: "entry"}, ret_as_jmp=True).split() == ["if_c", "jmp", "#entry"]
    assert pasm.assemble_line(pasm.disassemble(ret, ret_as_jmp=True)) == ret
