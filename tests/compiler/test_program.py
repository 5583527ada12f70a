"""CompiledProgram: layout for the translator, compile_source, EEPROM form, warnings."""
import os

import pytest

from spinemu.compiler import compile_file, compile_source
from spinemu.diagnostics import CompileError
from spinemu.image import ImageHeader, from_eeprom, load_image

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_layout_gives_every_instance_its_hub_addresses():
    prog = compile_file(os.path.join(ROOT, "spin_src", "stepper_demo.spin"))
    top = prog.layout
    hdr = ImageHeader.parse(prog.binary)
    assert (top.pbase, top.vbase) == (0x10, hdr.vbase)
    assert top.var == {"idx": (0, 4, 1)}
    assert top.methods == {"main": (1, 0x20), "pause": (2, 0xAD)}
    assert top.constants["STEPS_PER_REV"] == 48
    (motor,) = top.children
    assert (motor.name, os.path.basename(motor.path)) == ("motor", "stepper.spin")
    assert motor.pbase == 0xC4 and motor.vbase == hdr.vbase + 4
    assert motor.var["stack"] == (8, 4, 64) and motor.var["stpIdx"] == (0x120, 4, 1)
    assert motor.dat["Steps"][0:2] == (0x3C, 1)
    assert prog.binary[motor.pbase + motor.dat["Steps"][0]] == 0b0011
    assert motor.methods["runStepper"][0] == 14


def test_duplicate_objects_share_code_but_not_var():
    kid = "VAR\n  long v\nPUB set(x)\n  v := x\n"
    prog = compile_source('OBJ\n  a : "kid"\n  b : "kid"\nPUB main\n  a.set(1)\n  b.set(2)\n',
                          files={"kid.spin": kid})
    a, b = prog.layout.children
    assert a.pbase == b.pbase and b.vbase == a.vbase + 4
    assert len(prog.objects) == 2


def test_compiled_image_is_a_valid_image_and_eeprom_holds_it():
    prog = compile_source("CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\nPUB main\n  dira[16]~~\n")
    assert load_image(prog.binary) == prog.binary
    ee = prog.eeprom()
    assert len(ee) == 32768 and from_eeprom(ee) == prog.binary
    hdr = ImageHeader.parse(prog.binary)
    assert (hdr.clkfreq, hdr.clkmode) == (80_000_000, 0x6F)
    assert ee[hdr.dbase - 8:hdr.dbase] == bytes.fromhex("fffff9fffffff9ff")


def test_compile_source_reports_the_name_it_was_given():
    with pytest.raises(CompileError) as info:
        compile_source("PUB main\n  x := 1\n", name="demo.spin")
    assert str(info.value).splitlines()[0] == "demo.spin:2:3: error: unknown symbol 'x'"


def test_no_warnings_for_a_clean_program():
    assert compile_file(os.path.join(ROOT, "spin_src", "simple_stepper.spin")).warnings == []
