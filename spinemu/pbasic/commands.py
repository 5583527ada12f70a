"""Run-time behaviour of the BS2's pin and timing commands.

Each ``make_*`` function takes compiled argument closures (``f(m) -> int``)
and returns the instruction body ``run(m) -> next pc | None``.  Semantics
follow the BASIC Stamp Syntax and Reference Manual v2.2, chapter 5 (the BS2
columns of each command's Quick Facts table); where the manual leaves a
detail open the choice is marked [OPEN] here, warned about at run time and
listed in docs/pbasic.md.

Units on the BS2: PULSOUT/PULSIN/RCTIME 2 us, PAUSE/COUNT/FREQOUT/DTMFOUT ms,
NAP 18 ms x 2^n, SLEEP 1 s, PWM cycles of about 1 ms.
"""
from __future__ import annotations

import math
from typing import Callable, Optional

from . import messages as M
from .machine import MASK, Machine, StopRun

__all__ = ["pin_arg", "make_pin_op", "make_pause", "make_pulsout", "make_pulsin",
           "make_rctime", "make_count", "make_freqout", "make_dtmfout", "make_pwm",
           "make_button", "make_random", "make_nap", "make_sleep", "make_end",
           "random_next", "DTMF_TONES", "GLITCH_PERIOD_US", "GLITCH_US"]

PULSE_TIMEOUT_UNITS = 65535          # 16-bit counters of 2 us units: 131.07 ms
GLITCH_PERIOD_US = 2_304_000         # watchdog wake-up every 2.3 s [OPEN: exact period]
GLITCH_US = 18_000                   # outputs released for ~18 ms

#: DTMF tone pairs (Hz) for DTMFOUT values 0-15: 0-9, *, #, A, B, C, D.
DTMF_TONES = {
    1: (697, 1209), 2: (697, 1336), 3: (697, 1477), 12: (697, 1633),
    4: (770, 1209), 5: (770, 1336), 6: (770, 1477), 13: (770, 1633),
    7: (852, 1209), 8: (852, 1336), 9: (852, 1477), 14: (852, 1633),
    10: (941, 1209), 0: (941, 1336), 11: (941, 1477), 15: (941, 1633),
}


def pin_arg(f: Callable, warn: Callable, highest: int = 15) -> Callable:
    """A pin argument: 0..15 (SERIN/SEROUT: 16 is the programming port);
    larger values use their low 4 bits (with a warning)."""
    def pin(m):
        p = f(m)
        if p > highest:
            warn(m, M.W_PIN_RANGE.format(p, p & 15))
            p &= 15
        return p
    return pin


# ------------------------------------------------------------------ pins
def make_pin_op(kind: str, pin: Callable) -> Callable:
    """HIGH, LOW, TOGGLE, INPUT, OUTPUT, REVERSE (README 4.8)."""
    if kind == "high":
        def run(m):
            bit = 1 << pin(m)
            m.w[1] |= bit
            m.w[2] |= bit
            m.pins_changed()
    elif kind == "low":
        def run(m):
            bit = 1 << pin(m)
            m.w[1] &= ~bit
            m.w[2] |= bit
            m.pins_changed()
    elif kind == "toggle":
        def run(m):
            bit = 1 << pin(m)
            m.w[1] ^= bit
            m.w[2] |= bit
            m.pins_changed()
    elif kind == "input":
        def run(m):
            m.w[2] &= ~(1 << pin(m))
            m.pins_changed()
    elif kind == "output":
        def run(m):
            m.w[2] |= 1 << pin(m)
            m.pins_changed()
    elif kind == "reverse":
        def run(m):
            m.w[2] ^= 1 << pin(m)
            m.pins_changed()
    else:  # pragma: no cover - compiler only asks for the six above
        raise ValueError(kind)
    return run


def make_pause(ms: Callable) -> Callable:
    def run(m):
        m.advance(ms(m) * 1000)
    return run


# ------------------------------------------------------------------ pulses
def make_pulsout(pin: Callable, duration: Callable) -> Callable:
    """Make the pin an output, invert it for duration x 2 us, restore it."""
    def run(m):
        p = pin(m)
        units = duration(m)
        m.set_pin(p, output=True)
        if units == 0:
            return
        bit = 1 << p
        m.w[1] ^= bit
        m.pins_changed()
        m.advance(2 * units)
        m.w[1] ^= bit
        m.pins_changed()
    return run


def _wait_level(m: Machine, pin: int, level: int, timeout_us: int) -> Optional[int]:
    """Wait until an input pin reads ``level``; return the time, or None at the timeout."""
    return m.wait_input(pin, level, m.t + timeout_us)


