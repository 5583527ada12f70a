#!/usr/bin/env python3
"""Random PASM programs run with the PASM speed-ups on and off: identical pins, hub RAM, end and counts.

Usage (from the worktree root; no oracle needed)::

    python tests/chip/tools/pasm_idle_random.py --count 200 --seed 1     # polling programs
    python tests/chip/tools/pasm_idle_random.py --count 200 --kind random  # pasm_random.py's programs
    python tests/chip/tools/pasm_idle_random.py --count 200 --kind loops   # ... run 30 times round

The PASM cog's idle-loop skipper (spinemu/chip/pasm_idle.py) and its
compiled blocks (spinemu/chip/pasm_blocks.py) must not change anything a
program can observe.  Each program runs four times: skipping and blocks on,
each alone, and both off (every instruction through its handler); the pin
trace, hub RAM, end cycle, reason and the instructions each PASM cog ran
must be identical (but for cogs another cog stopped: they may have run
ahead through private instructions past the stop, how far depends on the
scheduling).

:func:`polling_program` (deterministic for a seed) writes a Spin main and
one to three PASM cogs built from the loops drivers poll with: a hub
mailbox read until it changes or becomes non-zero, INA tested against a mask
(``test mask, ina``, ``mov``/``and``/``cmp``), a CNT deadline compared signed
or unsigned (``mov t, cnt``/``sub``/``cmps``/``if_c jmp``, also with a
deadline register read before it is written, which is no idle loop),
FullDuplexSerial's ``jmpret`` coroutines, ``waitcnt``/``waitpeq`` waits and
counting loops; between the waits the cogs toggle pins, count, write hub
longs, rewrite the same value, start a counter on a pin others read.  The
Spin main writes the mailboxes, drives pins and stops cogs at random
moments; a :class:`~spinemu.chip.inputs.PinStimulus` changes input pins;
some programs run in ``--compat chip``.
"""
from __future__ import annotations

import argparse
import os
import random
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, ROOT)

from spinemu.chip import Chip  # noqa: E402
from spinemu.chip.inputs import PinStimulus  # noqa: E402
from spinemu.compiler import compile_source  # noqa: E402

HEADER = """'' random polling program {seed} (tests/chip/tools/pasm_idle_random.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long box[8]
PUB main | t
"""
#: pins: outputs of the PASM cogs, outputs of Spin, inputs from the stimulus
PASM_OUT = [0, 1, 2, 3, 4, 5]
SPIN_OUT = [8, 9, 10]
STIM_IN = [16, 17, 18]


