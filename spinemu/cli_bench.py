"""The bench's part of the command line: ``run --bench/--input/--eeprom-out/--view`` for every engine, and
``trace decode uart|i2c|spi|pwm``.

Only :mod:`spinemu.cli` imports this module.  :class:`RunBench` puts
together what hangs on the pins of one run -- the ``--input`` stimulus
(one parser for every engine), the parts of a ``--bench`` file, the serial
console, the boot EEPROM of a ``.eeprom`` target or ``--eeprom-out`` -- as
one :class:`spinemu.bench.Bench`, attaches it to whichever engine runs the
program, and renders what the parts did.  The library behind it is
:mod:`spinemu.bench`.
"""
from __future__ import annotations

import time

from .diagnostics import SpinError, UsageError

__all__ = ["bench_options", "RunBench", "chip_input_model", "add_decode_parser", "decode_command"]

#: warnings shown per part (the rest are counted)
_WARNINGS_SHOWN = 5


def bench_options(p) -> None:
    """The bench's options of ``spinemu run``."""
    g = p.add_argument_group(
        "bench",
        "Parts on the pins, the same for Propeller and BASIC Stamp programs (see docs/bench.md).")
    g.add_argument("--bench", metavar="FILE",
                   help="put the parts of a bench file (TOML: [[part]] tables) on the pins; the summary says "
                        "what each did, and --trace records the levels they put on the pins")
    g.add_argument("--eeprom-out", metavar="FILE",
                   help="write the boot EEPROM's content at the end of the run (a 24LC256 on P28/P29 holding "
                        "the program, unless the bench file has one); 'spinemu run FILE' boots from it again")
    g.add_argument("--view", action="store_true",
                   help="show the parts live in the terminal as the run goes, in real time")


class RunBench:
    """The bench of one ``spinemu run`` (see the module docstring).

    Args:
        args: the parsed arguments.
        out: the command line's output streams.
        clock_hz: the engine's clock.
        pin_count: 32 (Propeller) or 16 (BASIC Stamp).
        engine: the engine's name in messages.
        eeprom_image: the 32 KB EEPROM form of the program (Propeller; ``None`` on the BASIC Stamp).
        session: the serial console session, if any.
    """

    def __init__(self, args, out, *, clock_hz: int, pin_count: int, engine: str,
                 eeprom_image: bytes | None = None, session=None):
        from .bench import Bench
        from .bench.board import BenchPinError

        self.args, self.out, self.clock_hz, self.pin_count = args, out, clock_hz, pin_count
        self.spec = _parse_spec(args, pin_count, engine)
        if args.bench:
            from .bench.benchfile import load_bench
            self.bench = load_bench(args.bench, pin_count=pin_count, engine=engine)
        else:
            self.bench = Bench()
        self.console = session.console if session is not None else None
        if self.console is not None:
            if max(self.console.tx, self.console.rx) >= pin_count:
                raise UsageError(f"--console-pins: {engine} has pins 0..{pin_count - 1} (the console defaults to "
                                 f"30,31: give --console-pins TX,RX)")
            try:
                self.bench.add(self.console)
            except BenchPinError as e:
                raise UsageError(f"--console-pins: {e}")
        self.eeprom = None
        if eeprom_image is not None:
            boot = [p for p in self.bench.find("eeprom") if (p.scl, p.sda) == (28, 29)]
            if boot:
                self.eeprom = boot[0]
                if not getattr(self.eeprom, "data_given", True):
                    self.eeprom.load(eeprom_image)
            elif args.eeprom_out or args.target.lower().endswith((".eeprom", ".eep")):
                from .bench import I2cEeprom
                self.eeprom = self.bench.add(I2cEeprom(data=eeprom_image))
        elif args.eeprom_out:
            raise UsageError("--eeprom-out: a BASIC Stamp program's EEPROM is its own (result.eeprom); "
                             "put an 'eeprom' part on its pins in a bench file for an I2C EEPROM")
        self.view = _LiveView(self.bench, out, clock_hz) if args.view else None

    @property
    def parts(self) -> list:
        """The parts other than the console (the console has its own summary row)."""
        return [p for p in self.bench.parts if p is not self.console]

    @property
    def active(self) -> bool:
        return bool(self.bench.parts)

    def chip_inputs(self, compat: str):
        """The chip's input model: the pull mode, and the ``--input`` waveforms on top."""
        return _input_model(self.spec, self.args.inputs, compat, self.clock_hz)

    def attach(self, engine) -> None:
        """Put the bench on ``engine`` (before its run)."""
        if self.active:
            self.bench.attach(engine)

    def run_context(self):
        """A context manager around the run (the live view)."""
        import contextlib
        return self.view if self.view is not None else contextlib.nullcontext()

    # ------------------------------------------------------------------ after the run
    def trace(self, trace):
        """The trace to write: with parts, the levels they (and the stimuli) put on the pins are in it."""
        if self.active and self.bench.inputs is not None:
            return self.bench.wire_trace(trace)
        return trace

    def finish(self) -> None:
        if self.args.eeprom_out and self.eeprom is not None:
            try:
                self.eeprom.save_file(self.args.eeprom_out)
            except OSError as e:
                raise SpinError(f"cannot write the EEPROM: {e.strerror or e}", path=self.args.eeprom_out)

    def warnings(self) -> list[str]:
        out = []
        for p in self.parts:
            ws = p.warnings
            out += [str(w) for w in ws[:_WARNINGS_SHOWN]]
            if len(ws) > _WARNINGS_SHOWN:
                out.append(f"{p.name}: {len(ws) - _WARNINGS_SHOWN} more warnings like these")
        return out

    def rows(self) -> list:
        rows = []
        if self.parts:
            rows.append(("parts", "\n".join(p.summary() for p in self.parts)))
        if self.eeprom is not None and self.args.eeprom_out:
            rows.append(("EEPROM", f"saved to {self.args.eeprom_out}"))
        return rows


