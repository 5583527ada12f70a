"""spinemu.analysis.disasm: listings of real images, PASM detection, source maps, bad input."""
from __future__ import annotations

import struct
from pathlib import Path

import pytest

from spinemu.analysis.disasm import analyse_image, disassemble_image
from spinemu.diagnostics import ImageError
from spinemu.image import ImageHeader

DATA = Path(__file__).resolve().parents[1] / "data"
GOLDEN = DATA / "pasm" / "disasm"
IMAGES = {
    "as_printed_simple_stepper": DATA / "article" / "as_printed_simple_stepper.binary",
    "as_printed_stepper_demo": DATA / "article" / "as_printed_stepper_demo.binary",
    "corrected_stepper_demo": DATA / "article" / "corrected_stepper_demo.binary",
    "pasm_demo": GOLDEN / "pasm_demo.binary",
    "pasm_launch": GOLDEN / "pasm_launch.binary",
}


def check_golden(text: str, golden: Path, update: bool) -> None:
    """Compare with a golden file; on a mismatch write ``<golden>.actual`` next to it."""
    actual = golden.with_name(golden.name + ".actual")
    if update:
        golden.write_text(text)
        actual.unlink(missing_ok=True)
        return
    expected = golden.read_text() if golden.exists() else ""
    if text != expected:
        actual.write_text(text)
        pytest.fail(f"listing differs from {golden.name}: compare with {actual.name} "
                    f"(rerun with --update-golden to accept)")
    actual.unlink(missing_ok=True)


@pytest.mark.parametrize("name", sorted(IMAGES))
def test_listing_matches_golden(name, update_golden):
    text = disassemble_image(IMAGES[name].read_bytes())
    check_golden(text, GOLDEN / f"{name}.lst", update_golden)


def test_eeprom_lists_like_the_binary():
    binary = disassemble_image((GOLDEN / "pasm_demo.binary").read_bytes())
    eeprom = disassemble_image((GOLDEN / "pasm_demo.eeprom").read_bytes())
    assert eeprom == binary


def test_header_tree_and_methods_of_the_stepper_demo():
    listing = analyse_image(IMAGES["as_printed_stepper_demo"].read_bytes())
    assert listing.checksum_ok
    root = listing.root
    assert (root.base, root.var_base, root.var_size) == (0x10, 0x2C0, 4)
    (motor,) = root.children
    assert (motor.base, motor.var_base, motor.var_size) == (0xC4, 0x2C4, 292)
    top = listing.objects[0x10]
    assert [m.start for m in top.methods] == [0x20, 0xAD]
    assert top.methods[0].insns[0].addr == listing.header.pcurr
    # every byte of every method is an instruction, a string or padding
    for obj in listing.objects.values():
        for m in obj.methods:
            covered = sum(len(i.data) for i in m.insns) + sum(len(t) + 1 for _, t in m.strings)
            covered += m.padding[1] if m.padding else 0
            assert covered == m.end - m.start, (hex(m.start), covered)


def test_cognew_of_a_dat_address_makes_a_pasm_block():
    listing = analyse_image(IMAGES["pasm_demo"].read_bytes())
    blocks = {(b.kind, b.start, b.end) for obj in listing.objects.values() for b in obj.dat}
    # top: data table, counter_loop (launched by coginit; 5 longs incl. its variable),
    # spare (never launched; found as plausible code); child: the blinker
    assert ("data", 0x28, 0x40) in blocks
    assert ("pasm", 0x40, 0x54) in blocks
    assert ("pasm", 0x54, 0x70) in blocks
    text = disassemble_image(IMAGES["pasm_demo"].read_bytes())
    assert "launched by COGINIT at $00CA (method 1)" in text
    assert "7 longs that look like code" in text
    assert "call    #L00D" in text and "L00D_ret" in text
    assert "jmp     #L000" in text            # the ret-form long that is no return


def test_indexed_launch_address_if_never_start_and_bitmaps():
    listing = analyse_image(IMAGES["pasm_launch"].read_bytes())
    blocks = [(b.kind, b.start, b.end) for b in listing.objects[0x10].dat]
    # glyph bytes and $FFFFFFFF fills stay data; cognew(@code[0], 0) is found through the
    # constant index; the walk steps over the leading if_never long (the d0 trick)
    assert blocks == [("data", 0x18, 0x58), ("pasm", 0x58, 0x68), ("pasm", 0x68, 0x6C)]