class _Cog:
    """Builds the PASM text of one cog (labels made unique with the cog's prefix)."""

    def __init__(self, rng: random.Random, prefix: str, n_cogs: int):
        self.rng = rng
        self.p = prefix
        self.lines: list = []
        self.data: dict = {}
        self.k = 0
        self.n_cogs = n_cogs

    def label(self) -> str:
        self.k += 1
        return f"{self.p}L{self.k}"

    def reg(self, name: str, value: int = 0) -> str:
        full = f"{self.p}{name}"
        self.data.setdefault(full, value)
        return full

    def emit(self, line: str, label: str = "") -> None:
        self.lines.append(f"{label:<12} {line}")

    # ------------------------------------------------------------------ pieces
    def noise(self, changing: bool = False) -> None:
        """A few private instructions; ``changing``: one of them changes the cog's state every pass."""
        rng = self.rng
        for _ in range(rng.randrange(0, 3)):
            s1, s2 = self.reg("s1"), self.reg("s2", rng.getrandbits(32))
            op = rng.choice(["mov {a}, #{i}", "add {a}, {b}", "xor {a}, #{i} wz", "test {b}, #{i} wc",
                             "rol {a}, #{i}", "mov {a}, {b}", "sub {a}, #{i}", "cmp {b}, #{i} wz, wc",
                             "muxc {a}, #{i}", "nop"])
            self.emit(op.format(a=s1, b=s2, i=rng.randrange(512)))
            if op.startswith(("add {a}, {b}", "rol", "sub {a}", "muxc")):
                self.emit(f"mov {s1}, #{rng.randrange(512)}")       # the same value each pass again
        if changing:
            self.emit(f"add {self.reg('count')}, #1")

    def wait(self) -> None:
        """One polling loop (or a plain wait) that ends when something changes."""
        rng = self.rng
        kind = rng.choices(["hub_change", "hub_nonzero", "pin_test", "pin_cmp", "cnt_signed", "cnt_unsigned",
                            "cnt_livein", "coroutine", "waitcnt", "waitpeq", "count"],
                           [14, 10, 12, 6, 12, 6, 3, 8, 4, 3, 3])[0]
        top = self.label()
        x = self.reg("x")
        if kind in ("hub_change", "hub_nonzero"):
            addr = self.reg(f"a{rng.randrange(4)}")
            if kind == "hub_change":
                last = self.reg("last")
                self.emit(f"rdlong {x}, {addr}", top)
                self.noise(rng.random() < 0.1)
                self.emit(f"cmp {x}, {last} wz")
                self.emit(f"if_z jmp #{top}")
                self.emit(f"mov {last}, {x}")
            else:
                self.emit(f"rdlong {x}, {addr} wz", top)
                self.noise(rng.random() < 0.1)
                self.emit(f"if_z jmp #{top}")
                self.emit(f"wrlong {self.reg('zero')}, {addr}")
        elif kind in ("pin_test", "pin_cmp"):
            pin = rng.choice(STIM_IN + SPIN_OUT + [p for p in PASM_OUT if rng.random() < 0.3])
            mask = self.reg(f"m{pin}", 1 << pin)
            level = rng.choice(["z", "nz"])
            if kind == "pin_test":
                self.emit(f"test {mask}, ina wz", top)
                self.noise(rng.random() < 0.1)
                self.emit(f"if_{level} jmp #{top}")
            else:
                self.emit(f"mov {x}, ina", top)
                self.emit(f"and {x}, {mask}")
                self.noise()
                self.emit(f"cmp {x}, {mask} wz")
                self.emit(f"if_{level} jmp #{top}")
        elif kind.startswith("cnt"):
            dl = self.reg("dl")
            delay = rng.choice([40, 100, 500, 3000, 20000, 70000])
            self.emit(f"mov {dl}, cnt")
            self.emit(f"add {dl}, {self.reg(f'd{delay}', delay)}")
            if kind == "cnt_livein":          # the loop keeps a CNT-derived value from pass to pass: not idle
                acc = self.reg("acc")
                self.emit(f"mov {acc}, cnt")
                self.emit(f"sub {acc}, cnt", top)
                self.emit(f"add {acc}, cnt")
                self.emit(f"mov {x}, {dl}")
                self.emit(f"sub {x}, cnt")
                self.emit(f"cmps {x}, #0 wc")
                self.emit(f"if_nc jmp #{top}")
                return
            self.emit(f"mov {x}, {dl}", top)
            self.noise(rng.random() < 0.05)
            if kind == "cnt_signed":
                self.emit(f"sub {x}, cnt")
                self.emit(f"cmps {x}, #0 wc" if rng.random() < 0.7 else f"cmps {x}, {self.reg('zero')} wc, wz")
                self.emit(f"if_nc jmp #{top}")
            else:
                self.emit(f"sub {x}, cnt")
                self.emit(f"cmp {x}, {self.reg(f'd{delay}', delay)} wc")     # below the delay until it wraps
                self.emit(f"if_c jmp #{top}")
        elif kind == "coroutine":             # FullDuplexSerial's ping-pong: two pollers share the cog
            a_code, b_code = self.reg("acode"), self.reg("bcode")
            b_top = self.label()
            addr = self.reg(f"a{rng.randrange(4)}")
            pin = rng.choice(STIM_IN + SPIN_OUT)
            mask = self.reg(f"m{pin}", 1 << pin)
            done = self.label()
            self.emit(f"mov {b_code}, #{b_top}")
            self.emit(f"jmpret {a_code}, {b_code}", top)
            self.emit(f"test {mask}, ina wc")
            self.emit(f"if_nc jmp #{top}")
            self.emit(f"jmp #{done}")
            self.emit(f"jmpret {b_code}, {a_code}", b_top)
            self.emit(f"rdlong {x}, {addr} wz")
            self.emit(f"if_z jmp #{b_top}")
            self.emit(f"jmp #{done}")
            self.lines.append(done)
        elif kind == "waitcnt":
            self.emit(f"mov {x}, cnt")
            self.emit(f"add {x}, #{rng.randrange(20, 500)}")
            self.emit(f"waitcnt {x}, #0")
        elif kind == "waitpeq":
            pin = rng.choice(STIM_IN + SPIN_OUT)
            mask = self.reg(f"m{pin}", 1 << pin)
            self.emit(f"waitpeq {mask}, {mask}" if rng.random() < 0.5 else f"waitpne {mask}, {mask}")
        else:                                 # a counting loop: busy, its state changes every pass
            self.emit(f"mov {x}, #{rng.randrange(5, 300)}")
            self.emit(f"djnz {x}, #{top}", top)

    def action(self) -> None:
        rng = self.rng
        kind = rng.choice(["toggle", "report", "count", "same", "counter", "setpin"])
        pin = rng.choice(PASM_OUT)
        mask = self.reg(f"m{pin}", 1 << pin)
        if kind == "toggle":
            self.emit(f"xor outa, {mask}")
        elif kind == "setpin":
            self.emit(f"or outa, {mask}")     # often already set: a write that changes nothing
        elif kind == "report":
            self.emit(f"wrlong {self.reg('x')}, {self.reg(f'a{rng.randrange(4, 6)}')}")
        elif kind == "count":
            c = self.reg("count")
            self.emit(f"add {c}, #1")
            self.emit(f"wrlong {c}, {self.reg(f'a{rng.randrange(4, 6)}')}")
        elif kind == "same":
            self.emit(f"rdlong {self.reg('y')}, {self.reg('a6')}")
            self.emit(f"wrlong {self.reg('y')}, {self.reg('a6')}")
        else:                                 # NCO on a pin (others may poll it)
            self.emit(f"movs ctra, #{pin}")
            self.emit(f"movi ctra, #%0_00100_000")
            self.emit(f"mov frqa, {self.reg('frq', rng.choice([1 << 20, 1 << 24, 3 << 22]))}")

    def text(self, entry: str) -> list:
        out = [f"{entry:<12} mov {self.p}base, par"]
        for i in range(7):
            out.append(f"{'':<12} mov {self.p}a{i}, {self.p}base")
            out.append(f"{'':<12} add {self.p}a{i}, #{4 * i}")
            self.data.setdefault(f"{self.p}a{i}", 0)
        out.append(f"{'':<12} mov dira, {self.reg('dirs', sum(1 << p for p in PASM_OUT))}")
        self.data.setdefault(f"{self.p}base", 0)
        return out + self.lines + [f"{k:<12} long {v}" for k, v in self.data.items()]


