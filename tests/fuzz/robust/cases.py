"""One robustness case from one seed: the files to write and the command lines to run.

A case is an input a new user might have (a mutated Spin source, an odd Spin
program, a corrupted image, a mutated BASIC Stamp program, a mutated trace
log) and one to three ``spinemu`` command lines that use it, or a random
command line built from ``spinemu``'s own argument parser (every command and
subcommand, with nan/inf/negative/huge numbers, bad pin specs, missing files,
folders, unsupported extensions).  Command lines name files as ``{dir}/...``;
the runner puts its work folder there.  Runs always carry a cycle budget
(``--cycles``/``--seconds``) unless their program stops by itself.

``make_case(seed)`` is a pure function of the seed (and of the repository's
files): the same seed gives the same case on every machine.
"""
from __future__ import annotations

import argparse
import random
import struct
from dataclasses import dataclass, field
from functools import lru_cache

from . import corpus
from .mutate import PBASIC, SPIN, encode, flip_bytes, mutate_text, odd_number
from .snippets import spin_program

__all__ = ["Case", "KINDS", "make_case"]


@dataclass
class Case:
    """Files to write into the work folder and the command lines to run there.

    Attributes:
        seed: the case's seed (``make_case(seed)`` rebuilds it).
        kind: which generator made it.
        origin: what it started from (a repository file, a template).
        files: ``{name: bytes}`` written into the work folder first.
        commands: argv lists; ``{dir}`` stands for the work folder.
        python_dirs: folders (``{dir}/...``) whose generated ``.py`` files must compile.
    """

    seed: int
    kind: str
    origin: str
    files: dict = field(default_factory=dict)
    commands: list = field(default_factory=list)
    python_dirs: list = field(default_factory=list)
    forced: bool = False    # made with an explicit kind (a reproduction must name it too)


# ----------------------------------------------------------------------------- small terminating programs
STOP_SPIN = "PUB main\n  dira[0..3] := %1111\n  outa[0..3] := %1010\n"
STOP_BS2 = "' {$STAMP BS2}\n' {$PBASIC 2.5}\nHIGH 1\nPAUSE 5\nLOW 1\nEND\n"
LOG = "4 00000000 00000000\n1000 0000001e 00000000\n2000 0000001e 00000002\n3000 0000001e 00000006\n" \
      "4000 0000001e 0000000c\n5000 0000001e 00000008\n"


@lru_cache(maxsize=None)
def _stop_image() -> bytes:
    """The image of :data:`STOP_SPIN` (compiled once per process)."""
    import os
    import tempfile

    from spinemu.compiler import compile_file

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "stop.spin")
        with open(path, "w") as fh:
            fh.write(STOP_SPIN)
        return compile_file(path).binary


def _cycles(rng: random.Random) -> list:
    if rng.random() < 0.8:
        return ["--cycles", str(rng.choice([1, 100, 5_000, 50_000, 200_000]))]
    return ["--seconds", rng.choice(["0.0001", "0.001", "1e-9", "0.002"])]


def _run_options(rng: random.Random, spin: bool = True) -> list:
    out = ["--no-progress"]
    if rng.random() < 0.5:
        out.append("-q")
    if spin and rng.random() < 0.2:
        out += ["--compat", "chip"]
    if spin and rng.random() < 0.1:
        out += ["--inputs", rng.choice(["pullup", "pulldown"])]
    if rng.random() < 0.25:
        out += ["--trace", "{dir}/" + rng.choice(["t.log", "t.vcd", "t.LOG", "t"])]
    if rng.random() < 0.15:
        out += ["--input", _stimulus(rng, 32 if spin else 16)]
    if spin and rng.random() < 0.1:
        out += ["--dump-hub", "{dir}/hub.bin"]
    if spin and rng.random() < 0.1:
        out += _console_options(rng)
    return out


def _console_options(rng: random.Random) -> list:
    """The serial console of a Spin run, with odd values now and then."""
    out = []
    if rng.random() < 0.5:
        out += ["--baud", rng.choice(["9600", "115200", "1", "0", "-5", "nan", "1e9", "300", "2000000"])]
    if rng.random() < 0.4:
        out += ["--console-out", "{dir}/" + rng.choice(["c.txt", "nodir/c.txt", ""])]
    if rng.random() < 0.3:
        out += ["--console-in", "{dir}/" + rng.choice(["in.txt", "missing.txt", ""])]
        if rng.random() < 0.5:
            out += ["--console-in-at", rng.choice(["0", "0.001", "-1", "nan", "inf", "1e300"])]
    if rng.random() < 0.3:
        out += ["--console-pins", rng.choice(["30,31", "0,1", "31,31", "32,1", "x", "1", "-1,2"])]
    if rng.random() < 0.2:
        out.append("--console")
    return out or ["--console-out", "{dir}/c.txt"]


