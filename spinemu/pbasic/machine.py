"""The BASIC Stamp 2 machine: 32 bytes of RAM, 16 pins, 2 KB EEPROM, a clock.

Time base: spinemu counts BS2 time in microseconds.  One trace "cycle" is
1 us (``CLOCK_HZ`` = 1 MHz): every duration the BS2 documents is a whole
number of microseconds (PULSOUT/PULSIN/RCTIME count 2 us units, serial bit
times are ``baudmode + 20`` us, PAUSE counts ms), so nothing is rounded.

RAM is 16 words (``w[0]`` = INS, ``w[1]`` = OUTS, ``w[2]`` = DIRS,
``w[3..15]`` = W0..W12); variables are (bit offset, width) views into it
(README 1.1).  ``w[0]`` is never stored: :meth:`Machine.ins` computes INS from
the pins.  A pin is driven to its OUTS bit when its DIRS bit is 1; the
recorded trace holds ``(t, DIRS, OUTS & DIRS)`` after every change, the
format of the Spin side (:class:`spinemu.trace.PinTrace`, 16 pins).

Undriven pins read the input model (:mod:`spinemu.bench.inputs`: the
``inputs`` levels of a run, parts on the pins).  The machine offers the
bench's engine interface (``clock_hz``, ``pin_count``, ``inputs``,
``drive_history``, ``add_pin_listener``), so the same parts as on the
Propeller hang on its pins (:mod:`spinemu.bench`).

Hot path: :meth:`pins_changed` and :meth:`advance` run on every pin write and
every timed command.
"""
from __future__ import annotations

from collections import deque
from typing import Optional

from ..bench.history import TraceHistory
from ..diagnostics import Diagnostic
from ..trace import PinTrace
from . import messages as M

__all__ = ["Machine", "StopRun", "CLOCK_HZ", "MASK"]

CLOCK_HZ = 1_000_000
MASK = 0xFFFF
_NEVER = 1 << 62


class StopRun(Exception):
    """Raised inside the run loop to end the run (END, STOP, budget, input)."""

    def __init__(self, reason: str):
        super().__init__(reason)
        self.reason = reason


