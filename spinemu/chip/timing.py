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

from functools import lru_cache

__all__ = ["Timing", "load_timing", "hub_align", "segments_rest", "math_param", "MATH_REF", "access_offsets",
           "wide_offsets"]


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
        self.waitpin = {True: (g("waitpeq/issue"), g("waitpeq/after")),
                        False: (g("waitpne/issue"), g("waitpne/after"))}
        self.waitvid_issue, self.waitvid_after = g("waitvid/issue"), g("waitvid/after")
        self.spr_push, self.spr_pop, self.spr_using = g("spr/push"), g("spr/pop"), g("spr/using")
        self.spr_read_at = g("spr/read_at")
        self.coginit = {False: g("coginit"), True: g("coginit/result")}
        self.coginit_done = g("coginit/done")
        self.locknew = {False: g("locknew"), True: g("locknew/result")}
        self.lockset = {(op, res): g(f"{op}" + ("/result" if res else ""))
                        for op in ("lockset", "lockclr") for res in (False, True)}
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
        # REG bytecodes; a register is read where the plain read reads it (CNT,
        # INA and PHS values depend on it), and written by the last instruction
        self.reg, self.reg_read_at = {}, {}
        for op in (0x3D, 0x3E, 0x3F):
            read_at = g(f"reg/{op:02x}/0/read_at")
            for access in range(3):
                self.reg[(op, access)] = g(f"reg/{op:02x}/{access}")
                self.reg_read_at[(op, access)] = read_at
        # non-math assignment operators by their full byte (push bit included), for
        # targets in hub memory ("mem") and in cog registers ("reg")
        self.assign_mem, self.assign_reg = (
            [g(f"assign/{fam}/{a:02x}") if a & 0x7F in _ASSIGN_CODES else 0 for a in range(256)]
            for fam in ("mem", "reg"))
        self.repeat = {(fam == "reg", st, ins, lg): g(f"repeat/{fam}/{'step' if st else 'plain'}/"
                                                       f"{'loop' if ins else 'exit'}" + ("/long" if lg else ""))
                       for fam in ("mem", "reg") for st in (False, True) for ins in (False, True)
                       for lg in (False, True)}
        # plain math bytecodes: one number, or 33 numbers indexed by math_param
        self._math = [self._table(g(f"math/{0xE0 + f:02x}")) for f in range(32)]
        self._math_assign = {(fam == "reg", f, p): g(f"math_assign/{fam}/{0xE0 + f:02x}" + ("/push" if p else ""))
                             for fam in ("mem", "reg") for f in range(32) for p in (False, True)}
        self._loops = {name: (g(f"{name}/zero") if "strcomp" not in name else 0, g(f"{name}/base"),
                              g(f"{name}/per")) for name in _LOOPS}
        self.init_segments = data.get("init/segments", [4, "H", 4, "H", 4, "H", 4, "H", 4, "H", 4, "H", 0])
        self._loops["run"] = (g("run/zero"), g("run/base"), g("run/per"))

    def _get(self, name: str) -> int:
        v = self.data.get(name)
        if v is None:
            v = self._estimate(name)
        if v is None:
            self.missing.add(name)
            return 0
        return v

    def _estimate(self, name: str):
        """Paths the compiler never emits (or the probes never reached), from their nearest relative.

        * a conditional jump costs the same taken or not (JZ/JNZ/CASE_RANGE
          were measured equal both ways);
        * an inc/dec/sign/set/clear operator costs the same for every size
          field (measured for the sizes Spin uses);
        * a unary MATH assignment that also pushes costs what the plain one
          does; NOT costs what ``!`` does;
        * WRITE without push costs what WRITE with push does;
        * WAITVID's instruction sits where WAITPEQ's does (spinsim has no
          video generator to measure it against).
        """
        d = self.data
        parts = name.split("/")
        if parts[-1] in ("taken", "not"):
            return d.get("/".join(parts[:-1] + ["not" if parts[-1] == "taken" else "taken"]))
        if parts[0] == "assign":
            code = int(parts[2], 16)
            b = code & 0x7F
            for alt in ([b ^ s for s in (0x00, 0x02, 0x04, 0x06)] if 0x20 <= b < 0x40 else []) + [b]:
                for fam in (parts[1], "reg" if parts[1] == "mem" else "mem"):
                    v = d.get(f"assign/{fam}/{alt | (code & 0x80):02x}") or d.get(f"assign/{fam}/{alt | 0x80:02x}")
                    if v is not None:
                        return v
            return None
        if parts[0] == "math_assign":
            op = "e7" if parts[2] == "ff" else parts[2]
            return d.get(f"math_assign/{parts[1]}/{op}")
        if parts[0] == "waitvid":
            return d.get(f"waitpeq/{parts[1]}")
        return None

    # value-dependent paths ------------------------------------------------
    @staticmethod
    def _table(v):
        return v if isinstance(v, list) else [v] * 33

    def math(self, f: int, x: int, y: int) -> int:
        return self._math[f][math_param(0xE0 | f, x, y)]

    def math_assign(self, reg: bool, f: int, x: int, y: int, push: bool) -> int:
        """Cycles of a MATH assignment operator (``x`` = the target's value)."""
        table = self._math[f]
        op = 0xE0 | f
        return self._math_assign[(reg, f, push)] + table[math_param(op, x, y)] - table[MATH_REF.get(op, 0)]

    def _loop(self, name: str, n: int) -> int:
        zero, base, per = self._loops[name]
        return base + per * n if n else zero

    def strsize(self, n: int) -> int:
        return self._loop("strsize", n)

    def strcomp(self, n: int, equal: bool) -> int:
        """``n``: characters compared, the terminating zero or the first difference included."""
        return self._loop("strcomp_eq" if equal else "strcomp_ne", n)

    def fill(self, size: int, count: int) -> int:
        return self._loop(("bytefill", "wordfill", "longfill")[size], count)

    def move(self, size: int, count: int) -> int:
        return self._loop(("bytemove", "wordmove", "longmove")[size], count)

    def returns(self, op: int, frames: int, pushed: bool) -> int:
        name = ("abort", "abort_value", "return", "return_value")[op - 0x30]
        return self._get(f"{name}/{'push' if pushed else 'drop'}") + self._get("abort/per_frame") * (frames - 1)

    def run(self, params: int) -> int:
        """RUN with the ROM routine it hands over to, for a method with ``params`` parameters."""
        return self._loop("run", params)

    def interpreter_start(self, t_first: int, phase: int) -> int:
        """Cycle of the first bytecode of a Spin cog whose first instruction runs at ``t_first``."""
        return t_first + segments_rest(self.init_segments, phase, t_first)