def _stimulus(rng: random.Random, pins: int) -> str:
    def one():
        pin = rng.choice([str(rng.randrange(pins)), f"P{rng.randrange(pins)}", str(pins), "-1", "P", "x",
                          "99999999999999999999", "p3"])
        if rng.random() < 0.4:
            return f"{pin}={rng.choice(['1', '0', '2', '-1', '', 'x', 'nan'])}"
        steps = ",".join(f"{rng.choice(['0', '1', '5', ''])}@{rng.choice(['0', '0.5', '1e-3', 'nan', 'inf', '-1', '1e308', '-inf', '', 'x', '1e-320'])}"
                         for _ in range(rng.randrange(1, 4)))
        return f"{pin}={steps}"

    return ";".join(one() for _ in range(rng.randrange(1, 3)))


# ----------------------------------------------------------------------------- Spin sources
def _spin_commands(rng: random.Random, name: str, include: list, count: int) -> tuple:
    """Command lines that use the Spin source ``{dir}/name``; also which folders get Python."""
    src = "{dir}/" + name
    inc = [x for d in include for x in ("-L", d)]
    commands, pydirs = [], []
    for verb in rng.sample(["compile", "run", "disasm", "translate", "run"], count):
        if verb == "compile":
            extra = rng.choice([[], ["-o", "{dir}/out.binary"], ["-e", "{dir}/out.eeprom"],
                                ["--listing", "{dir}/out.lst", "-o", "{dir}/out.binary"], ["-q"]])
            commands.append(["compile", src] + extra + inc)
        elif verb == "run":
            engine = ["--engine", "python"] if rng.random() < 0.25 else []
            commands.append(["run", src] + _cycles(rng) + _run_options(rng) + engine + inc)
        elif verb == "disasm":
            commands.append(["disasm", src] + inc + (["-o", "{dir}/out.txt"] if rng.random() < 0.3 else []))
        else:
            if rng.random() < 0.2:
                commands.append(["translate", src, "--side-by-side"] + inc)
            else:
                commands.append(["translate", src, "-o", "{dir}/py"] + inc)
                pydirs.append("{dir}/py")
    return commands, pydirs


def _spin_mutant(rng: random.Random, seed: int) -> Case:
    rel, data = rng.choice(corpus.spin_sources())
    text = data.decode("utf-8", "replace") if not data.startswith((b"\xff\xfe", b"\xfe\xff")) else \
        data.decode("utf-16", "replace")
    text = mutate_text(rng, text, SPIN, "spin")
    name = rel.rsplit("/", 1)[-1]
    folder = str(corpus.ROOT / rel.rsplit("/", 1)[0])
    commands, pydirs = _spin_commands(rng, name, [folder], rng.choice([1, 1, 2, 3]))
    return Case(seed, "spin-mutant", rel, {name: encode(rng, text)}, commands, pydirs)


def _spin_snippet(rng: random.Random, seed: int) -> Case:
    text, children = spin_program(rng)
    if rng.random() < 0.3:
        text = mutate_text(rng, text, SPIN, "spin")
    files = {"odd.spin": encode(rng, text) if rng.random() < 0.3 else text.encode("utf-8", "surrogatepass")}
    for child, body in children.items():
        files[child] = body.encode()
    commands, pydirs = _spin_commands(rng, "odd.spin", [], rng.choice([1, 2, 3]))
    return Case(seed, "spin-snippet", "snippets.spin_program", files, commands, pydirs)


def _translate(rng: random.Random, seed: int) -> Case:
    """Odd sources through the translator: the generated modules must compile, then run."""
    if rng.random() < 0.6:
        text, children = spin_program(rng)
        origin = "snippets.spin_program"
    else:
        rel, data = rng.choice(corpus.spin_sources())
        text, children, origin = data.decode("utf-8", "replace"), {}, rel
        text = mutate_text(rng, text, SPIN, "spin", rounds=1) if rng.random() < 0.5 else text
    files = {"odd.spin": text.encode("utf-8", "surrogatepass")}
    files.update({c: b.encode() for c, b in children.items()})
    inc = [] if origin.startswith("snippets") else ["-L", str(corpus.ROOT / origin.rsplit("/", 1)[0])]
    commands = [["translate", "{dir}/odd.spin", "-o", "{dir}/py"] + inc]
    if rng.random() < 0.4:
        commands.append(["run", "{dir}/odd.spin", "--engine", "python", "--cycles",
                         str(rng.choice([1_000, 20_000, 100_000])), "--no-progress", "-q"] + inc)
    return Case(seed, "translate", origin, files, commands, ["{dir}/py"])


