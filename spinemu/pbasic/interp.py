"""Run a compiled PBASIC program on the emulated BS2 and collect what it did.

The run loop is the hot path: per instruction it charges the timing mode's
cost (realistic mode; pin changes land at the end of the instruction),
calls the instruction body and follows the returned program counter.  The
run ends at END/STOP (or the end of the program), at the time budget, when
the program waits for input that never comes, or after ``max_instructions``
(a loop that never lets time pass in exact timing would otherwise spin
forever).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Union

from ..bench.board import Bench
from ..bench.inputs import PinWaveforms
from ..bench.terminal import screen, stream_text
from ..diagnostics import split_lines
from ..trace import PinTrace
from .compiler import Program
from .machine import CLOCK_HZ, MASK, Machine, StopRun
from .timing import Timing, get_timing

__all__ = ["RunResult", "run_program", "DEFAULT_SECONDS", "DEFAULT_MAX_INSTRUCTIONS"]

#: Budget when neither ``seconds`` nor ``cycles`` is given.
DEFAULT_SECONDS = 10.0
#: Safety net for loops in which no time passes (exact timing).
DEFAULT_MAX_INSTRUCTIONS = 5_000_000


@dataclass
class RunResult:
    """What a run produced.

    Attributes:
        trace: every pin change, 1 cycle = 1 us (``trace.clock_hz`` = 1 MHz), 16 pins.
        debug_output: DEBUG text for a console (CR -> newline).
        debug_bytes: the raw DEBUG byte stream.
        serial_output: ``{pin: bytes}`` sent by SEROUT, decoded.
        warnings: run-time warnings (OPEN behaviours hit, undefined EEPROM reads...).
        end_cycle: the time the run ended, in us.
        reason: "end", "stop", "time", "input" or "instructions".
        ram: the 32 bytes of RAM at the end (INS as the pins read).
        eeprom: the 2048 bytes of EEPROM at the end.
        instructions: how many instructions ran.
    """

    trace: PinTrace
    debug_output: str
    debug_bytes: bytes
    serial_output: dict
    warnings: list
    end_cycle: int
    reason: str
    ram: bytes
    eeprom: bytes
    instructions: int
    timing: str
    program: Program = field(repr=False, default=None)

    @property
    def end_time(self) -> float:
        """Seconds of simulated time covered by the run."""
        return self.end_cycle / CLOCK_HZ

    def var(self, name: str) -> int:
        """The final value of a variable (any RAM name or alias)."""
        sym = self.program.symbols.lookup(name)
        if sym is None or sym.var is None:
            raise KeyError(name)
        v = sym.var
        word = int.from_bytes(self.ram[(v.bitoff >> 4) * 2:(v.bitoff >> 4) * 2 + 2], "little")
        return (word >> (v.bitoff & 15)) & ((1 << v.width) - 1)

    def variables(self) -> dict:
        """``{name: value}`` of every user variable and alias at the end."""
        return {name: self.var(name) for name, *_ in self.program.variables()}

    def debug_screen(self, width: int = 80, height: int = 24) -> list:
        """The Debug Terminal's screen (cursor-control characters honoured)."""
        return screen(self.debug_bytes, width, height)

    def summary(self) -> str:
        t = self.trace
        lines = [f"ran {self.instructions} instructions in {self.end_time:.6f} s "
                 f"({self.timing} timing), stopped: {self.reason}"]
        pins = t.driven_pins()
        if pins:
            counts = t.edge_counts()
            lines.append("pins driven: " + ", ".join(
                f"P{p}({counts.get(p, 0)} edges)" for p in pins))
        for pin, data in sorted(self.serial_output.items()):
            lines.append(f"SEROUT P{pin}: {bytes(data)!r}")
        if self.warnings:
            lines.append(f"{len(self.warnings)} warning(s)")
        return "\n".join(lines)


def run_program(prog: Program, *, seconds: Optional[float] = None, cycles: Optional[int] = None,
                timing: Union[str, Timing] = "exact", inputs: Optional[dict] = None,
                debug_in: Union[str, bytes] = "", serial_in: Optional[dict] = None,
                float_level: int = 0, gosub_model: str = "ring", end_glitch: bool = False,
                max_instructions: int = DEFAULT_MAX_INSTRUCTIONS,
                initial_ram: Optional[bytes] = None, parts=()) -> RunResult:
    """Run ``prog``; see :func:`spinemu.pbasic.run_file` for the arguments."""
    tm = get_timing(timing)
    if gosub_model not in ("ring", "restart"):
        raise ValueError("gosub_model must be 'ring' or 'restart'")
    limit = None
    if seconds is not None:
        limit = int(round(seconds * CLOCK_HZ))
    if cycles is not None:
        limit = cycles if limit is None else min(limit, cycles)
    if limit is None:
        limit = int(DEFAULT_SECONDS * CLOCK_HZ)
    if isinstance(debug_in, str):
        debug_in = debug_in.encode("latin-1", "replace")
    stim = PinWaveforms(inputs or {}, CLOCK_HZ, base=MASK if float_level else 0, pin_count=16, poll_cycles=1)
    m = Machine(prog.eeprom, prog.defined, inputs=stim, float_level=float_level, stimulated=stim.pins,
                limit_us=limit, realistic=tm.realistic, debug_in=debug_in, serial_in=serial_in,
                pin_names={p: n for p, n in prog.pin_names.items()}, n_selects=prog.n_selects,
                gosub_model=gosub_model, end_glitch=end_glitch)
    if initial_ram is not None:
        # Experiments only: a real BS2 clears RAM at reset.  INS/OUTS/DIRS stay 0.
        for wi in range(3, 16):
            m.w[wi] = int.from_bytes(bytes(initial_ram)[2 * wi:2 * wi + 2], "little")
    if parts:
        (parts if isinstance(parts, Bench) else Bench(parts)).attach(m)
        m.parts_attached()
    m.debug_char_us = tm.debug_char_us
    m.eeprom_write_us = tm.eeprom_write_us
    m.path = prog.path
    m.source_lines = split_lines(prog.source)
    code = prog.code
    m.positions = [ins.pos for ins in code]
    fns = [ins.fn for ins in code]
    costs = [tm.cost(ins.kind) for ins in code]
    pc = 0
    count = 0
    reason = "instructions"
    try:
        while count < max_instructions:
            c = costs[pc]
            m.pc = pc
            if c:
                m.advance(c)
            nxt = fns[pc](m)
            pc = pc + 1 if nxt is None else nxt
            count += 1
    except StopRun as stop:
        reason = stop.reason
        count += 1 if reason in ("end", "stop", "input") else 0
    m.trace.end_cycle = m.t
    m.end_run(final=reason in ("end", "stop"))
    return RunResult(
        trace=m.trace,
        debug_output=stream_text(bytes(m.debug_out)),
        debug_bytes=bytes(m.debug_out),
        serial_output={p: bytes(v) for p, v in m.serial_out.items()},
        warnings=m.diagnostics(),
        end_cycle=m.t,
        reason=reason,
        ram=m.ram_bytes(),
        eeprom=bytes(m.eeprom),
        instructions=count,
        timing=tm.name,
        program=prog,
    )