def _parse_spec(args, pin_count: int, engine: str) -> dict:
    """``--input`` read by the one parser every engine uses (usage errors name the option)."""
    from .bench import parse_input_spec
    from .bench.inputs import InputSpecError

    if not args.stimulus:
        return {}
    try:
        spec = parse_input_spec(args.stimulus)
    except InputSpecError as e:
        raise UsageError(f"--input: {e}")
    bad = [p for p in spec if not 0 <= p < pin_count]
    if bad:
        raise UsageError(f"--input: pin {bad[0]} does not exist on {engine} (pins are 0..{pin_count - 1})")
    return spec


def _input_model(spec: dict, pull, compat: str, clock_hz: int):
    if not spec:
        return pull                               # None: the compat mode's own default
    from .bench import PinWaveforms

    pull = pull or ("pullup" if compat == "spinsim" else "pulldown")
    return PinWaveforms(spec, clock_hz, base=0xFFFFFFFF if pull == "pullup" else 0, pin_count=32)


def chip_input_model(args, clock_hz: int, compat: str):
    """The chip's input model from ``--inputs`` and ``--input`` (for runs without a bench)."""
    return _input_model(_parse_spec(args, 32, "the Propeller"), args.inputs, compat, clock_hz)


class _LiveView:
    """``--view``: the parts' state in the terminal as the run goes, paced to real time."""

    def __init__(self, bench, out, clock_hz: int):
        self.bench, self.out, self.clock_hz = bench, out, clock_hz
        self._live = None
        self._wall0 = None
        self._shown = 0.0
        bench.on_time = self._tick

    def _table(self, cycle: int):
        from rich.table import Table

        table = Table(title=f"{cycle / self.clock_hz:9.3f} s", show_header=False, box=None)
        table.add_column(style="bold")
        table.add_column()
        for name, state in self.bench.view():
            table.add_row(name, state)
        return table

    def __enter__(self):
        from rich.live import Live

        self._live = Live(self._table(0), console=self.out.console, auto_refresh=False, transient=False)
        self._live.__enter__()
        return self

    def __exit__(self, *exc):
        if self._live is not None:
            self._live.update(self._table(self.bench.end_cycle or 0), refresh=True)
            self._live.__exit__(*exc)
            if not self.out.console.is_terminal:
                self.out.console.line()             # the last frame ends without a new line

    def _tick(self, cycle: int) -> None:
        if cycle >= 1 << 62 or self._live is None:
            return
        now = time.monotonic()
        if self._wall0 is None:
            self._wall0 = now
        ahead = cycle / self.clock_hz - (now - self._wall0)
        if ahead > 0:
            time.sleep(min(ahead, 0.5))
        if now - self._shown > 0.05:
            self._shown = now
            self._live.update(self._table(cycle), refresh=True)