def test_pasm_modes_can_be_overridden():
    image = IMAGES["pasm_demo"].read_bytes()
    none = analyse_image(image, pasm="none")
    assert all(b.kind == "data" for o in none.objects.values() for b in o.dat)
    launched = analyse_image(image, pasm="launched")
    kinds = [(b.kind, b.start) for b in launched.objects[0x10].dat]
    assert kinds == [("data", 0x28), ("pasm", 0x40), ("data", 0x54)]
    everything = analyse_image(image, pasm="all")
    assert [(b.kind, b.start, b.end) for b in everything.objects[0x10].dat] == [("pasm", 0x28, 0x70)]
    given = analyse_image(image, pasm=[0x54])
    assert [(b.kind, b.start) for b in given.objects[0x10].dat] == [("data", 0x28), ("pasm", 0x54)]
    with pytest.raises(ValueError):
        analyse_image(image, pasm="some")


def test_data_is_not_taken_for_code():
    listing = analyse_image(IMAGES["as_printed_simple_stepper"].read_bytes())
    assert [b.kind for o in listing.objects.values() for b in o.dat] == ["data"]


def test_source_lines_are_shown_above_their_code():
    image = IMAGES["pasm_demo"].read_bytes()
    spin = GOLDEN / "pasm_demo.spin"
    source_map = {0x70: (str(spin), 15), 0x7B: (str(spin), 16), 0x40: ("x.spin", 3, "  rdlong value, par")}
    text = disassemble_image(image, source_map=source_map)
    lines = text.splitlines()
    k = lines.index("    ' pasm_demo.spin:15  blink[0].start(16, 80_000)")
    assert lines[k + 1].startswith("    $0070")
    assert "    ' pasm_demo.spin:16  blink[1].start(17, 160_000)" in lines
    assert "    ' x.spin:3  rdlong value, par" in lines
    # a callable works the same way
    assert disassemble_image(image, source_map=source_map.get) == text


def test_wrong_checksum_is_reported_not_raised():
    image = bytearray(IMAGES["pasm_demo"].read_bytes())
    image[5] ^= 0xFF
    text = disassemble_image(bytes(image))
    assert "WRONG (contents give $" in text.splitlines()[2]


@pytest.mark.parametrize("mangle, message", [
    (lambda b: b[:10], "too short"),
    (lambda b: b[:6] + b"\x20\x00" + b[8:], "pbase"),
    (lambda b: b[:8] + struct.pack("<H", 0x7000) + b[10:], "vbase"),
])
def test_broken_images_raise_image_error(mangle, message):
    image = IMAGES["pasm_demo"].read_bytes()
    with pytest.raises(ImageError, match=message):
        disassemble_image(mangle(image))


def test_object_table_pointing_past_the_image_raises_image_error():
    image = bytearray(IMAGES["pasm_demo"].read_bytes())
    hdr = ImageHeader.parse(image)
    struct.pack_into("<H", image, hdr.pbase, 0x7000)      # top object size
    with pytest.raises(ImageError, match="past the image end"):
        disassemble_image(bytes(image))


def test_bytes_that_do_not_decode_are_dumped_not_fatal():
    image = bytearray(IMAGES["pasm_demo"].read_bytes())
    listing = analyse_image(bytes(image))
    last = listing.objects[0x138].methods[-1]          # blinker's `running`
    image[last.end - 4] = 0x3B                          # PUSH_IMM4 needing 4 more bytes
    from spinemu.image import image_checksum
    image[5] = image_checksum(bytes(image))
    text = disassemble_image(bytes(image))
    assert f"${last.end - 4:04X}  4 bytes that do not decode" in text


def test_listing_excerpts_in_the_docs_are_current():
    doc = (Path(__file__).resolve().parents[2] / "docs" / "disasm.md").read_text()
    golden = (GOLDEN / "pasm_demo.lst").read_text()
    blocks = doc.split("```")[1::2]
    excerpts = [b.strip("\n") for b in blocks if not b.startswith("python")]
    assert len(excerpts) == 3
    for excerpt in excerpts:
        assert excerpt in golden, excerpt[:80]
