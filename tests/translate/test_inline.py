"""The woven methods write their charges and long hub accesses out (spinemu.translate.inline), computing the same."""
from __future__ import annotations

import ast
import os
import textwrap

from spinemu.translate import _write, runtime, spin
from spinemu.translate.inline import inline_method, install
from spinemu.translate.program import translate_program
from spinemu.translate.weave import load_package, prepare

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCH = os.path.join(ROOT, "tests", "data", "translate", "cpu_bench.spin")

ACCESSES = textwrap.dedent("""
    def f(self, i, v):
        self.arr[i] = v
        self.arr[i + 1] += self.arr[i] * 3
        self.x = self.arr[i + 1] - 1
        self.x -= v
        self.w = self.x
        self.w += 0x1FFFF
        self.b = self.w + v
        self.b -= 3
        self.ws[i] = self.b * v
        self.ws[i + 1] -= self.ws[i]
        self.bs[i] = self.ws[i + 1]
        self.bs[i + 2] += self.bs[i] + 1
        self.d[i] = self.bs[i + 2]
        return (self.x, self.arr[i], self.arr[i + 1], self.w, self.b, self.ws[i], self.ws[i + 1], self.bs[i],
                self.bs[i + 2], self.d[i], self.d[i + 1])
""")


class _Obj(spin.Object):
    x = spin.Long(0)
    arr = spin.Long(4, 4)
    w = spin.Word(20)
    b = spin.Byte(23)
    ws = spin.Word(24, 4)
    bs = spin.Byte(31, 5)
    d = spin.Long(4, 2, dat=True)


def _both(vbase: int):
    """``f`` run plain and inlined on an object at ``vbase``: (results, hub bytes) each."""
    out = []
    for inline in (False, True):
        fn = ast.parse(ACCESSES).body[0]
        if inline:
            fn = inline_method(fn, _Obj)
        ns: dict = {}
        install(ns)
        exec(compile(ast.Module([fn], []), "<test>", "exec"), ns)
        spin.RT.attach(bytearray(0x10000))
        obj = _Obj()
        obj._vbase, obj._pbase = vbase, vbase - 0x40
        results = [ns["f"](obj, i, v) for i, v in ((0, 5), (1, -7), (2, 0x7FFFFFFF), (-1, 3))]
        out.append((results, bytes(spin.RT.mem)))
    return out


def test_inlined_long_accesses_read_and_write_what_the_properties_do():
    plain, fast = _both(0x100)
    assert plain == fast
    assert any(plain[1])        # the stores reached the hub


def test_inlined_stores_past_8000_are_dropped_as_the_properties_drop_them():
    plain, fast = _both(0x7FEB)     # some variables below $8000, some above
    assert plain == fast
    assert not any(plain[1][0x8000:]) and any(plain[1][0x7F00:0x8000])


def test_woven_benchmark_methods_call_no_charge_or_accessor(tmp_path):
    modules, compiled = translate_program(BENCH)
    _write(modules, compiled, tmp_path)
    top = load_package(tmp_path).TOP
    prepare(top)
    code = top.main.__code__
    assert "__spin_tick" not in code.co_names and "__spin_tick_at" not in code.co_names
    assert "total" not in code.co_names                 # self.total: read from the hub view
    assert "__spin_pause_tick" in code.co_names         # the hand-over to the scheduler is still there


