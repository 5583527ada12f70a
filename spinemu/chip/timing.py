"""How many cycles the ROM Spin interpreter spends on each bytecode.

The model (docs/timing.md explains it in full):

* Every bytecode begins with the interpreter's fetch loop: one instruction,
  then a hub read of the opcode.  A hub instruction issued at cycle ``s``
  completes at the first cycle ``>= s + 8`` that falls on the cog's hub
  window (``t mod 16 == hub_phase``).  So the fetch completes at
  ``tf = align(t_start + 12)``.
* From ``tf`` on, the interpreter's path for the bytecode is a fixed list of
  plain instructions (4 cycles each) and hub instructions; because ``tf`` is
  on the hub window, the time from ``tf`` to the start of the next bytecode
  is one constant per path: ``rest``.  Paths differ by opcode, operand
  length, assignment operator, whether a jump is taken, and by loop counts
  (multiply, divide, string and memory loops).
* Events inside a bytecode (a CNT read, an OUTA/DIRA write, a WAITCNT) are
  constant offsets from ``tf`` too.

The constants are measured, not guessed: ``tests/chip/tools/derive_timing.py``
runs probe programs on spinsim 0.99 (Parallax's ROM interpreter on
cycle-exact cogs), lines every bytecode up with spinemu's own execution, and
writes :mod:`spinemu.chip.timing_data`.
"""
from __future__ import annotations

from typing import Optional

__all__ = ["Timing", "load_timing", "hub_align", "segments_rest"]


def hub_align(t: int, phase: int) -> int:
    """The first cycle ``>= t`` on the hub window ``phase`` (mod 16).

    >>> hub_align(20, 8), hub_align(24, 8), hub_align(25, 8)
    (24, 24, 40)
    """
    return t + ((phase - t) & 15)


def segments_rest(segments, phase: int = 8, t: int = 0) -> int:
    """Cycles a list of segments takes from an aligned start.

    ``segments`` alternates counts of plain instructions and ``"H"`` (a hub
    instruction).  Used for the cog start-up path and by the derivation.

    >>> segments_rest([14, "H", 1, "H", 21, "H", 3], 8, 8)
    188
    """
    start = t
    for s in segments:
        if s == "H":
            t = hub_align(t + 8, phase)
        else:
            t += 4 * s
    return t - start


