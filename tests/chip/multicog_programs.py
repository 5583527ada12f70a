"""Random multi-cog Spin programs: every way cogs meet, for comparing two schedulings.

:func:`program` writes a Spin source from a seed.  The main cog takes a lock
and starts one to seven workers; each cog then loops over statements drawn
from a menu of the ways Propeller cogs interact (and of the work between
those meetings, which a cog may run ahead through):

* private work: loops over locals and a local array, calls of a method with
  locals, CASE, DAT table reads, CNT reads;
* shared counters under a lock (LOCKSET/LOCKCLR), and the same counters
  raced on without one;
* producer/consumer through hub RAM: a one-long mailbox and an eight-long
  ring buffer (busy waits: the fast-forward parks them);
* cogs starting and stopping each other (COGSTOP, COGNEW again on the same
  stack, COGINIT restarting a running cog);
* pins: each worker drives its own pin, reads the others (INA) and waits for
  another cog's pin with WAITPEQ/WAITPNE (a deadlock is a valid ending);
* reaching into another cog's stack: the main cog passes the address of one
  of its locals to a worker that changes it, and reads and writes the
  workers' stacks (as a stack-usage checker does).

The programs are deterministic; how they end (a cycle limit, a deadlock, all
cogs stopped, a fault) is part of what is compared.
"""
from __future__ import annotations

import random

STACK_LONGS = 48


class _Gen:
    def __init__(self, rng: random.Random, workers: int):
        self.rng = rng
        self.workers = workers

    def expr(self) -> str:
        rng = self.rng
        return rng.choice(["x", "y", "z", "x + y", "x ^ z", "(x >> 3) + 1", "y * 3", "i",
                           str(rng.randrange(1, 200)), "loc[i & 3]", "x & $FF"])

    def stmt(self, me: int, depth: int = 0) -> list:
        """Lines (without the indentation of the block) of one statement of cog ``me`` (0: main)."""
        rng = self.rng
        other_pin = 16 + rng.randrange(self.workers + 1)
        kinds = ["compute", "compute", "compute", "lock", "racy", "mbox_put", "mbox_get", "ring_put",
                 "ring_get", "wait", "pin", "pin_read", "waitpin", "dat", "bytes", "call", "case", "result",
                 "cnt", "peek"]
        if me == 0:
            kinds += ["cogctl", "cogctl", "poke", "mine"]
        else:
            kinds += ["ptr", "ptr"]
        k = rng.choice(kinds)
        e = self.expr()
        if k == "compute":
            n = rng.randint(6, 60)
            body = rng.choice(["x := x * 3 + i ^ (x >> 5)", "loc[i & 3] += x + i", "y := y + (x ** 2) / (i + 1)",
                               "z := (z <- 3) ^ x + i"])
            extra = ["  x += loc[(i + 1) & 3]"] if rng.random() < 0.4 else []
            return [f"repeat i from 0 to {n}", "  " + body] + extra
        if k == "lock":
            return ["repeat until not lockset(lock_id)", f"counter += {rng.randint(1, 3)}",
                    "shared[counter & 7] := " + e, "lockclr(lock_id)"]
        if k == "racy":
            return [rng.choice(["racy += 1", f"racy := racy + {e}", f"shared[{rng.randrange(8)}] ^= {e}",
                                "racy++"])]
        if k == "mbox_put":
            return [f"repeat while mbox and i++ < {rng.randint(20, 400)}", f"mbox := ({e}) | 1"]
        if k == "mbox_get":
            return [f"repeat until mbox or i++ > {rng.randint(20, 400)}", "y := mbox", "mbox := 0"]
        if k == "ring_put":
            return ["if ((head + 1) & 7) <> tail", f"  ring[head] := {e}", "  head := (head + 1) & 7"]
        if k == "ring_get":
            return ["if tail <> head", "  y += ring[tail]", "  tail := (tail + 1) & 7"]
        if k == "wait":
            return [f"waitcnt(cnt + {rng.randint(400, 4000)} + (x & 511))"]
        if k == "pin":
            return [rng.choice([f"!outa[{16 + me}]", f"outa[{16 + me}] := x & 1", f"outa[{16 + me}] := y >> 31"])]
        if k == "pin_read":
            return [f"z += ina[{other_pin}]"]
        if k == "waitpin":
            mask = 1 << other_pin
            return [rng.choice([f"waitpeq({mask}, {mask}, 0)", f"waitpne({mask}, {mask}, 0)",
                                f"waitpeq(0, {mask}, 0)"])]
        if k == "dat":
            return [f"y := table[{e} & 7] + tbytes[x & 15]"]
        if k == "bytes":
            return [f"bbuf[{e} & 15] := x", f"wbuf[y & 7] += {e}"]
        if k == "call":
            return [f"x := helper(x, {e})"]
        if k == "case":
            return [f"case {e} & 3", "  0: y++", "  1: y -= x", "  2: loc[y & 3] := z", "  other: z := x"]
        if k == "result":
            return [f"results[{me}] := {e}"]
        if k == "cnt":
            return ["x += cnt & 255"]
        if k == "peek":                             # read a worker's stack, as a stack-usage check does
            w = rng.randrange(self.workers) if self.workers else 0
            return [f"z += stacks[{w * STACK_LONGS + rng.randrange(STACK_LONGS)}]"]
        if k == "poke":                             # write into a worker's unused stack
            w = rng.randrange(self.workers) if self.workers else 0
            return [f"stacks[{w * STACK_LONGS + rng.randrange(STACK_LONGS - 8, STACK_LONGS)}] := {e}"]
        if k == "mine":                             # main's local that a worker changes through its address
            return ["y += mine", "mine := x"]
        if k == "ptr":                              # change main's local through the address passed in
            return [rng.choice(["long[ptr] += 1", f"long[ptr] := {e}", "y += long[ptr]"])]
        if k == "cogctl":
            if not self.workers:
                return ["x++"]
            w = rng.randrange(self.workers)
            return [rng.choice([f"cogstop(cogs[{w}])",
                                f"cogstop(cogs[{w}])\ncogs[{w}] := cognew(worker{w + 1}(@mine), @stacks[{w * STACK_LONGS}])",
                                f"coginit(cogs[{w}], worker{w + 1}(@mine), @stacks[{w * STACK_LONGS}])"])]
        raise AssertionError(k)

    def body(self, me: int, n: int) -> list:
        out = []
        for _ in range(n):
            for line in self.stmt(me):
                out += line.split("\n")
        return out