def test_div_and_mod_fast_path_gives_spins_values_and_charges_the_divisors_loop():
    class FakeCog:
        t = 0
    saved = spin.RT.cog, spin.RT.div_extra
    spin.RT.cog, spin.RT.div_extra = FakeCog(), list(range(100, 133))
    try:
        edge = (0, 1, 7, 1000, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0x1_0000_0005, -1, -7, -0x80000000)
        for a in edge:
            for b in edge:
                sa, sb = spin.wrap(a), spin.wrap(b)
                q = 0 if sb == 0 else spin.wrap(abs(sa) // abs(sb) * (-1 if (sa < 0) != (sb < 0) else 1))
                r = 0 if sb == 0 else abs(sa) % abs(sb) * (-1 if sa < 0 else 1)
                for op, want in ((spin.div, q), (spin.mod, r)):
                    before = spin.RT.cog.t
                    assert op(a, b) == want, (op.__name__, a, b)
                    assert spin.RT.cog.t - before == 100 + abs(sb).bit_length()
    finally:
        spin.RT.cog, spin.RT.div_extra = saved


CHARGES = textwrap.dedent("""
    def f(self, n):
        __spin_tick(276)
        x = n
        __spin_tick_at(100, 8, 50)
        while True:
            __spin_tick(36)
            old = n
            n = wrap(n - 1)
            if old == 0:
                break
            __spin_tick(44)
            x = x + 3
            __spin_add(4)
            x = spin.mod(x * 3 + n, 1000)
            y = spin.div(x - 500, 7)
            x = x + y
            __spin_tick_at(52, 16)
            __spin_tick(24)
        __spin_tick(20)
        return x
""")


class _Cog:
    id, hub_phase, t = 3, 10, 5


class _Caller(_Obj):
    def g(self):
        runtime.tick(40)
        spin.RT.cog.t += 3
        return 1


def _charged_run(inline: bool, step: int, source: str = CHARGES, final: int = 3000):
    """``source`` (``f``) run plain or inlined; every hand-over to the scheduler moves the limit ``step`` on.

    Returns f's result, the cog's counter after it, the hand-overs (counter, key) and the hub.
    """
    fn = ast.parse(source).body[0]
    if inline:
        fn = inline_method(fn, _Caller)
    ns = {"__spin_tick": runtime.tick, "__spin_tick_at": runtime.tick_at, "__spin_add": runtime.add, "wrap": spin.wrap,
          "spin": spin}
    install(ns)
    exec(compile(ast.Module([fn], []), "<test>", "exec"), ns)
    RT = spin.RT
    saved = RT.cog, RT.limit, RT.final, RT.pause, RT.keys, RT.div_extra
    events = []

    def pause():
        events.append((RT.cog.t, RT.keys[3]))
        RT.limit += step

    RT.cog, RT.limit, RT.final, RT.pause, RT.keys = _Cog(), step, final, pause, [None] * 8
    RT.div_extra = [3 * n + 1 for n in range(33)]
    RT.attach(bytearray(0x10000))
    try:
        x = ns["f"](_Caller(), 30)
        return x, RT.cog.t, events, bytes(RT.mem[:64])
    finally:
        RT.cog, RT.limit, RT.final, RT.pause, RT.keys, RT.div_extra = saved


def test_inlined_charges_hand_over_at_the_same_cycles_with_the_same_counter():
    for step in (7, 50, 333, 1000):
        plain = _charged_run(False, step)
        assert _charged_run(True, step) == plain
        assert plain[2]                     # it did hand over


def _loop_ticks(rng) -> tuple:
    """Often a charge just before a loop and one ending its body (the loop's head may then align by a constant)."""
    if rng.random() < 0.4:
        return [], []
    return [f"__spin_tick({rng.choice((4, 20, 36, 23))})"], [f"__spin_tick({rng.choice((4, 20, 276, 23))})"]


def _random_body(rng, depth: int, in_for: bool) -> list:
    """Random statements: charges, neutral ones, calls and divisions, nested ifs and loops with break/continue."""
    out = []
    for _ in range(rng.randint(1, 7)):
        r = rng.random()
        if r < 0.35:
            k = rng.choice((4, 8, 36, 276, 1252, 23))
            out.append(rng.choice((f"__spin_tick({k})", f"__spin_tick_at({k}, {rng.choice((0, 8, 400))})",
                                   f"__spin_tick_at({k}, 16, {k - 4})", f"__spin_add({rng.choice((4, -16, 7))})")))
        elif r < 0.6:
            out.append(rng.choice(("x = wrap(x * 3 + n)", "self.arr[x & 3] = x", "self.x += x", "x = x ^ self.x",
                                   "self.arr[1] -= self.arr[x & 3]")))
        elif r < 0.72:
            out.append(rng.choice(("x = spin.mod(x + 7, 13)", "x = spin.div(x, 3)", "x = spin.div(x, -3)",
                                   "x += self.g()")))
        elif depth < 3 and r < 0.82:
            out.append(f"if x & {rng.choice((1, 2, 4))}:")
            out += ["    " + line for line in _random_body(rng, depth + 1, in_for)]
        elif depth < 3 and r < 0.91:
            pre, post = _loop_ticks(rng)
            out += pre + [f"for k{depth} in range({rng.randint(0, 3)}):"]
            out += ["    " + line for line in _random_body(rng, depth + 1, True) + post]
        elif depth < 3:
            pre, post = _loop_ticks(rng)
            out += [f"w{depth} = 0"] + pre + rng.choice(([f"while w{depth} < 3:", f"    w{depth} += 1"],
                                                          ["while True:", f"    w{depth} += 1",
                                                           f"    if w{depth} > 3:", "        break"]))
            out += ["    " + line for line in _random_body(rng, depth + 1, in_for) + post]
        elif in_for:
            out += [rng.choice(("if x & 8:", "if x & 16:")), rng.choice(("    continue", "    break"))]
    return out or ["x = x + 1"]


def test_inlined_charges_match_the_runtimes_on_random_methods():
    import random
    rng = random.Random(7)
    for case in range(150):
        body = _random_body(rng, 0, False)
        source = "def f(self, n):\n    x = n\n" + "".join(f"    {line}\n" for line in body) + "    return x\n"
        for step, final in ((30, 1 << 40), (401, 2000)):
            plain = _charged_run(False, step, source, final)
            assert _charged_run(True, step, source, final) == plain, source
