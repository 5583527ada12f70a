"""The closed-form counters against a clock-by-clock model of the manual's counter table.

spinsim has no counters, so the reference here is the Propeller Manual v1.2
("CTRA, CTRB", the counter mode table) executed literally, one clock at a
time: every clock the accumulating counters add FRQ, the outputs are
PHS[31] / the carry / bit ``34 - PLLDIV`` of the accumulator (the ideal PLL
divider) and their inverses, the detector and LOGIC modes add FRQ when their
condition on A1, A2, B1 (the pin levels one and two clocks earlier) holds,
and a feedback mode drives BPIN with !A1.  Random scenarios put a stimulus,
another cog's DIRA/OUTA writes and two output counters of a third cog on
four pins, and a counter in a random input mode on them; the emulator's PHS
reads, pin pieces, pin levels and trace must equal the model's at every
cycle.  The conventions both sides share: a register write at cycle ``w``
takes effect for the additions after ``w``; an output reads the registers
as written at its cycle (a DUTY output is low in the cycle of the write).
"""
from __future__ import annotations

import random

import pytest

from spinemu.chip import Chip
from spinemu.chip.cog import RUNNING
from spinemu.chip.inputs import PinStimulus
from spinemu.chip.phase import Phase, combine, complement, floor_sum
from spinemu.chip.pinfold import PinFold
from spinemu.compiler import compile_source

M32 = 0xFFFFFFFF
PINS = 4
T_END = 2000
IDLE_IMAGE = compile_source("PUB main\n").binary


# ----------------------------------------------------------------------------- the clock-by-clock model
class ModelCounter:
    """One counter, clock by clock, straight from the manual's table."""

    def __init__(self):
        self.ctr = self.frq = self.acc = 0
        self.wrote = None

    @property
    def mode(self):
        return (self.ctr >> 26) & 31

    def pins(self):
        return self.ctr & 63, (self.ctr >> 9) & 63

    def add(self, u, levels):
        """The addition of clock ``u`` (registers as written before ``u``); returns the carry."""
        if self.wrote is None or self.wrote >= u:
            return False
        mode = self.mode
        a, b = self.pins()
        if 1 <= mode <= 7 or mode == 31:
            cond = True
        elif mode >= 8:
            def lvl(pin, t):
                return (levels[t] >> pin) & 1 if pin < 32 else 0
            a1, a2, b1 = lvl(a, u - 1), lvl(a, u - 2), lvl(b, u - 1)
            if mode < 16:
                cond = {0: a1, 2: a1 and not a2, 4: not a1, 6: not a1 and a2}[mode & 6]
            else:
                cond = (mode >> (a1 + 2 * b1)) & 1
        else:
            cond = False
        if not cond:
            return False
        before = self.acc
        self.acc += self.frq
        if not (1 <= mode <= 7):
            self.acc &= M32
        return (self.acc >> 32) != (before >> 32)

    def outputs(self, carry, wrote_now, fast_pll_low=False):
        """Pins driven high by an accumulator output mode at this clock."""
        mode = self.mode
        a, b = self.pins()
        if mode in (4, 5):
            level = (self.acc >> 31) & 1
        elif mode in (6, 7):
            level = 0 if wrote_now else int(carry)
        elif mode in (2, 3):
            plldiv = (self.ctr >> 23) & 7
            if fast_pll_low and (not self.frq or (1 << (35 - plldiv)) / self.frq < 16):
                return 0
            level = (self.acc >> (34 - plldiv)) & 1
        else:
            return 0
        out = 0
        if level and a < 32:
            out |= 1 << a
        if mode & 1 and not level and b < 32:
            out |= 1 << b
        return out