# ----------------------------------------------------------------------------- trace decode
def add_decode_parser(ts, parents) -> None:
    """``spinemu trace decode``: its subparser under the trace actions ``ts``."""
    from .cli_console import baud_rate

    dc = ts.add_parser(
        "decode", help="decode a protocol on the pins: uart, i2c, spi, pwm", parents=parents,
        description="Decode a protocol on pins of a trace log. uart: asynchronous serial (8N1) on one pin, as "
                    "text (CR, CR LF and LF as new lines) or, with --frames, one line per byte. i2c: --pins "
                    "SCL,SDA: transfers with address, read/write, data and ACK/NAK. spi: --pins SCLK,MOSI[,MISO"
                    "[,CS]] in --mode 0-3: words. pwm: --pins N: pulse widths and periods. An undriven pin reads "
                    "as the line's idle level (I2C: pulled up). Protocol violations are warnings with their "
                    "cycle. --annotations writes the decoded frames to a text file to read beside the VCD "
                    "(see docs/traces.md).")
    dc.add_argument("protocol", choices=["uart", "i2c", "spi", "pwm"])
    dc.add_argument("file")
    dc.add_argument("--pin", type=int, metavar="N", help="uart: the pin carrying the serial data")
    dc.add_argument("--pins", metavar="LIST", help="the pins, separated by commas: i2c SCL,SDA; "
                                                   "spi SCLK,MOSI[,MISO[,CS]]; pwm N (uart: N, as --pin)")
    dc.add_argument("--baud", type=baud_rate, default=115_200.0, metavar="B",
                    help="uart: bits per second (default 115200)")
    dc.add_argument("--inverted", action="store_true", help="uart: the line idles low and the start bit is high")
    dc.add_argument("--hold-last", action="store_true",
                    help="uart: the line keeps its last level after the trace ends (completes a frame cut by the "
                         "end, e.g. when the program stopped during its last stop bit)")
    dc.add_argument("--frames", action="store_true", help="uart: one line per byte: cycle, time, value, character")
    dc.add_argument("--mode", type=int, choices=[0, 1, 2, 3], default=0, help="spi: CPOL*2+CPHA (default 0)")
    dc.add_argument("--bits", type=int, default=8, metavar="N", help="spi: bits per word (default 8)")
    dc.add_argument("--lsb-first", action="store_true", help="spi: least significant bit first")
    dc.add_argument("--active-low", action="store_true", help="pwm: the pulses are low")
    dc.add_argument("--start", type=int, metavar="CYCLE", help="only frames starting at or after this cycle")
    dc.add_argument("--end", type=int, metavar="CYCLE", help="only frames starting at or before this cycle")
    dc.add_argument("--annotations", metavar="FILE",
                    help="also write the decoded frames to FILE (tab-separated: start and end in seconds and in "
                         "cycles, text), e.g. run.i2c.txt next to run.vcd")