class Machine:
    """State of one running BS2.

    Args:
        eeprom: 2048 bytes as downloaded (DATA; program area zero).
        defined: 2048 flags, 1 where DATA defined the byte.
        inputs: the input model: what undriven pins read (levels over microseconds).
        float_level: what a pin no stimulus or part drives reads (for warnings).
        stimulated: the pins the run's ``inputs`` levels name (bit mask).
        limit_us: stop when the clock would pass this time (None: no limit).
        realistic: charge interpreter time per instruction (see :mod:`.timing`).
        debug_in: bytes typed into the DEBUG terminal (DEBUGIN, SERIN 16).
        serial_in: ``{pin: bytes}`` that a device sends when SERIN listens.
    """

    clock_hz = CLOCK_HZ
    pin_count = 16

    def __init__(self, eeprom: bytes, defined: bytes, *, inputs, float_level: int = 0, stimulated: int = 0,
                 limit_us: Optional[int], realistic: bool, debug_in: bytes = b"",
                 serial_in: Optional[dict] = None, pin_names: Optional[dict] = None,
                 n_selects: int = 0, gosub_model: str = "ring", end_glitch: bool = False,
                 program_start: int = 0):
        self.w = [0] * 16
        self.t = 0
        self.limit = limit_us
        self.realistic = realistic
        self.inputs = inputs
        self.float_level = 1 if float_level else 0
        self._stimulated = stimulated & MASK
        self.eeprom = bytearray(eeprom)
        self.defined = bytearray(defined)
        self.ee_writes: dict[int, int] = {}
        self.trace = PinTrace(CLOCK_HZ, pin_count=16, pin_names=dict(pin_names or {}))
        self.trace.record(0, 0, 0)
        self.debug_out = bytearray()
        self.serial_out: dict[int, bytearray] = {}
        self.debug_in = deque(debug_in)
        self.serial_in = {int(p): deque(bytes(v, "latin-1") if isinstance(v, str) else bytes(v))
                          for p, v in (serial_in or {}).items()}
        self.sel = [0] * n_selects
        self.gosub_slots = [0] * 4
        self.gosub_ptr = 0
        self.gosub_depth = 0
        self.gosub_model = gosub_model
        self.end_glitch = end_glitch
        self.program_start = program_start
        self.halted: Optional[str] = None
        self.debug_char_us = 0.0        # set from the timing mode by the run loop
        self.eeprom_write_us = 0
        # (line, column, message) -> [count, Diagnostic prototype fields]
        self._warnings: dict[tuple, list] = {}
        self.path = "<input>"
        self.source_lines: list[str] = []
        self.pc = 0                      # the running instruction (set by the run loop)
        self.positions: list = []        # source position of each instruction
        # pins that float when undriven: no stimulus and no part (set again once parts are attached)
        self.unstimulated = ~self._stimulated & MASK
        self.drive_history = TraceHistory(self.trace.changes)
        self.pin_listeners: list = []
        self._listen_step = 0
        self._listen_at = _NEVER
        self._listen_from = 0

    # ------------------------------------------------------------ bench engine interface
    def add_pin_listener(self, listener, interval_cycles: Optional[int] = None) -> None:
        """Call ``listener(changes, upto, present)`` as the run goes (see :mod:`spinemu.bench`).

        ``changes`` are the pin states before ``upto`` since the last call;
        the BS2 reads its pins at its present, so ``present`` is ``upto``.
        """
        step = max(1, int(interval_cycles or CLOCK_HZ // 100))
        self.pin_listeners.append(listener)
        self._listen_step = min(self._listen_step, step) if self._listen_step else step
        self._listen_at = min(self._listen_at, self.t + self._listen_step)

    def parts_attached(self) -> None:
        """The bench is attached: the pins it drives no longer float."""
        self.unstimulated = ~(self._stimulated | int(getattr(self.inputs, "mask", 0) or 0)) & MASK

    def _deliver(self, upto: int) -> None:
        changes = self.trace.changes
        n = len(changes)
        k = self._listen_from
        while k < n and changes[k][0] < upto:
            k += 1
        new = changes[self._listen_from:k]
        self._listen_from = k
        for listener in self.pin_listeners:
            listener(new, upto, upto if upto < _NEVER else self.t + 1)

    def _time_passes(self, t: int) -> None:
        """Time goes from now to ``t`` with no pin change: the listeners see it in steps."""
        at = self._listen_at
        while at <= t:
            self._deliver(at)
            at += self._listen_step
        self._listen_at = at

    def end_run(self, final: bool) -> None:
        """After the run: the last listener calls (``final``: nothing will change the pins any more)."""
        if not self.pin_listeners:
            return
        self._deliver(_NEVER if final else self.t + 1)
        for listener in self.pin_listeners:
            ended = getattr(listener, "run_ended", None)
            if ended is not None:
                ended(self.t)

    # ------------------------------------------------------------ pins
    def ins(self) -> int:
        """INS: driven level of outputs, the input model's level of inputs."""
        d = self.w[2]
        return ((self.w[1] & d) | (self.inputs.levels(self.t) & ~d)) & MASK

    def pin_level(self, pin: int) -> int:
        bit = 1 << pin
        if self.w[2] & bit:
            return 1 if self.w[1] & bit else 0
        return self.input_level(pin)

    def input_level(self, pin: int) -> int:
        """The level an input pin reads now ([OPEN] an unstimulated pin floats)."""
        if self.unstimulated >> pin & 1:
            self.float_warning(1 << pin)
        return (self.inputs.levels(self.t) >> pin) & 1

    def wait_input(self, pin: int, level: int, deadline: Optional[int]) -> Optional[int]:
        """Let time pass until input ``pin`` reads ``level``; the time it does, or None at ``deadline``.

        Without a deadline and with nothing to change the pin, the run ends
        (``StopRun("input")``) at the time limit.
        """
        inputs = self.inputs
        if self.unstimulated >> pin & 1:
            self.float_warning(1 << pin)
        while (inputs.levels(self.t) >> pin) & 1 != level:
            nxt = inputs.next_change(self.t)
            if nxt is not None and self.pin_listeners and nxt > self._listen_at:
                nxt = self._listen_at            # listeners may send input meanwhile
            if nxt is None or (deadline is not None and nxt > deadline):
                if deadline is None:
                    self.advance_to(self.limit if self.limit is not None else self.t)
                    raise StopRun("input")
                self.advance_to(deadline)
                return None
            self.advance_to(nxt)
        return self.t

    def input_edges(self, pin: int, start: int, end: int) -> list:
        """Times in ``(start, end]`` at which input ``pin`` changes level (time does not pass)."""
        inputs = self.inputs
        out = []
        t = start
        level = (inputs.levels(t) >> pin) & 1
        while True:
            t = inputs.next_change(t)
            if t is None or t > end:
                return out
            now = (inputs.levels(t) >> pin) & 1
            if now != level:
                out.append(t)
                level = now

    def float_warning(self, pins_mask: int, pos=None) -> None:
        pins = [p for p in range(16) if pins_mask >> p & 1]
        self.warn(pos or self.here(), M.W_FLOATING.format(
                      ", ".join(f"P{p}" for p in pins), "s" if len(pins) > 1 else "",
                      "" if len(pins) > 1 else "s", self.float_level))

    def here(self):
        """Source position of the running instruction."""
        return self.positions[self.pc] if 0 <= self.pc < len(self.positions) else None
    def pins_changed(self) -> None:
        """Record the pin state at the current time (no-op if unchanged)."""
        d = self.w[2]
        self.trace.record(self.t, d, self.w[1] & d)

    def set_pin(self, pin: int, *, out: Optional[int] = None, output: Optional[bool] = None) -> None:
        """Change one pin's OUTS and/or DIRS bit and record the change."""
        bit = 1 << pin
        if out is not None:
            self.w[1] = (self.w[1] | bit) if out else (self.w[1] & ~bit)
        if output is not None:
            self.w[2] = (self.w[2] | bit) if output else (self.w[2] & ~bit)
        self.pins_changed()

    # ------------------------------------------------------------ time
    def advance(self, us: int) -> None:
        """Let ``us`` microseconds pass; stop the run at the time limit."""
        t = self.t + us
        if self.limit is not None and t > self.limit:
            if self.limit >= self._listen_at:
                self._time_passes(self.limit)
            self.t = self.limit
            raise StopRun("time")
        if t >= self._listen_at:
            self._time_passes(t)
        self.t = t

    def advance_to(self, t: int) -> None:
        if t > self.t:
            self.advance(t - self.t)

    def wait_forever(self, what: str, pos) -> None:
        """Block for good (SERIN without data and without timeout)."""
        self.warn(pos, M.W_INPUT_WAIT.format(what))
        if self.limit is not None:
            self.advance_to(self.limit)
        raise StopRun("input")

    # ------------------------------------------------------------ EEPROM
    def ee_read(self, addr: int, pos) -> int:
        addr &= 0x7FF
        if not self.defined[addr]:
            self.warn(pos, M.W_EEPROM_UNDEFINED.format(addr, self.eeprom[addr]))
        return self.eeprom[addr]

    def ee_write(self, addr: int, value: int, pos) -> None:
        addr &= 0x7FF
        self.eeprom[addr] = value & 0xFF
        self.defined[addr] = 1
        n = self.ee_writes.get(addr, 0) + 1
        self.ee_writes[addr] = n
        if n in (100_000, 1_000_000):
            self.warn(pos, M.W_EEPROM_WEAR.format(addr, n))

    # ------------------------------------------------------------ serial
    def emit(self, pin: int, data: bytes) -> None:
        if pin == 16:
            self.debug_out += data
        else:
            self.serial_out.setdefault(pin, bytearray()).extend(data)

    # ------------------------------------------------------------ warnings
    def warn(self, pos, message: str) -> None:
        """A run-time warning at a source position (counted, reported once)."""
        key = (pos.line if pos else None, pos.column if pos else None, message)
        entry = self._warnings.get(key)
        if entry is None:
            self._warnings[key] = [1, self.t, pos]
        else:
            entry[0] += 1

    def diagnostics(self) -> list[Diagnostic]:
        out = []
        for (line, col, msg), (count, first_t, pos) in self._warnings.items():
            text = msg
            text += f" (at {first_t / CLOCK_HZ:.6f} s"
            text += f", {count} times)" if count > 1 else ")"
            src = self.source_lines[line - 1] if line and 0 < line <= len(self.source_lines) else None
            out.append(Diagnostic(text, self.path, line, col, src, "warning",
                                  pos.length if pos else 1))
        return out

    # ------------------------------------------------------------ RAM views
    def ram_bytes(self) -> bytes:
        words = list(self.w)
        words[0] = self.ins()
        return b"".join(v.to_bytes(2, "little") for v in words)

    def read_bits(self, bitoff: int, width: int) -> int:
        wi, sh = bitoff >> 4, bitoff & 15
        word = self.ins() if wi == 0 else self.w[wi]
        return (word >> sh) & ((1 << width) - 1)