def polling_program(seed: int) -> tuple:
    """``(source, inputs, compat, cycles)`` of random polling program ``seed``."""
    rng = random.Random(seed)
    n_cogs = rng.choice([1, 1, 2, 2, 3])
    dat = ["DAT", f"{'':<12} org 0"]
    for k in range(n_cogs):
        cog = _Cog(rng, f"c{k}", n_cogs)
        top = cog.label()
        cog.lines.append(top)
        for _ in range(rng.randrange(1, 4)):
            cog.wait()
            cog.action()
        if rng.random() < 0.15:
            cog.emit("cogid " + cog.reg("x"))
            cog.emit("cogstop " + cog.reg("x"))
        else:
            cog.emit(f"jmp #{top}")
        if k:
            dat.append(f"{'':<12} org 0")
        dat += cog.text(f"entry{k}")
    spin = []
    for k in range(n_cogs):
        spin.append(f"  cognew(@entry{k}, @box)")
    spin.append(f"  dira[{SPIN_OUT[0]}..{SPIN_OUT[-1]}] := %111")
    spin.append("  t := cnt")
    for _ in range(rng.randrange(3, 12)):
        spin.append(f"  waitcnt(t += {rng.choice([800, 2000, 9000, 30000, 90000])})")
        act = rng.random()
        if act < 0.45:
            spin.append(f"  box[{rng.randrange(8)}] := {rng.choice([0, 1, 2, rng.getrandbits(16)])}")
        elif act < 0.8:
            spin.append(f"  !outa[{rng.choice(SPIN_OUT)}]")
        elif act < 0.9:
            spin.append(f"  box[{rng.randrange(8)}]++")
        else:
            spin.append(f"  cogstop({rng.randrange(1, n_cogs + 1)})")
    if rng.random() < 0.5:
        spin.append("  repeat")                 # Spin spins too (a busy loop parked by the Spin side)
    changes = []
    for pin in STIM_IN:
        t = 0
        for _ in range(rng.randrange(0, 6)):
            t += rng.choice([500, 3000, 20000, 100000])
            changes.append((t, 1 << pin, rng.getrandbits(1) << pin))
    inputs = PinStimulus(changes, initial=rng.getrandbits(32)) if changes or rng.random() < 0.5 else None
    compat = "chip" if rng.random() < 0.25 else "spinsim"
    cycles = rng.choice([300_000, 600_000, 1_500_000])
    return HEADER.format(seed=seed) + "\n".join(spin) + "\n" + "\n".join(dat) + "\n", inputs, compat, cycles