def decode_command(args, trace, out) -> int:
    """``trace decode``: dispatch on the protocol."""
    from .bench.annotations import write_annotations
    from .bench.levels import parse_pin_list

    pins = None
    if args.pins is not None:
        try:
            pins = parse_pin_list(args.pins, trace.pin_count)
        except ValueError as e:
            raise UsageError(f"--pins: {e}")
    if args.protocol == "uart":
        if args.pin is None and pins:
            args.pin = pins[0]
        from .cli_console import decode_uart_frames
        frames = decode_uart_frames(args, trace, out)
    else:
        want = {"i2c": (2, 2, "SCL,SDA"), "spi": (2, 4, "SCLK,MOSI[,MISO[,CS]]"), "pwm": (1, 1, "N")}[args.protocol]
        if pins is None or not want[0] <= len(pins) <= want[1]:
            raise UsageError(f"trace decode {args.protocol} needs --pins {want[2]}")
        frames = _DECODERS[args.protocol](args, trace, pins, out)
    if args.annotations:
        from .cli import _write_atomic
        _write_atomic(args.annotations, lambda f: write_annotations(f, frames, trace.clock_hz, args.protocol,
                                                                   pins or [args.pin]), False)
    return 0


def _window(args, frames):
    lo = args.start if args.start is not None else 0
    hi = args.end if args.end is not None else 1 << 62
    return [f for f in frames if lo <= f[0] <= hi]


def _print_frames(out, frames, clock_hz: int) -> None:
    from .analysis.view import format_time
    for start, end, text in frames:
        out.stdout.write(f"{start:>12} {format_time(start, clock_hz):>12}  {text}\n")


def _violations(out, violations, clock_hz: int) -> None:
    from .analysis.view import format_time
    for cycle, message in violations[:_WARNINGS_SHOWN]:
        out.warn(f"warning: {message} (at cycle {cycle}, {format_time(cycle, clock_hz)})")
    if len(violations) > _WARNINGS_SHOWN:
        out.warn(f"warning: {len(violations) - _WARNINGS_SHOWN} more protocol violations")


def _decode_i2c(args, trace, pins, out) -> list:
    from .bench.i2c import decode_i2c

    d = decode_i2c(trace, pins[0], pins[1])
    frames = _window(args, [(t.start, t.end if t.end is not None else trace.end_cycle,
                             ("Sr " if t.restart else "S ") + t.text() + (" P" if t.stopped else ""))
                            for t in d.transfers])
    _print_frames(out, frames, trace.clock_hz)
    _violations(out, d.violations, trace.clock_hz)
    return frames


def _decode_spi(args, trace, pins, out) -> list:
    from .bench.spi import decode_spi

    sclk, mosi = pins[0], pins[1]
    miso = pins[2] if len(pins) > 2 else None
    cs = pins[3] if len(pins) > 3 else None
    try:
        d = decode_spi(trace, sclk, mosi, miso, cs, mode=args.mode, bits=args.bits, lsb_first=args.lsb_first)
    except ValueError as e:
        raise UsageError(str(e))
    frames = _window(args, [(w.start, w.end, w.text()) for w in d.words])
    _print_frames(out, frames, trace.clock_hz)
    _violations(out, d.violations, trace.clock_hz)
    return frames


def _decode_pwm(args, trace, pins, out) -> list:
    from .bench.pwm import decode_pulses

    d = decode_pulses(trace, pins[0], active=0 if args.active_low else 1)
    hz = trace.clock_hz
    frames = []
    for p in d.pulses:
        text = f"width {p.width / hz * 1e3:.4f} ms"
        if p.period:
            text += f", period {p.period / hz * 1e3:.4f} ms, duty {100 * p.duty:.2f} %"
        frames.append((p.start, p.end, text))
    frames = _window(args, frames)
    _print_frames(out, frames, hz)
    return frames


_DECODERS = {"i2c": _decode_i2c, "spi": _decode_spi, "pwm": _decode_pwm}