def make_scenario(seed):
    r = random.Random(seed)

    def out_ctr(modes, apin=None):
        apin = r.randrange(PINS) if apin is None else apin
        return (r.choice(modes) << 26) | (r.randrange(8) << 23) | (r.randrange(PINS) << 9) | apin

    def frq():
        return r.choice([r.randrange(1 << 32), r.randrange(1 << 27, 1 << 30), 1 << 30, 1 << 31,
                         r.randrange(1, 1 << 26)])

    mode = r.randrange(8, 32)
    apin = r.randrange(PINS)
    bpin = r.choice([r.randrange(PINS), 40])            # 40: port B, reads 0
    if mode in (9, 11, 13, 15) and apin == bpin:
        bpin = (apin + 1) % PINS
    w1 = r.randrange(1, T_END // 2)
    # half the time cog 3's first counter drives cog 1's APIN (and cog 1 sees its own BPIN if it drives one)
    dira = {1: r.randrange(16), 3: r.randrange(16)}
    onto_a = r.random() < 0.5
    if onto_a:
        dira[3] |= 1 << apin
    if r.random() < 0.5 and bpin < 32:
        dira[1] |= 1 << bpin
    writes = [  # (cycle, order, cog, register 0-5, value)
        (a := r.randrange(1, T_END), 3, 3, 2, frq()),
        (a, 4, 3, 0, out_ctr([4, 5, 6, 7, 2, 3, 0], apin if onto_a else None)),
        (r.randrange(1, T_END), 5, 3, 2, frq() // 3),
        (b := r.randrange(1, T_END), 6, 3, 3, frq()), (b, 7, 3, 1, out_ctr([4, 5, 6, 7, 2, 0])),
        (w1, 8, 1, 2, r.choice([1, r.randrange(1 << 32)])), (w1, 9, 1, 0, (mode << 26) | (bpin << 9) | apin),
        (r.randrange(w1, T_END), 10, 1, 2, r.randrange(1 << 20)),
    ]
    # then cog 1's counter may switch to any mode (its PHS carried over, or written)
    w2 = r.randrange(w1, T_END)
    if r.random() < 0.5:
        writes += [(w2, 11, 1, 2, frq()), (w2, 12, 1, 0, out_ctr(list(range(32)), apin))]
        if r.random() < 0.3:
            writes.append((r.randrange(w2, T_END), 13, 1, 4, r.randrange(1 << 32)))
    return {
        "stimulus": sorted((r.randrange(1, T_END), 1 << r.randrange(PINS), r.choice([0, 0xF]))
                           for _ in range(r.randrange(0, 40))),
        "drives": sorted((r.randrange(1, T_END), r.randrange(16), r.randrange(16)) for _ in range(r.randrange(12))),
        "dira": dira,
        "writes": sorted(writes),
        "reads": sorted(r.randrange(w1, T_END) for _ in range(6)),
    }


def model(sc):
    """Per clock: pin levels, PHS of cog 1's CTRA, and the trace's (dir, out)."""
    stim = PinStimulus(sc["stimulus"])
    drives = {t: (d, o) for t, d, o in sc["drives"]}
    writes = {}
    for t, _, cog, reg, v in sc["writes"]:
        writes.setdefault(t, []).append((cog, reg, v))
    ctrs = {(1, 0): ModelCounter(), (3, 0): ModelCounter(), (3, 1): ModelCounter()}
    d2 = o2 = 0
    dira3 = sc["dira"][3]
    dira3_at = dict(sc.get("dira3", ()))                # cog 3's DIRA changes, if the scenario has any
    levels, without_fb, phs, trace = {}, {}, {}, {}
    for u in range(T_END + 1):
        carries = {k: c.add(u, levels) for k, c in ctrs.items()}
        now = set()
        for cog, reg, v in writes.get(u, ()):
            c = ctrs[(cog, reg & 1)]
            if reg >> 1 == 0:
                c.ctr = v
            elif reg >> 1 == 1:
                c.frq = v
            else:
                c.acc = v
            c.wrote = u
            now.add((cog, reg & 1))
        if u in drives:
            d2, o2 = drives[u]
        dira3 = dira3_at.get(u, dira3)
        phs[u] = ctrs[(1, 0)].acc & M32
        def out(cog, ab, shown=False):
            return ctrs[(cog, ab)].outputs(carries[(cog, ab)], (cog, ab) in now, shown)

        out3, shown3 = out(3, 0) | out(3, 1), out(3, 0, True) | out(3, 1, True)
        out1, shown1 = out(1, 0), out(1, 0, True)
        d = d2 | sc["dira"][1] | dira3

        def level(fb, out3=out3, dira3=dira3):
            o = (d2 & o2) | (dira3 & out3) | (sc["dira"][1] & (fb | out1))
            return (o | (stim.levels(u) & ~d)) & M32

        fb = 0
        c1 = ctrs[(1, 0)]
        if c1.mode in (9, 11, 13, 15) and c1.wrote is not None and c1.wrote <= u:
            a, b = c1.pins()
            if b < 32 and not (without_fb.get(u - 1, 0) >> a) & 1:
                fb = 1 << b
        without_fb[u] = level(0)
        levels[u] = level(fb)
        trace[u] = (d, (d2 & o2) | (dira3 & shown3) | (sc["dira"][1] & (fb | shown1)))
    return levels, phs, trace



def emulate(sc, step=None):
    """The same scenario on a chip's counters and pin record; PHS read at the scenario's read cycles.

    ``step(chip, t)``, if given, is called before the actions of cycle ``t`` (everything before ``t`` is done).
    """
    chip = Chip(IDLE_IMAGE, compat="chip", inputs=PinStimulus(sc["stimulus"]))
    chip._boot()
    cogs = chip.cogs
    for k in (1, 2, 3):
        cogs[k].state = RUNNING
    actions = []
    for k in (3, 1):
        cogs[k].dira = sc["dira"][k]
        chip.note_pins(cogs[k], 0)
    for t, d, o in sc["drives"]:
        actions.append((t, 2, lambda t, d=d, o=o: (setattr(cogs[2], "dira", d), setattr(cogs[2], "outa", o),
                                                    chip.note_pins(cogs[2], t))))
    for t, order, cog, reg, v in sc["writes"]:
        actions.append((t, order, lambda t, cog=cog, reg=reg, v=v: chip.counters.write(cogs[cog], reg, v, t)))
    for t, d in sc.get("dira3", ()):
        actions.append((t, 1, lambda t, d=d: (setattr(cogs[3], "dira", d), chip.note_pins(cogs[3], t))))
    actions.sort(key=lambda a: a[:2])
    got = {}
    i = 0

    def act(t, fn):
        if step is not None:
            step(chip, t)
        fn(t)

    for rt in sc["reads"]:
        while i < len(actions) and actions[i][0] <= rt:
            act(actions[i][0], actions[i][2])
            i += 1
        got[rt] = chip.counters.phs(cogs[1], 0, rt)
    for t, _, fn in actions[i:]:
        act(t, fn)
    return chip, got


@pytest.mark.parametrize("seed", range(160))
def test_counters_match_the_clock_by_clock_model(seed):
    sc = make_scenario(seed)
    levels, phs, trace = model(sc)
    chip, got = emulate(sc)
    assert got == {rt: phs[rt] for rt in sc["reads"]}
    history = chip.counters.history
    for pin in range(PINS):
        for s, e, sig in history.pieces(pin, 3, T_END):
            for v in range(s + 1, e + 1):
                assert (sig if isinstance(sig, int) else sig.at(v)) == (levels[v] >> pin) & 1, (pin, v)
    for u in range(2, T_END, 7):
        assert history.levels(u) == levels[u], u
    for a in range(5, T_END - 1, 97):
        pin = a % PINS
        expect = next((v for v in range(a + 1, T_END + 1) if (levels[v] ^ levels[v - 1]) >> pin & 1), None)
        assert history.next_change(pin, a, horizon=T_END - a) == expect, (pin, a)
    changes = chip._build_trace(T_END).changes
    state, i = (0, 0), 0
    for u in range(T_END + 1):
        while i < len(changes) and changes[i][0] <= u:
            state = changes[i][1:]
            i += 1
        assert state == trace[u], u


def states_by_cycle(changes, end):
    """``(dir, out)`` at every cycle ``0..end`` from a list of changes."""
    state, i, out = (0, 0), 0, []
    for u in range(end + 1):
        while i < len(changes) and changes[i][0] <= u:
            state = changes[i][1:]
            i += 1
        out.append(state)
    return out


@pytest.mark.parametrize("seed", range(0, 160, 4))
def test_pin_states_folded_while_the_scenario_runs_are_the_traces_and_the_models(seed):
    """A second fold advanced in random steps during the scenario (as live pin listeners advance it), with
    cog 3 switching DIRA on and off under its counters, gives the trace's changes exactly; so does one
    advanced a cycle at a time."""
    sc = make_scenario(seed)
    r = random.Random(1000 + seed)
    sc["dira3"] = sorted({r.randrange(1, T_END): r.randrange(16) for _ in range(r.randrange(1, 8))}.items())
    _, _, trace = model(sc)
    folds = []

    def step(chip, t):
        if not folds:
            folds.append(PinFold(chip))
        if r.random() < 0.5:
            folds[0].advance(r.randrange(folds[0].folded_to, t + 1))

    chip, _ = emulate(sc, step)
    live = folds[0]
    live.advance(T_END + 1)
    whole = chip._build_trace(T_END).changes
    assert [(0, 0, 0)] + live.changes == whole
    assert live.late == 0
    by_cycle = PinFold(chip)                            # and one cycle at a time, after the run
    for t in range(1, T_END + 2):
        by_cycle.advance(t)
    assert by_cycle.changes == live.changes
    assert states_by_cycle(whole, T_END) == [trace[u] for u in range(T_END + 1)]


# ----------------------------------------------------------------------------- the arithmetic
def test_floor_sum_matches_the_plain_sum():
    r = random.Random(5)
    for _ in range(2000):
        n, m, a, b = r.randrange(60), r.randrange(1, 50), r.randrange(120), r.randrange(-200, 200)
        assert floor_sum(n, m, a, b) == sum((a * i + b) // m for i in range(n))


def test_phase_counts_edges_and_changes_match_a_cycle_by_cycle_walk():
    r = random.Random(6)
    for _ in range(1000):
        m = r.choice([8, 16, 32, 100])
        cuts = sorted(r.sample(range(m + 1), r.choice([2, 4])))
        window = tuple((lo, hi) for lo, hi in zip(cuts[::2], cuts[1::2]) if lo < hi)
        p = Phase(r.randrange(-500, 500), r.randrange(3 * m), m, window)
        a = r.randrange(-50, 50)
        b = a + r.randrange(80)
        xs = {v: p.at(v) for v in range(a - 1, b + 1)}
        span = range(a + 1, b + 1)
        assert p.count(a, b) == sum(xs[v] for v in span)
        assert p.rising(a, b) == sum(1 for v in span if xs[v] and not xs[v - 1])
        assert p.falling(a, b) == sum(1 for v in span if xs[v - 1] and not xs[v])
        assert list(p.changes(a, b)) == [v for v in span if xs[v] != xs[v - 1]]
        assert p.next_change(a, 1_000) == next((v for v in range(a + 1, a + 1_001) if p.at(v) != p.at(v - 1)), None)
        d = r.randrange(-5, 5)
        assert all(p.delayed(d).at(v) == p.at(v - d) and p.inverted().at(v) == 1 - p.at(v) for v in span)
        table = r.randrange(16)
        other = ((0, r.randrange(1, m)),)
        both = p.with_window(combine(p.window, other, m, table))
        assert all(both.at(v) == (table >> (p.at(v) + 2 * p.with_window(other).at(v))) & 1 for v in span)
        assert complement(complement(window, m), m) == window


def test_a_40_mhz_duty_output_is_counted_over_a_second_in_closed_form():
    # DUTY with FRQ = 2**31: a carry every other clock; over 80 million clocks: 40 million high clocks
    duty = Phase(0, 1 << 31, 1 << 32, ((0, 1 << 31),))
    assert duty.count(0, 80_000_000) == 40_000_000
    assert duty.rising(0, 80_000_000) == 40_000_000


def test_an_output_mode_after_a_detector_starts_from_the_phs_the_detector_counted():
    """POS counts 2047 high clocks with FRQ = 2**20 (PHS = 2**31 - 2**20); the NCO then set on P1
    without a PHS write must go high one clock later, in the output, in INA's view and in the trace."""
    chip = Chip(IDLE_IMAGE, compat="chip", inputs=PinStimulus([(200, 1, 1), (200 + 2047, 1, 0)]))
    chip._boot()
    cog = chip.cogs[1]
    cog.state = RUNNING
    cog.dira = 0b10
    chip.note_pins(cog, 0)
    chip.counters.write(cog, 2, 1 << 20, 100)                    # FRQA
    chip.counters.write(cog, 0, 0b01000 << 26, 100)              # POS detector on P0
    chip.counters.write(cog, 0, (0b00100 << 26) | 1, 5000)       # NCO on P1
    assert chip.counters.outputs(cog, 5000) == 0 and chip.counters.outputs(cog, 5001) == 0b10
    assert chip.counters.history.level(1, 5000) == 0 and chip.counters.history.level(1, 5001) == 1
    changes = chip._build_trace(6000).changes
    assert (5001, 0b10, 0b10) in changes
    assert chip.counters.phs(cog, 0, 5001) == (2047 << 20) + (1 << 20)