def run_both(image: bytes, *, inputs=None, compat: str = "spinsim", cycles=None) -> list:
    """Differences between the runs with the speed-ups on, each alone, and off (empty: identical)."""
    results = {}
    for skip, blocks in ((False, False), (True, True), (True, False), (False, True)):
        chip = Chip(image, inputs=inputs, compat=compat, fast_forward=skip, compile_blocks=blocks)
        r = chip.run(max_cycles=cycles)
        # a cog another cog stops may have run ahead through its private instructions: its count
        # depends on how far, so only the other cogs' counts are compared
        stopped = {e[1] for e in r.cog_events if e[2] == "stop" and "by cog" in e[3]}
        counts = {k: v for k, v in r.stats["pasm_instructions_per_cog"].items() if k not in stopped}
        results[(skip, blocks)] = (r.trace.changes, r.hub, r.end_cycle, r.reason, counts)
    ref = results[(False, False)]
    bad = []
    names = ("pins", "hub RAM", "end cycle", "reason", "instructions per cog")
    for mode, got in results.items():
        for name, a, b in zip(names, got, ref):
            if a != b:
                detail = f"{a} vs {b}" if name in ("end cycle", "reason", "instructions per cog") else ""
                bad.append(f"skip={mode[0]} blocks={mode[1]}: {name} differ {detail}")
    return bad


def random_program_case(seed: int, length: int = 60):
    """pasm_random.py's program ``seed`` as a ``(source, inputs, compat, cycles)`` case."""
    sys.path.insert(0, HERE)
    from pasm_random import program
    return program(seed, length), None, "spinsim", 2_000_000


def looped_program_case(seed: int, length: int = 40):
    """pasm_random.py's program ``seed`` run 30 times round (hot code: compiled blocks, code that
    ``movs``/``movd`` change again and again, ``call``/``ret`` from several places)."""
    src = random_program_case(seed, length)[0]
    head = "entry   mov     hp, par\n"
    assert head in src
    src = src.replace(head, head + "top\n", 1)
    stop = f"        {'':<12} cogid   ha\n"
    assert stop in src
    src = src.replace(stop, f"        {'':<12} djnz    reps, #top\n" + stop, 1)
    return src + "reps         long    30\n", None, "spinsim", 3_000_000


CASES = {"polling": polling_program, "random": random_program_case, "loops": looped_program_case}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1, help="first program's seed (then seed+1, ...)")
    ap.add_argument("--kind", choices=sorted(CASES), default="polling")
    ap.add_argument("--show", action="store_true", help="print the source of programs that differ")
    a = ap.parse_args(argv)
    failed = 0
    t0 = time.time()
    for seed in range(a.seed, a.seed + a.count):
        src, inputs, compat, cycles = CASES[a.kind](seed)
        image = compile_source(src).binary
        bad = run_both(image, inputs=inputs, compat=compat, cycles=cycles)
        if bad:
            failed += 1
            print(f"seed {seed}: " + " | ".join(bad[:3]), flush=True)
            if a.show:
                print(src)
    print(f"{a.count} {a.kind} programs: {a.count - failed} identical, {failed} differ ({time.time() - t0:.0f} s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