_ASSIGN_CODES = {0x00, 0x08, 0x0C, 0x10, 0x14, 0x18, 0x1C} | {b for b in range(0x20, 0x40) if not b & 1}
_LOOPS = ("strsize", "strcomp_eq", "strcomp_ne", "bytefill", "wordfill", "longfill", "bytemove", "wordmove", "longmove")


def load_timing(data: dict | None = None) -> Timing:
    """The measured timing (:mod:`spinemu.chip.timing_data`), or ``data`` if given."""
    if data is None:
        return _measured()
    return Timing(data)


@lru_cache(maxsize=1)
def _measured() -> Timing:
    from .timing_data import DATA
    return Timing(DATA)


#: the parameter each value-dependent math bytecode's ROM loop depends on
def math_param(op: int, x: int, y: int) -> int:
    """Loop parameter of math operator ``op`` for ``x OP y`` (``x`` alone if unary).

    DIV/MOD: bit length of ``|y|`` (0: the divide-by-zero path); ENCODE: the
    leading zeros of ``x``.  Other operators take the same path whatever the
    values (parameter 0).

    >>> math_param(0xF6, 100, -7), math_param(0xF1, 1, 0), math_param(0xEC, 5, 6)
    (3, 31, 0)
    """
    if op in (0xF6, 0xF7):
        return (-y & 0xFFFFFFFF if y & 0x80000000 else y).bit_length()
    if op == 0xF1:
        return 32 - x.bit_length()
    return 0


#: the parameter whose cycles the assignment-operator table includes
MATH_REF = {0xF6: 1, 0xF7: 1, 0xF1: 0}


def access_offsets() -> list:
    """Per opcode: cycles from the fetch to the bytecode's access of shared state.

    The scheduler orders cogs by these moments, not by bytecode starts, so
    that a cog reading a variable and another writing it see each other in
    the order of their hub accesses.  Measured on spinsim 0.99 logs of
    tests/data/chip/programs/access_*.spin (completion cycle of the hub
    instruction that reads or writes the variable, minus the fetch's).  An
    update (a USING access with an assignment operator: ``x++``, ``x += n``)
    reads its variable at the moment given here and writes it back with the
    bytecode's last instruction, 4 cycles before the next bytecode starts
    (tests/chip/tools/derive_update_moments.py measured both on every
    access form and operator): the handlers write it then (see
    :meth:`spinemu.chip.scheduler.Scheduler.defer_write`).  Other bytecodes
    touch only their own stack: 0.

    ==========================  ====  ====  ===============
    access                      push  pop   update (read)
    ==========================  ====  ====  ===============
    VAR/LOC long ($40-$7F)       112   144   192
    memory, offset operand       224   256   304
    ... indexed                  240   272   320
    memory, address popped       176   208   256
    ... indexed                  192   224   272
    ==========================  ====  ====  ===============

    REG reads 144 (bit 220, range 244), SPR 164 (PUSH_SPR and USING_SPR: where
    they read the register), LOCKNEW/LOCKSET/LOCKCLR 112, COGSTOP 112 (when the
    target stops), COGINIT 172 (when the new cog starts).  Register reads sit
    at the read moment because CNT, INA and a counter's PHS in an input mode
    depend on when they are read: by then every other cog has run up to it.
    """
    acc = [0] * 256
    for op in range(0x40, 0x80):
        acc[op] = (112, 144, 192, 0)[op & 3]
    for op in range(0x80, 0xE0):
        table = (224, 256, 304) if (op >> 2) & 3 else (176, 208, 256)
        if op & 3 != 3:
            acc[op] = table[op & 3] + (16 if op & 0x10 else 0)
    acc[0x3D], acc[0x3E], acc[0x3F], acc[0x24], acc[0x26] = 220, 244, 144, 164, 164
    for op in range(0x29, 0x30):
        if op != 0x2C:
            acc[op] = 112
    acc[0x21] = 112
    acc[0x28] = acc[0x2C] = 172
    return acc


def wide_offsets() -> bytes:
    """Per opcode: 16 where a two-byte offset operand (its first byte >= $80) delays the access.

    A VAR, LOC or DAT access ($80-$DF with a base) whose offset is 128 or more
    reads its second offset byte first: its hub access comes 16 cycles later
    than :func:`access_offsets` says (measured on spinsim: a long push 240, a
    pop 272).  The moment of the bytecode at ``pc`` is therefore
    ``acc[op] + (wide[op] & (mem[pc + 1] >> 3))``: bit 7 of the offset's
    first byte, shifted to 16.
    """
    wide = bytearray(256)
    for op in range(0x80, 0xE0):
        if (op >> 2) & 3 and op & 3 != 3:
            wide[op] = 16
    return bytes(wide)
