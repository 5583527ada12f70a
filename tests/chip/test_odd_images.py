"""Images a compiler or an accident can make that used to crash a run or a listing.

* A header clock of 0 Hz: OpenSpin 1.00.81 writes it for ``_xinfreq = 0`` (checked
  by hand: ``CON _clkmode = xinput, _xinfreq = 0`` gives ``00 00 00 00`` in the
  header; spinemu's compiler gives the same bytes).  Times then need another
  base: the chip counts them at RCFAST's 12 MHz and says so.
* A method table entry pointing past its object (a corrupted image): the DAT
  range in front of the first method must not run past the image.
"""
import io
import struct

import pytest

from spinemu.analysis.disasm import analyse_image, disassemble_image
from spinemu.chip import Chip
from spinemu.cli import main
from spinemu.compiler import compile_source
from spinemu.image import FALLBACK_CLOCK_HZ, ImageHeader, image_checksum
from spinemu.trace import PinTrace

ZERO_CLOCK = "CON\n  _clkmode = xinput\n  _xinfreq = 0\nPUB main\n  dira[0] := 1\n  outa[0] := 1\n  repeat\n"


def zero_clock_image() -> bytes:
    image = compile_source(ZERO_CLOCK).binary
    assert ImageHeader.parse(image).clkfreq == 0
    return image


def test_an_image_with_a_zero_clock_runs_with_times_counted_at_rcfast():
    result = Chip(zero_clock_image()).run(max_cycles=10_000)
    assert result.trace.clock_hz == FALLBACK_CLOCK_HZ == 12_000_000
    assert any("clock of 0 Hz" in w for w in result.warnings)
    out = io.StringIO()
    result.trace.write_vcd(out)
    assert "$timescale" in out.getvalue()


def test_the_cli_runs_a_zero_clock_image_and_reports_its_time(tmp_path):
    path = tmp_path / "zero.binary"
    path.write_bytes(zero_clock_image())
    out, err = io.StringIO(), io.StringIO()
    code = main(["run", str(path), "--seconds", "0.001", "--trace", str(tmp_path / "z.vcd"), "--no-progress"],
                out, err)
    assert code == 0, err
    assert "12,000 cycles at 12,000,000 Hz" in out.getvalue()
    assert "warning: the image's header gives a clock of 0 Hz" in err.getvalue()


def test_a_trace_needs_a_clock_above_zero():
    with pytest.raises(ValueError, match="above 0 Hz"):
        PinTrace(0)


def _with_method_past_the_image(image: bytes) -> bytes:
    buf = bytearray(image)
    struct.pack_into("<H", buf, 16 + 4, 0x7F00)       # method 1's code offset: far past the object
    buf[5] = image_checksum(bytes(buf))
    return bytes(buf)


def test_a_listing_of_a_method_table_pointing_past_the_image_stays_inside_it():
    image = _with_method_past_the_image(compile_source("DAT\n  long 1, 2\nPUB main\n  outa := 1\n").binary)
    listing = analyse_image(image)
    for obj in listing.objects.values():
        assert obj.dat_start <= obj.dat_end <= len(image)
    assert "Propeller image" in disassemble_image(image)


def test_an_abort_into_a_frame_chain_that_loops_is_a_fault_not_a_hang():
    """The frame's previous-frame word points at itself and no frame catches: the ROM would unwind for ever."""
    from spinemu.diagnostics import EmulationError

    src = ("PUB main\n  word[@result - 4] := @result\n  word[@result - 8] := 0\n  abort 1\n")
    with pytest.raises(EmulationError, match="frame chain that loops") as info:
        Chip(compile_source(src).binary).run(max_cycles=1_000_000)
    assert "cog 0" in info.value.message


def test_a_frame_base_past_ffff_is_kept_to_16_bits_as_the_interpreter_keeps_it():
    """Two bytes of the corrected demo changed (a robustness-fuzzer case): a call then builds its frame
    from a corrupt chain and carried dbase past $FFFF into a hub word (was ValueError)."""
    from pathlib import Path

    image = bytearray((Path(__file__).parent.parent / "data" / "article" / "corrected_stepper_demo.binary")
                      .read_bytes())
    image[73], image[143] = 0x77, 0xC3
    image[5] = image_checksum(bytes(image))
    for blocks in (True, False):
        result = Chip(bytes(image), compile_blocks=blocks).run(max_cycles=200_000)
        assert result.end_cycle <= 200_000