# ----------------------------------------------------------------------------- images
_FIELDS = {"clkfreq": (0, "<I"), "clkmode": (4, "<B"), "checksum": (5, "<B"), "pbase": (6, "<H"),
           "vbase": (8, "<H"), "dbase": (10, "<H"), "pcurr": (12, "<H"), "dcurr": (14, "<H")}


def _fix_checksum(buf: bytearray) -> None:
    from spinemu.image import image_checksum

    if len(buf) >= 16:
        vbase = struct.unpack_from("<H", buf, 8)[0]
        body = bytes(buf[:vbase]) if 16 < vbase <= len(buf) else bytes(buf)
        buf[5] = image_checksum(body)


def _mutate_image(rng: random.Random, data: bytes) -> tuple:
    buf = bytearray(data)
    what = []
    for _ in range(rng.choice([1, 1, 2, 3])):
        pick = rng.random()
        if pick < 0.4 and len(buf) >= 16:
            name = rng.choice(list(_FIELDS))
            at, fmt = _FIELDS[name]
            top = 0xFF if fmt == "<B" else 0xFFFF if fmt == "<H" else 0xFFFFFFFF
            value = rng.choice([0, 1, 2, 3, 4, 8, 15, 16, 17, len(buf) - 1, len(buf), len(buf) + 1, 0x7FFF,
                                0x8000, 0x8001, 0xFFFF, top, rng.randrange(top + 1), rng.randrange(64)]) & top
            struct.pack_into(fmt, buf, at, value)
            what.append(f"{name}={value}")
        elif pick < 0.7:
            buf = bytearray(flip_bytes(rng, bytes(buf[:16]), 0) + flip_bytes(rng, bytes(buf[16:]))) \
                if rng.random() < 0.2 else bytearray(buf[:16] + flip_bytes(rng, bytes(buf[16:])))
            what.append("bytes")
        elif pick < 0.8 and len(buf) > 16:
            base = 16
            at = base + rng.randrange(min(64, len(buf) - base))
            buf[at] = rng.choice([0, 1, 0xFF, 0x7F, 0x80, rng.randrange(256)])
            what.append(f"table@{at}")
        elif pick < 0.9:
            buf = buf[: rng.randrange(len(buf) + 1)]
            what.append("truncated")
        else:
            buf += bytes(rng.randrange(256) for _ in range(rng.choice([1, 4, 100, 40000])))
            what.append("extended")
    if rng.random() < 0.8:
        _fix_checksum(buf)
    return bytes(buf), ",".join(what)


def _image(rng: random.Random, seed: int) -> Case:
    if rng.random() < 0.08:
        data = bytes(rng.randrange(256) for _ in range(rng.choice([0, 1, 15, 16, 17, 100, 32768, 40000])))
        origin, how = "random bytes", ""
        if rng.random() < 0.5 and len(data) >= 16:
            data = bytearray(data)
            struct.pack_into("<HHHHH", data, 6, 16, min(len(data), rng.randrange(17, 0x8000)),
                             rng.randrange(0x8000), rng.randrange(17, 0x8000), rng.randrange(0x8000))
            _fix_checksum(data)
            data = bytes(data)
    else:
        if rng.random() < 0.15:
            origin, data = "STOP_SPIN", _stop_image()
        else:
            origin, data = rng.choice(corpus.images())
        if rng.random() < 0.15 and not origin.endswith(".eeprom"):
            from spinemu.image import to_eeprom
            try:
                data = to_eeprom(data)
            except Exception:  # noqa: BLE001 - an image that has no EEPROM form stays a binary
                pass
        data, how = _mutate_image(rng, data)
    name = "img" + rng.choice([".binary", ".binary", ".eeprom", ".bin", ".eep", ".BINARY"])
    commands = []
    for verb in rng.sample(["run", "disasm", "run"], rng.choice([1, 2])):
        if verb == "run":
            commands.append(["run", "{dir}/" + name] + _cycles(rng) + _run_options(rng))
        else:
            commands.append(["disasm", "{dir}/" + name] + (["-o", "{dir}/d.txt"] if rng.random() < 0.2 else []))
    return Case(seed, "image", f"{origin} {how}".strip(), {name: data}, commands)