def program(seed: int) -> str:
    """The Spin source of random multi-cog program ``seed``."""
    rng = random.Random(seed)
    workers = rng.choice([1, 1, 2, 3, 3, 4, 5, 7])
    g = _Gen(rng, workers)
    lines = ["CON", "  _clkmode = xtal1 + pll16x", "  _xinfreq = 5_000_000", "",
             "VAR",
             "  long lock_id, counter, racy, mbox, head, tail",
             "  long ring[8], shared[8], results[8], cogs[8]",
             f"  long stacks[{STACK_LONGS * max(workers, 1)}]",
             "  word wbuf[8]", "  byte bbuf[16]", "",
             "DAT",
             "  table  long 3, 1, 4, 1, 5, 9, 2, 6",
             "  tbytes byte 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 233, 121, 98, 7, 0", "",
             "PUB main | i, x, y, z, mine, loc[4]",
             "  lock_id := locknew",
             f"  dira[16] := {rng.randint(0, 1)}",
             f"  x := {rng.randrange(1000)}"]
    for w in range(workers):
        lines.append(f"  cogs[{w}] := cognew(worker{w + 1}(@mine), @stacks[{w * STACK_LONGS}])")
        if rng.random() < 0.3:
            lines.append(f"  waitcnt(cnt + {rng.randint(500, 20_000)})")
    rounds = rng.choice(["", str(rng.randint(2, 30))])
    lines.append(f"  repeat {rounds}".rstrip())
    lines += ["    " + s for s in g.body(0, rng.randint(3, 9))]
    if rounds and rng.random() < 0.5:
        lines += [f"  cogstop(cogs[{w}])" for w in range(workers) if rng.random() < 0.5]
    for w in range(workers):
        me = w + 1
        lines += ["", f"PRI worker{me}(ptr) | i, x, y, z, loc[4]",
                  f"  dira[{16 + me}] := 1", f"  x := {rng.randrange(1000)}"]
        rounds = rng.choice(["", "", str(rng.randint(3, 40))])
        lines.append(f"  repeat {rounds}".rstrip())
        lines += ["    " + s for s in g.body(me, rng.randint(2, 7))]
    lines += ["", "PRI helper(p, q) | r",
              "  r := p * 7 + q",
              "  repeat 3",
              "    r := r ^ (r >> 3) + q",
              "  return r", ""]
    return "\n".join(lines)


if __name__ == "__main__":       # print one program: python tests/chip/multicog_programs.py SEED
    import sys
    print(program(int(sys.argv[1]) if len(sys.argv) > 1 else 0))