class Timing:
    """Cycle counts for every bytecode path, built from a table of measurements.

    Args:
        data: the table (``timing_data.DATA``): names to cycle counts.  A
            missing name counts 0 cycles and is listed in :attr:`missing`.
    """

    def __init__(self, data: dict):
        self.data = data
        self.missing: set = set()
        g = self._get
        self.frame = g("frame")
        self.call, self.call_obj, self.call_obj_x = g("call"), g("call_obj"), g("call_obj_x")
        both = ((False, False), (False, True), (True, False), (True, True))
        for name in ("tjz", "djnz", "jz", "jnz", "case_value", "case_range"):
            setattr(self, name, {(lg, tk): g(f"{name}/{'long' if lg else 'short'}/{'taken' if tk else 'not'}")
                                 for lg, tk in both})
        self.jmp = {False: g("jmp/short"), True: g("jmp/long")}
        self.case_done, self.look_done = g("case_done"), g("look_done")
        for name in ("lookup_value", "lookdown_value", "lookup_range", "lookdown_range"):
            setattr(self, name, {True: g(f"{name}/found"), False: g(f"{name}/not")})
        self.pop_bytes = g("pop")
        self.clkset, self.lockret = g("clkset"), g("lockret")
        self.cogstop, self.cogstop_at = g("cogstop"), g("cogstop/at")
        self.waitcnt_issue, self.waitcnt_min, self.waitcnt_after = (
            g("waitcnt/issue"), g("waitcnt/min"), g("waitcnt/after"))
        self.waitpin_issue, self.waitpin_after = g("waitpin/issue"), g("waitpin/after")
        self.waitvid_issue, self.waitvid_after = g("waitvid/issue"), g("waitvid/after")
        self.spr_push, self.spr_pop, self.spr_using = g("spr/push"), g("spr/pop"), g("spr/using")
        self.spr_read_at, self.spr_write_at = g("spr/read_at"), g("spr/write_at")
        self.spr_using_write_at = g("spr/using_write_at")
        self.coginit = {False: g("coginit"), True: g("coginit/result")}
        self.coginit_done = g("coginit/done")
        self.locknew = {False: g("locknew"), True: g("locknew/result")}
        self.lockset = {False: g("lockset"), True: g("lockset/result")}
        self.push_const, self.push_mask = g("push_const"), g("push_mask")
        self.push_imm = [0] + [g(f"push_imm/{n}") for n in range(1, 5)]
        self.var = [0] * 0x80
        for op in range(0x40, 0x80):
            if op & 3 != 2:
                self.var[op] = g(f"var/{op:02x}")
        self.var_using = {False: g("var_using/var"), True: g("var_using/loc")}
        self.mem = {}
        self.mem_using = {}
        for op in range(0x80, 0xE0):
            for lg in ((False, True) if (op >> 2) & 3 else (False,)):
                name = f"mem/{op:02x}" + ("/long" if lg else "")
                if op & 3 == 2:
                    self.mem_using[(op, lg)] = g(name)
                else:
                    self.mem[(op, lg)] = g(name)
        self.reg, self.reg_read_at, self.reg_write_at = {}, {}, {}
        for op in (0x3D, 0x3E, 0x3F):
            for access in range(3):
                for pins in (False, True):
                    key = (op, access, pins)
                    name = f"reg/{op:02x}/{access}" + ("/pins" if pins else "")
                    self.reg[key] = g(name)
                    self.reg_read_at[key] = g(name + "/read_at")
                    self.reg_write_at[key] = g(name + "/write_at")
        self.assign = [0] * 0x80
        for b in range(0x40):
            self.assign[b] = g(f"assign/{b:02x}") if b in _ASSIGN_CODES else 0
        self.assign_push = {False: 0, True: g("assign/push")}
        self.repeat = {(st, ins): g(f"repeat/{'step' if st else 'plain'}/{'loop' if ins else 'exit'}")
                       for st in (False, True) for ins in (False, True)}
        self._math = [g(f"math/{0xE0 + f:02x}") for f in range(32)]
        self._math_assign = [g(f"math_assign/{0xE0 + f:02x}") for f in range(32)]
        self._loops = {name: (g(f"{name}/base"), g(f"{name}/per")) for name in _LOOPS}
        self.init_segments = data.get("init/segments", [4, "H", 4, "H", 4, "H", 4, "H", 4, "H", 4, "H", 0])
        self.run_base, self.run_per_param = g("run/base"), g("run/per_param")

    def _get(self, name: str) -> int:
        v = self.data.get(name)
        if v is None:
            self.missing.add(name)
            return 0
        return v

    # value-dependent paths ------------------------------------------------
    def math(self, f: int, x: int, y: int) -> int:
        return self._math[f] + self._math_extra(f, x, y)

    def math_assign(self, f: int, x: int, y: int) -> int:
        return self._math_assign[f] + self._math_extra(f, x, y)

    def _math_extra(self, f: int, x: int, y: int) -> int:
        return 0

    def _loop(self, name: str, n: int) -> int:
        base, per = self._loops[name]
        return base + per * n

    def strsize(self, n: int) -> int:
        return self._loop("strsize", n)

    def strcomp(self, n: int, equal: bool) -> int:
        return self._loop("strcomp", n)

    def fill(self, size: int, count: int) -> int:
        return self._loop(("bytefill", "wordfill", "longfill")[size], count)

    def move(self, size: int, count: int) -> int:
        return self._loop(("bytemove", "wordmove", "longmove")[size], count)

    def returns(self, op: int, frames: int, pushed: bool) -> int:
        name = ("abort", "abort_value", "return", "return_value")[op - 0x30]
        return self._get(f"{name}/{'push' if pushed else 'drop'}") + self._get("abort/per_frame") * (frames - 1)

    def run(self, params: int) -> int:
        return self.run_base + self.run_per_param * params

    def interpreter_start(self, t_first: int, phase: int) -> int:
        """Cycle of the first bytecode of a Spin cog whose first instruction runs at ``t_first``."""
        return t_first + segments_rest(self.init_segments, phase, t_first)


_ASSIGN_CODES = {0x00, 0x08, 0x0C, 0x10, 0x14, 0x18, 0x1C} | {b for b in range(0x20, 0x40) if not b & 1}
_LOOPS = ("strsize", "strcomp", "bytefill", "wordfill", "longfill", "bytemove", "wordmove", "longmove")


def load_timing(data: Optional[dict] = None) -> Timing:
    """The measured timing (:mod:`spinemu.chip.timing_data`), or ``data`` if given."""
    if data is None:
        from .timing_data import DATA
        data = DATA
    return Timing(data)