# ----------------------------------------------------------------------------- BASIC Stamp
def _pbasic(rng: random.Random, seed: int) -> Case:
    origin, text = rng.choice(corpus.pbasic_programs())
    lines = text.splitlines(keepends=True)
    head, keep = [], rng.random() < 0.7
    while keep and len(head) < len(lines) and lines[len(head)].lstrip().startswith("' {$"):
        head.append(lines[len(head)])           # mostly keep the directives, so the body gets run
    text = "".join(head) + mutate_text(rng, "".join(lines[len(head):]), PBASIC, "pbasic")
    name = "prog" + rng.choice([".bs2", ".bs2", ".bs1", ".pbasic", ".bas", ".BS2"])
    commands = []
    for _ in range(rng.choice([1, 1, 2])):
        argv = ["run", "{dir}/" + name, "--seconds", rng.choice(["0.01", "0.1", "0.5", "1e-6"])] + \
               _run_options(rng, spin=False)
        if rng.random() < 0.3:
            argv += ["--timing", rng.choice(["exact", "realistic"])]
        if rng.random() < 0.3:
            argv += ["--debug-in", rng.choice(["12\r", "abc", "", "\x00\xff", "9" * 50, "\r\r\r"])]
        commands.append(argv)
    return Case(seed, "pbasic", origin, {name: encode(rng, text) if rng.random() < 0.1 else text.encode()},
                commands)


# ----------------------------------------------------------------------------- trace logs
def _mutate_log(rng: random.Random, text: str) -> str:
    lines = text.splitlines()[: rng.choice([5, 50, 400, 2000])]
    for _ in range(rng.choice([0, 1, 2, 4])):
        if not lines:
            break
        i = rng.randrange(len(lines))
        pick = rng.random()
        parts = lines[i].split()
        if pick < 0.3 and parts:
            parts[rng.randrange(len(parts))] = rng.choice(["-1", "0", "nan", "ffffffffff", "1" * 40, "x", "",
                                                           "-ffffffff", "1e5", "0x10", odd_number(rng)])
            lines[i] = " ".join(parts)
        elif pick < 0.5:
            lines.insert(i, lines[i])
        elif pick < 0.6:
            lines[i], lines[-1] = lines[-1], lines[i]
        elif pick < 0.7:
            lines[i] = rng.choice(["# comment", "", "$var wire 1 ! p0 $end", "\x00", "1 2", "1 2 3 4"])
        else:
            del lines[i]
    return "\n".join(lines) + rng.choice(["\n", ""])