def make_pulsin(pin: Callable, state: Callable, write: Callable) -> Callable:
    """Measure a pulse of ``state`` in 2 us units; 0 on timeout (131.07 ms).

    The pin becomes an input.  If the pin already reads ``state``, PULSIN
    first waits for it to leave that state.  [OPEN] each of the three waits
    has its own 131.07 ms limit.
    """
    limit = 2 * PULSE_TIMEOUT_UNITS

    def run(m):
        p = pin(m)
        s = 1 if state(m) & 1 else 0
        m.set_pin(p, output=False)
        if _wait_level(m, p, 1 - s, limit) is None:
            write(m, 0)
            return
        start = _wait_level(m, p, s, limit)
        if start is None:
            write(m, 0)
            return
        end = _wait_level(m, p, 1 - s, limit)
        write(m, 0 if end is None else min(MASK, (end - start) // 2))
    return run


def make_rctime(pin: Callable, state: Callable, write: Callable) -> Callable:
    """How long an input stays in ``state``, in 2 us units (manual: 1 if it is not
    in ``state`` at the start, 0 if longer than 65535 units)."""
    def run(m):
        p = pin(m)
        s = 1 if state(m) & 1 else 0
        m.set_pin(p, output=False)
        if m.input_level(p) != s:
            write(m, 1)
            return
        start = m.t
        end = _wait_level(m, p, 1 - s, 2 * PULSE_TIMEOUT_UNITS)
        write(m, 0 if end is None else max(1, (end - start) // 2))
    return run


def make_count(pin: Callable, duration: Callable, write: Callable) -> Callable:
    """Count cycles (rising edges) on an input during ``duration`` ms."""
    def run(m):
        p = pin(m)
        m.set_pin(p, output=False)
        start = m.t
        end = start + duration(m) * 1000
        level = m.input_level(p)
        edges = m.input_edges(p, start, end)
        rising = 0
        for _ in edges:
            level ^= 1
            rising += level
        m.advance_to(end)
        write(m, min(MASK, rising))
    return run


# ------------------------------------------------------------------ sound
def _tone(m: Machine, p: int, ms: int, f1: int, f2: int, warn: Callable) -> None:
    """Drive a tone for ``ms``: [OPEN] a square wave at the tone frequency (two
    tones: the sign of the sum of the sines, sampled every 5 us); silence (both
    0) holds the pin low; the pin is left an output, low."""
    f1 &= 0x7FFF                      # the BS2 ignores bit 15 (manual, FREQOUT)
    f2 &= 0x7FFF
    bit = 1 << p
    start = m.t
    end = start + ms * 1000
    m.w[2] |= bit
    m.w[1] &= ~bit
    m.pins_changed()
    if f1 == 0 and f2 == 0:
        m.advance_to(end)
        return
    warn(m, M.W_FREQOUT)
    if not (f1 and f2):
        # One tone: a square wave, high for the first half period.
        half = 500_000 / (f1 or f2)
        level, k = 0, 0
        while True:
            t = start + int(round(k * half))
            if t >= end:
                break
            m.advance_to(t)
            m.w[1] ^= bit
            level ^= 1
            m.pins_changed()
            k += 1
    else:
        # Two tones: the sign of the sum of the sines, sampled every 5 us.
        w1 = 2 * math.pi * f1 / 1e6
        w2 = 2 * math.pi * f2 / 1e6
        level = 0
        for t in range(start, end, 5):
            x = t - start
            new = 1 if math.sin(w1 * x) + math.sin(w2 * x) > 0 else 0
            if new != level:
                m.advance_to(t)
                m.w[1] ^= bit
                m.pins_changed()
                level = new
    m.advance_to(end)
    if level:
        m.w[1] &= ~bit
        m.pins_changed()


def make_freqout(pin: Callable, duration: Callable, f1: Callable, f2: Optional[Callable],
                 warn: Callable) -> Callable:
    def run(m):
        _tone(m, pin(m), duration(m), f1(m), f2(m) if f2 else 0, warn)
    return run


def make_dtmfout(pin: Callable, on_ms: Optional[Callable], off_ms: Optional[Callable],
                 tones: list, warn: Callable) -> Callable:
    """DTMF digits: each tone ``on_ms`` (default 200 ms), then ``off_ms`` (default 50 ms) low."""
    def run(m):
        p = pin(m)
        on = on_ms(m) if on_ms else 200
        off = off_ms(m) if off_ms else 50
        for tf in tones:
            lo, hi = DTMF_TONES[tf(m) & 15]
            _tone(m, p, on, lo, hi, warn)
            m.advance(off * 1000)
    return run


def make_pwm(pin: Callable, duty: Callable, cycles: Callable, warn: Callable) -> Callable:
    """PWM: [OPEN] per the BS2 manual, 256 ticks of ~4 us per cycle; each tick adds
    ``duty`` to an 8-bit accumulator and outputs its carry; afterwards the pin is
    made an input."""
    tick = 4

    def run(m):
        p = pin(m)
        d = duty(m) & 0xFF
        n = cycles(m) * 256
        bit = 1 << p
        warn(m, M.W_PWM)
        acc = 0
        m.w[2] |= bit
        for _ in range(n):
            acc += d
            out = acc >> 8
            acc &= 0xFF
            if bool(m.w[1] & bit) != bool(out):
                m.w[1] ^= bit
                m.pins_changed()
            m.advance(tick)
        m.w[2] &= ~bit
        m.pins_changed()
    return run


# ------------------------------------------------------------------ inputs
def make_button(pin: Callable, down: Callable, delay: Callable, rate: Callable,
                read_ws: Callable, write_ws: Callable, target: Callable, label) -> Callable:
    """BUTTON, modelled from the manual's description (workspace counts loops):
    the first pass that sees the button down acts; while held, it acts again
    after ``delay`` passes and then every ``rate`` passes; delay 0 acts on
    every pass, delay 255 only once per press.  Branch when the action
    matches TargetState (1 = pressed)."""
    def run(m):
        p = pin(m)
        m.set_pin(p, output=False)
        pressed = m.input_level(p) == (down(m) & 1)
        ws = read_ws(m)
        dly = delay(m) & 0xFF
        act = False
        if not pressed:
            ws = 0
        elif ws == 0:
            act = True
            ws = dly
        elif dly != 255:
            ws -= 1
            if ws == 0:
                act = True
                ws = rate(m) & 0xFF
        write_ws(m, ws)
        if act == bool(target(m) & 1):
            return label.pc
        return None
    return run


def random_next(x: int) -> int:
    """[OPEN] One RANDOM step: a maximal 16-bit Fibonacci LFSR (taps 16, 14, 13, 11);
    0 is first mapped to $ACE1 so that RANDOM on a cleared variable still moves.

    >>> random_next(0) != 0, random_next(1)
    (True, 32768)
    """
    x &= MASK
    if x == 0:
        x = 0xACE1
    bit = (x ^ (x >> 2) ^ (x >> 3) ^ (x >> 5)) & 1
    return (x >> 1) | (bit << 15)


def make_random(read: Callable, write: Callable, warn: Callable) -> Callable:
    def run(m):
        warn(m, M.W_RANDOM)
        write(m, random_next(read(m)))
    return run


# ------------------------------------------------------------------ power
def _glitch_wake(m: Machine) -> None:
    """On waking from NAP/SLEEP the outputs are released for ~18 ms (optional)."""
    d = m.w[2]
    if not (m.end_glitch and d):
        return
    m.warn(m.here(), M.W_GLITCH)
    m.trace.record(m.t, 0, 0)
    m.advance(GLITCH_US)
    m.trace.record(m.t, d, m.w[1] & d)


def make_nap(period: Callable) -> Callable:
    """NAP n: low-power pause of 18 ms x 2^n (n 0-7)."""
    def run(m):
        m.advance(18_000 << (period(m) & 7))
        _glitch_wake(m)
    return run


def make_sleep(seconds: Callable) -> Callable:
    """SLEEP n: n seconds [OPEN: the BS2 sleeps in 2.3 s watchdog periods, +-1 %]."""
    def run(m):
        s = seconds(m)
        if s:
            m.advance(s * 1_000_000)
            _glitch_wake(m)
    return run


def make_end(reason: str) -> Callable:
    """END (low power, outputs glitch every 2.3 s when ``end_glitch`` is on) or STOP."""
    def run(m):
        if reason == "end" and m.end_glitch and m.limit is not None:
            d = m.w[2]
            if d:
                m.warn(m.here(), M.W_GLITCH)
            t = m.t + GLITCH_PERIOD_US
            while d and t < m.limit:
                m.t = t
                m.trace.record(t, 0, 0)
                m.t = min(t + GLITCH_US, m.limit)
                m.trace.record(m.t, d, m.w[1] & d)
                t += GLITCH_PERIOD_US
            m.t = m.limit
        raise StopRun(reason)
    return run
