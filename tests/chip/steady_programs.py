"""Random clock-paced Spin programs: steady states and the ways they end, for the steady-state skip.

:func:`program` writes a Spin source from a seed.  The main cog starts zero
to three workers; every cog loops over statements and then waits for its
next period with WAITCNT, so the chip settles into a steady state.  The
statements are the ways such a state changes or breaks: counters that go up
or down (longs, and bytes and words that wrap), comparisons of them with
thresholds they cross later, a mod-n step index into a DAT table, pin
writes, CNT reads, inner REPEAT loops, values passed between cogs through
hub RAM, operators the skip follows only with a fixed operand (multiplication,
left shifts, limits) or not at all (right shifts, a value multiplied by
itself period after period), a
main loop that ends after a number of rounds, and cogs whose loops are much
slower than the others' (they sleep through many periods of the fast ones).
"""
from __future__ import annotations

import random

HEADER = """CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

VAR
  long stack[120]
  long shared[4]
  word words[4]
  byte bytes[4]

"""


class _Gen:
    def __init__(self, rng: random.Random, cogs: int):
        self.rng, self.cogs = rng, cogs

    def stmt(self, me: int, depth: int = 0) -> list:
        rng = self.rng
        other = rng.randrange(self.cogs)
        t = rng.choice([3, 50, 200, 1000, -5, 0])
        kinds = ["a++", "a += 3", "b -= 2", f"shared[{me}]++", f"shared[{me}] += 7", f"bytes[{me}]++",
                 f"words[{me}] += 300", "i := (i + 1) // 4", f"!outa[{me}]", f"outa[{me}] := i & 1",
                 f"outa[{me}] := a > {t}", "b := table[i & 7]", "b := cnt - t", "c := cnt",
                 f"b := shared[{other}] + 1", f"shared[{me}] := bytes[{other}]", "b := a * 3", "b := a >> 2", "b := a << 2", "c *= 3", "b := a #> 100",
                 "b := -a", "b := a <# 40", f"c := a == {t}", "if", "if", "repeat", "ifinc"]
        k = rng.choice(kinds if depth < 1 else kinds[:-4])
        if k == "if":
            v = rng.choice(["a", "b", f"shared[{me}]", f"bytes[{me}]", "i"])
            op = rng.choice(["<", ">", "==", "<>", "=<", "=>"])
            body = [f"if {v} {op} {t}"] + ["  " + s for s in self.stmt(me, depth + 1)]
            if rng.random() < 0.5:
                body += ["else"] + ["  " + s for s in self.stmt(me, depth + 1)]
            return body
        if k == "repeat":
            return [f"repeat j from 0 to {rng.randrange(1, 4)}"] + ["  " + s for s in self.stmt(me, depth + 1)]
        if k == "ifinc":
            return [f"if ++a > {rng.choice([20, 300, 5000])}", "  a := 0"]
        return [k]

    def body(self, me: int) -> list:
        lines = []
        for _ in range(self.rng.randrange(1, 5)):
            lines += self.stmt(me)
        return lines


def program(seed: int) -> str:
    """A clock-paced multi-cog Spin program (see the module docstring)."""
    rng = random.Random(seed)
    cogs = rng.randrange(1, 5)
    g = _Gen(rng, cogs)
    periods = [rng.choice([8000, 16000, 40000, 80000, 12_008, 400_000, 2_000_000]) for _ in range(cogs)]
    out = [HEADER, "PUB main | t, a, b, c, i, j\n"]
    for w in range(1, cogs):
        out.append(f"  cognew(worker{w}, @stack[{(w - 1) * 40}])\n")
    out.append("  dira[0]~~\n  t := cnt\n")
    rounds = rng.choice(["repeat", "repeat", f"repeat {rng.randrange(200, 3000)}"])
    out.append(f"  {rounds}\n")
    for s in g.body(0):
        out.append("    " + s + "\n")
    out.append(f"    waitcnt(t += {periods[0]})\n\n")
    for w in range(1, cogs):
        out.append(f"PRI worker{w} | t, a, b, c, i, j\n  dira[{w}]~~\n  t := cnt\n  repeat\n")
        for s in g.body(w):
            out.append("    " + s + "\n")
        out.append(f"    waitcnt(t += {periods[w]})\n\n")
    out.append("DAT\n  table byte 3, 6, 12, 9, 1, 2, 4, 8\n")
    return "".join(out)


# ----------------------------------------------------------------------------- with an idle PASM cog
_IDLE_LOOPS = {
    # a hub mailbox polled until the main cog posts to it; then P2 high
    "mailbox": ["poll    rdlong  xx, par wz", "  if_z  jmp     #poll", "        or      dira, pin",
                "        or      outa, pin", "done    jmp     #done"],
    # a pin polled until it goes high (a Spin cog's pin wakes it, pin 5 nobody's does not)
    "pin": ["poll    test    watch, ina wz", "  if_z  jmp     #poll", "        or      dira, pin",
            "        or      outa, pin", "done    jmp     #done"],
    # a CNT deadline: the loop's horizon, then P2 toggles and it waits again
    "deadline": ["        mov     tt, cnt", "        add     tt, delay", "poll    mov     uu, cnt",
                 "        sub     uu, tt", "        cmps    uu, #0 wc", "  if_c  jmp     #poll",
                 "        xor     outa, pin", "        or      dira, pin", "        add     tt, delay",
                 "        jmp     #poll"],
}


def pasm_program(seed: int) -> str:
    """A main cog blinking and posting to a mailbox, a PWM cog, and a PASM cog in an idle loop
    (pasm_idle.py parks it): a mailbox, a pin or a CNT deadline it polls."""
    rng = random.Random(seed)
    kind = rng.choice(sorted(_IDLE_LOOPS))
    blink = rng.choice([2, 4, 10, 50])
    pwm_hz = rng.choice([100, 250, 1000, 5000])
    steps = rng.choice([4, 10, 16])
    post = rng.choice([-1, 3, 7])
    watch = rng.choice([0, 1, 5])
    delay = rng.choice([8000, 800_000, 40_000_000])
    return "\n".join([
        "CON", "  _clkmode = xtal1 + pll16x", "  _xinfreq = 5_000_000",
        "VAR", "  long mailbox, stack[32]",
        "PUB main | t, n", "  cognew(@entry, @mailbox)", "  cognew(pwm, @stack)", "  dira[0]~~", "  t := cnt",
        "  repeat", "    !outa[0]", f"    waitcnt(t += clkfreq / {blink})", f"    if ++n == {post}",
        "      mailbox := n",
        "PRI pwm | t, i", "  dira[1]~~", "  t := cnt", "  repeat", f"    repeat i from 0 to {steps - 1}",
        f"      outa[1] := i < {steps // 3}", f"      waitcnt(t += clkfreq / {pwm_hz * steps})",
        "DAT", "        org     0", "entry", *_IDLE_LOOPS[kind],
        "pin     long    |< 2", f"watch   long    |< {watch}", f"delay   long    {delay}",
        "xx      res     1", "tt      res     1", "uu      res     1", ""])