def _trace(rng: random.Random, seed: int) -> Case:
    origin, text = rng.choice(corpus.trace_logs() + (("LOG", LOG),))
    a, b = _mutate_log(rng, text), _mutate_log(rng, text) if rng.random() < 0.5 else text
    files = {"a.log": a.encode("utf-8", "surrogatepass"), "b.log": b.encode("utf-8", "surrogatepass")}
    pins = lambda: rng.choice(["0..4", "1..4", "4..7", "4..1,0", "31..0", "0", "", "..", "5..", "1,,2",  # noqa: E731
                               "0..32", "-1", "x", "1..1000000000", "0..99999999999999", "3,3,3,3",
                               "1..4,", "１..４"])
    clock = lambda: ["--clock", rng.choice(["80_000_000", "1_000_000", "1", "0", "-5", "nan", "1e9", "inf"])] \
        if rng.random() < 0.3 else []  # noqa: E731
    window = lambda: [x for flag in ("--start", "--end") if rng.random() < 0.2  # noqa: E731
                      for x in (flag, rng.choice(["0", "-100", "1000", "99999999999999999999", "5", "x"]))]
    action = rng.choice(["show", "compare", "convert", "plot", "steps", "sidebyside", "show", "steps", "decode"])
    if action == "compare":
        argv = ["trace", "compare", "{dir}/a.log", "{dir}/b.log"] + clock()
        if rng.random() < 0.3:
            argv += ["--until", rng.choice(["1000", "0", "-1", "nan"])]
        if rng.random() < 0.3:
            argv += ["--tolerance", rng.choice(["0", "nan", "inf", "-1", "0.5", "1e308"])]
        if rng.random() < 0.3:
            argv += ["--slack", rng.choice(["0", "-1", "100", "99999999999999999999"])]
    elif action == "sidebyside":
        argv = ["sidebyside", "{dir}/a.log", "{dir}/b.log", "--left-pins", pins(), "--right-pins", pins()]
        if rng.random() < 0.3:
            argv += ["--steps", rng.choice(["1", "10", "0", "-3", "nan"])]
    elif action == "show":
        argv = ["trace", "show", "{dir}/a.log"] + (["--pins", pins()] if rng.random() < 0.7 else []) + \
            clock() + window()
        if rng.random() < 0.3:
            argv += ["--width", rng.choice(["1", "2", "64", "0", "100000", "-1"])]
        if rng.random() < 0.3:
            argv += ["--changes", rng.choice(["1", "5", "0", "-5", "100000"])]
    elif action == "decode":
        argv = ["trace", "decode", "uart", "{dir}/a.log", "--pin", rng.choice(["1", "2", "0", "31", "32", "-1", "x"])]
        argv += ["--baud", rng.choice(["9600", "1000000", "1", "0", "nan", "1e12", "-3"])] if rng.random() < 0.7 else []
        argv += [f for f in ("--inverted", "--hold-last", "--frames") if rng.random() < 0.3] + clock() + window()
    elif action == "convert":
        argv = ["trace", "convert", "{dir}/a.log", "-o", "{dir}/" + rng.choice(["a.vcd", "a", "a.log"])] + clock()
    elif action == "plot":
        argv = ["trace", "plot", "{dir}/a.log", "-o", "{dir}/" + rng.choice(["a.png", "a.svg", "a.pdf", "a.xyz",
                                                                             "a", "a.PNG", "a.jpg"])]
        argv += (["--pins", pins()] if rng.random() < 0.5 else []) + clock() + window()
    else:
        argv = ["trace", "steps", "{dir}/a.log"] + (["--pins", pins()] if rng.random() < 0.9 else []) + \
            clock() + window()
        if rng.random() < 0.3:
            argv += ["--limit", rng.choice(["0", "-1", "3", "1000000"])]
    return Case(seed, "trace", origin, files, [argv])


# ----------------------------------------------------------------------------- random command lines
NUMBERS = ["nan", "NaN", "inf", "-inf", "+inf", "infinity", "1e309", "-1", "0", "-0", "0.0", "1e-300", "5e-324",
           "1", "10", "1000", "1_000_000", "0x10", "0b101", "0o7", "$10", "%101", "99999999999999999999999",
           "-99999999999", "1.5", "", " ", "abc", "1e3", "\u0661\u0662", "\u00bd", "1__0", "_1", "0.001", "1e-9"]
PIN_SPECS = ["0..4", "4..7,0", "0..1000000000", "-1", "32", "0..31", "", ",", "..", "1..", "a..b", "0...4",
             "1;2", "P3=1", "P5=0@0,1@0.25", "3=1@nan", "3=0@inf", "3=1@-1", "99=1", "P3=2", "3=", "=1",
             "3=1@", "3=1@1e400", "P3=1;P4=0@0,1@1e-6", "\u0663=1", "0..4294967296"]


@lru_cache(maxsize=None)
def _parser_shape() -> dict:
    """``{command path: [argparse actions]}`` for every command and subcommand, read from the CLI's parser."""
    from spinemu.cli import build_parser

    shape = {}

    def walk(parser, path):
        subs = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
        if not subs:
            shape[path] = [a for a in parser._actions if not isinstance(a, argparse._HelpAction)]
            return
        for name, sub in subs[0].choices.items():
            walk(sub, path + (name,))

    walk(build_parser(), ())
    return shape


def _file_value(rng: random.Random, wanted: str, valid=()) -> str:
    if valid and rng.random() < 0.5:
        return rng.choice(valid)
    pool = ["{dir}/stop.spin", "{dir}/stop.binary", "{dir}/stop.eeprom", "{dir}/stop.bs2", "{dir}/a.log",
            "{dir}/missing.spin", "{dir}/missing.binary", "{dir}", "{dir}/folder.spin", "{dir}/empty.spin",
            "{dir}/empty.binary", "{dir}/empty.log", "{dir}/stop.txt", "{dir}/noext", "", "-", "/",
            "{dir}/nodir/x.spin", "{dir}/stop.spin.bak", "{dir}/STOP.SPIN", "{dir}/text.binary",
            "{dir}/utf16.spin", "{dir}/image.spin", "/dev/null"]
    if wanted == "out":
        pool = ["{dir}/o.binary", "{dir}/o.eeprom", "{dir}/o.txt", "{dir}/o.png", "{dir}/o.xyz", "{dir}/o.vcd",
                "{dir}", "{dir}/nodir/o.bin", "", "/dev/full", "{dir}/folder.spin", "{dir}/o"]
    return rng.choice(pool)


def _value(rng: random.Random, action, command: str = "") -> str:
    if action.choices:
        return str(rng.choice(list(action.choices))) if rng.random() < 0.85 else rng.choice(["", "x", "PYTHON"])
    meta = (action.metavar or action.dest or "").upper()
    if action.type is not None and action.type not in (str,) or meta in ("N", "S", "CYCLE"):
        return rng.choice(NUMBERS)
    if "SPEC" in meta or "PINS" in meta or action.dest in ("stimulus", "pins"):
        return rng.choice(PIN_SPECS)
    if meta in ("TEXT",):
        return rng.choice(["abc", "", "\x00", "12\r", "\xff" * 3])
    if meta in ("NAME",):
        return rng.choice(["X", "", "1", "a b", "-D"])
    if meta == "DIR":
        return rng.choice(["{dir}", "{dir}/missing", "{dir}/stop.spin", ""])
    if action.option_strings and (any(k in meta for k in ("OUT", "FILE")) or
                                  action.dest in ("output", "eeprom", "listing", "dump_hub", "trace")):
        return _file_value(rng, "out")
    return _file_value(rng, "in", _VALID_INPUTS.get(command, ()))


#: inputs each command can read, so that half the random command lines get past the file checks
_VALID_INPUTS = {
    "run": ("{dir}/stop.spin", "{dir}/stop.binary", "{dir}/stop.eeprom", "{dir}/stop.bs2"),
    "compile": ("{dir}/stop.spin",), "translate": ("{dir}/stop.spin",),
    "disasm": ("{dir}/stop.spin", "{dir}/stop.binary", "{dir}/stop.eeprom"),
    "trace": ("{dir}/a.log",), "sidebyside": ("{dir}/a.log",),
}


def _cli(rng: random.Random, seed: int) -> Case:
    shape = _parser_shape()
    path = rng.choice(sorted(shape))
    argv = list(path)
    actions = shape[path]
    for action in actions:
        if not action.option_strings:
            if rng.random() < 0.95:
                argv.append(_value(rng, action, path[0]))
            continue
        if not (action.required or rng.random() < 0.3):
            continue
        flag = rng.choice(action.option_strings)
        if action.nargs == 0:
            argv.append(flag)
        else:
            argv += [flag, _value(rng, action, path[0])]
    if rng.random() < 0.05:
        argv.insert(rng.randrange(len(argv) + 1), rng.choice(["--bogus", "-x", "--", "--help", "-h", "--version"]))
    if path == ("run",) and not {"--cycles", "--seconds"} & set(argv) and rng.random() < 0.5:
        argv += _cycles(rng)
    files = {"stop.spin": STOP_SPIN.encode(), "stop.binary": _stop_image(), "stop.bs2": STOP_BS2.encode(),
             "a.log": LOG.encode(), "empty.spin": b"", "empty.binary": b"", "empty.log": b"",
             "stop.txt": STOP_SPIN.encode(), "noext": STOP_SPIN.encode(), "text.binary": STOP_SPIN.encode(),
             "utf16.spin": STOP_SPIN.encode("utf-16"), "image.spin": _stop_image(), "folder.spin/": b""}
    from spinemu.image import to_eeprom
    files["stop.eeprom"] = to_eeprom(_stop_image())
    return Case(seed, "cli", " ".join(path), files, [argv])


# ----------------------------------------------------------------------------- the dispatcher
#: kind -> (weight, generator)
KINDS = {
    "spin-mutant": (25, _spin_mutant),
    "spin-snippet": (14, _spin_snippet),
    "translate": (10, _translate),
    "image": (20, _image),
    "pbasic": (12, _pbasic),
    "trace": (7, _trace),
    "cli": (12, _cli),
}


def make_case(seed: int, kind: str = None) -> Case:
    """The case for ``seed`` (of ``kind`` if given, else a kind drawn from the seed)."""
    rng = random.Random(f"spinemu-robust:{seed}")
    names = list(KINDS)
    drawn = rng.choices(names, weights=[KINDS[k][0] for k in names])[0]   # drawn even when ``kind`` is given
    case = KINDS[kind or drawn][1](rng, seed)
    case.forced = kind is not None
    return case
