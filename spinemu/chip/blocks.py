"""Runs of Spin bytecode compiled to Python functions: the block cache (hot path).

The interpreter (:mod:`.spin`) pays, for every bytecode, a dispatch, the
operand decoding and the stack pointer's round trip through the cog object.
A *block* is a run of bytecodes from one hub address, compiled once into one
Python function that does the same work with the operands, stack offsets and
cycle counts folded into its text:

* **Timing is static inside a block.**  Every bytecode's fetch completes on
  the cog's hub window, and the rest of its path is a fixed count from there
  (docs/timing.md), so the fetch of bytecode ``j+1`` completes
  ``ceil16(rest_j + 12)`` cycles after the fetch of bytecode ``j``, whatever
  the window.  Only value-dependent paths (division, ENCODE, taken jumps,
  WAITCNT) add a term computed at run time.
* **Scheduling is unchanged.**  The interpreter starts a bytecode only while
  its hub access comes before the next access of any other cog
  (:meth:`Scheduler._run_spin`).  A block first checks that its *last*
  access, with the slowest value-dependent paths, is still before that
  limit; if not, it does nothing and the run loop interprets bytecodes one by
  one as before.  A WAITCNT does not end a block: the block checks the limit
  again for the bytecodes after the wait, and leaves after the wait if they
  would pass it.
* **Loops run inside the block.**  A block whose last bytecode jumps back to
  its own start with the stack as it found it (a ``repeat`` whose body is one
  block) goes round again without returning, while its next pass still ends
  before the limit.
* **Stack stores are lazy.**  A stack slot written twice in a block is
  stored once, with its last value, before anything that could read hub
  RAM there (a hub variable, a computed address, a frame, the block's end):
  nothing else runs while a block runs, so only the last value is seen.
* **Rare things are left to the interpreter** ("deoptimisation"): a write to
  a hub long that a parked busy loop reads or that holds compiled code, an
  unusual stack pointer, a call that would overflow the stack.  The block
  then stops *before* that bytecode, with the cog in exactly the state the
  interpreter would have it in, and the run loop interprets the bytecode.
* **Code may change.**  A block compares its code bytes with hub RAM when it
  starts (any writer, even a stack push, can change them) and is recompiled
  if they differ; writes that go through the checked paths to a long holding
  compiled code leave the block first (``Chip.watch`` bit ``CODE``), so a
  block never runs bytes that its own earlier bytecodes changed.
* **Private variants** (:meth:`BlockCompiler.compile_private`, for running
  ahead, :mod:`.ahead`) hold only bytecodes that touch the cog's own window
  (stack, locals), code, and hub longs that are read-only for now
  (``Chip.watch`` bit ``RO``); they check that at entry.

Compiled: constants, VAR/LOC longs, memory access with every assignment
operator but the undefined ones, math, FRAME, CALL, CALL_OBJ, RETURN,
jumps, REPEAT, CASE tests and WAITCNT.  Everything touching registers, pins,
cogs, locks or the clock is interpreted.  The bytecode families that read
and write data are in :mod:`.blockops`.

A block function is called as ``f(cog, tf, limit)`` with ``tf`` the cycle its
first fetch completes; it returns the start cycle of the cog's next bytecode,
``-1`` when it did nothing, ``-2 - t`` when it stopped early before a
bytecode starting at ``t`` that the interpreter must run, or (private
variants) :data:`.ahead.CLAIM` / :data:`.ahead.WANT_RO` when its window or
read-only longs must be claimed first.
"""
from __future__ import annotations

from .ahead import AHEAD, CLAIM, RO, WANT_RO, _hole_in
from .blockops import BUSY, CODE, DataOps, _Stop, _is_literal
from .mathops import BINARY, MASK32, UNARY
from .spin import random_forward, random_reverse

__all__ = ["BlockCompiler", "MAX_OPS", "HOT", "CODE", "BUSY", "PROGRAM", "WATCHPOINT"]

#: bytecodes in one block at most
MAX_OPS = 48
#: times a block start is reached before it is compiled (cold code stays interpreted)
HOT = 8
#: ``Chip.watch`` bits: the program's own code (runtime check), a debugger watchpoint
PROGRAM, WATCHPOINT = 4, 8

_BASE_LOCALS = {"vbase": "vb", "dbase": "db", "pbase": "pb"}
#: placeholders in generated text: ``nb + `` in a block that loops, else nothing; and a deopt
#: before the first bytecode: nothing was done (on the first pass of a loop)
_NB = "@NB@"
_FIRST_EXIT = "@FIRST@"


def _ceil16(x: int) -> int:
    return x + (-x & 15)


class _Block:
    """Compile-time state of one block being generated."""

    def __init__(self, start: int, private: bool):
        self.start = start
        self.private = private          # the private variant (ahead.py): only the cog's window and read-only longs
        self.lines: list = []           # the body, indented one level
        self.off = 0                    # stack offset (bytes) from the stack pointer at entry
        self.lo = 0                     # lowest and highest stack byte offsets touched
        self.hi = 0
        self.vals: dict = {}            # stack offset -> expression of the long stored there
        self.pending: dict = {}         # stack offset -> value not stored in hub RAM yet
        self.names = 0
        self.n = 0                      # bytecodes compiled
        self.d = 0                      # the current fetch is at tf + d ...
        self.tf = "tf"                  # ... where tf is this local
        self.worst = 0                  # latest possible current fetch, from the segment's first
        self.reach = 0                  # latest possible hub access, from the segment's first fetch
        self.segments: list = []        # reach of each segment before a WAITCNT's continuation check
        self.t_start = None             # expression: start cycle of the current bytecode
        self.pc = start                 # address of the current bytecode
        self.op_pc = start
        self.op_off = 0                 # stack offset when the current bytecode started
        self.bases: set = set()         # cog fields read into locals at entry
        self.end = False
        self.loops = False              # it jumps back to its start without returning
        self.waits = False              # a WAITCNT continues the block
        self.dlo = 1 << 30              # lowest and highest local-variable byte offsets touched (from dbase)
        self.dhi = -(1 << 30)
        self.locs: set = set()          # local-variable long offsets touched (from dbase)
        self.loc_writes: set = set()    # local-variable offsets written (watch bits checked at entry)
        self.var_reads: set = set()     # offsets (from vbase) of the hub variables it reads
        self.ro: set = set()            # (base local or None, offset): hub longs a private variant reads
        self.shared = False             # it writes hub RAM outside the stack and locals, or calls (no private variant)

    def snapshot(self) -> dict:
        state = dict(self.__dict__)
        state["lines"] = len(self.lines)
        for k in ("vals", "pending", "segments"):
            state[k] = type(self.__dict__[k])(self.__dict__[k])
        for k in ("bases", "locs", "loc_writes", "var_reads", "ro"):
            state[k] = set(self.__dict__[k])
        return state

    def restore(self, state: dict) -> None:
        lines = self.lines
        del lines[state["lines"]:]
        self.__dict__.update(state)
        self.lines = lines
        self.pc = self.op_pc

    def name(self, prefix="v") -> str:
        self.names += 1
        return f"{prefix}{self.names}"

    def emit(self, line: str, indent: int = 0) -> None:
        self.lines.append("    " * (indent + 1) + line)

    def let(self, expr: str) -> str:
        """A name or literal holding ``expr``."""
        if expr.isidentifier() or _is_literal(expr):
            return expr
        v = self.name()
        self.emit(f"{v} = {expr}")
        return v

    @staticmethod
    def slot(off: int) -> str:
        k = off // 4
        return "L[i]" if k == 0 else f"L[i + {k}]" if k > 0 else f"L[i - {-k}]"

    def touch(self, off: int, size: int = 4) -> None:
        self.lo = min(self.lo, off)
        self.hi = max(self.hi, off + size)

    def loc(self, off: int, size: int = 4) -> None:
        """The block touches the bytes ``[dbase + off, dbase + off + size)`` (whole longs)."""
        self.base("dbase")
        self.dlo = min(self.dlo, off)
        self.dhi = max(self.dhi, off + size)
        self.locs.update(range(off, off + size, 4))

    def read(self, off: int) -> str:
        v = self.vals.get(off)
        if v is None:
            self.touch(off)
            v = self.name()
            self.emit(f"{v} = {self.slot(off)}")
            self.vals[off] = v
        return v

    def write(self, off: int, expr: str) -> str:
        """Stack slot ``off`` holds ``expr`` from now on (stored in hub RAM at the next :meth:`flush`)."""
        v = self.let(expr)
        self.touch(off)
        self.vals[off] = v
        self.pending[off] = v
        return v

    def flush(self, indent: int = 0) -> None:
        """Store the stack slots written since the last flush (before hub RAM may be read there)."""
        for off in sorted(self.pending):
            self.emit(f"{self.slot(off)} = {self.pending[off]}", indent)
        self.pending.clear()

    def push(self, expr: str) -> str:
        v = self.write(self.off, expr)
        self.off += 4
        return v

    def pop(self) -> str:
        self.off -= 4
        return self.read(self.off)

    def peek(self) -> str:
        return self.read(self.off - 4)

    def base(self, field: str) -> str:
        """The local holding cog field ``field`` (read once at entry)."""
        self.bases.add(field)
        return _BASE_LOCALS[field]

    def forget(self) -> None:
        """A write to a computed address may have hit a stack slot: reread them (stored before the write)."""
        assert not self.pending
        self.vals.clear()

    def sp_expr(self, off: int = None) -> str:
        off = self.off if off is None else off
        return "sp" if off == 0 else f"sp + {off}" if off > 0 else f"sp - {-off}"

    def exit_lines(self, pc_expr: str, indent: int = 0, n: int = None) -> None:
        """Write the cog's pc, sp and bytecode count back (before a return); stores first."""
        self.flush(indent)
        self.emit(f"c.pc = {pc_expr}", indent)
        self.emit(f"c.sp = {self.sp_expr()}", indent)
        self.emit(f"c.bytecodes += {_NB}{self.n + 1 if n is None else n}", indent)

    def deopt(self, cond: str, want: str = None) -> None:
        """Leave the block before the current bytecode when ``cond`` holds.

        ``want``: an address the run loop should make read-only (private variants).
        """
        self.flush()
        self.emit(f"if {cond}:")
        if want:
            self.emit(f"WANT[0] = {want}", 1)
        if self.n == 0:                 # nothing done yet, unless on a later pass of a loop
            self.emit(_FIRST_EXIT, 1)
        self.emit(f"c.pc = {self.op_pc}", 1)
        self.emit(f"c.sp = {self.sp_expr(self.op_off)}", 1)
        self.emit(f"c.bytecodes += {_NB}{self.n}", 1)
        self.emit(f"return -2 - ({self.t_start if self.n else 't0'})", 1)

    def now(self, extra: int = 0) -> str:
        d = self.d + extra
        return self.tf if d == 0 else f"{self.tf} + {d}"


_GENERATOR_KEY = []
#: generated blocks kept in the code cache per start address and settings (the oldest go first)
_KEEP_PER_START = 8


def _generator_key() -> int:
    """A checksum of the modules whose code generates blocks (so that blocks generated by another
    version of them are not taken from the cache), or -1 if one cannot be read."""
    if not _GENERATOR_KEY:
        import sys
        import zlib
        key = 0
        for name in ("blocks", "blockops", "ahead", "mathops", "timing"):
            try:
                with open(sys.modules[f"{__package__}.{name}"].__file__, "rb") as f:
                    key = zlib.crc32(f.read(), key)
            except (OSError, KeyError, AttributeError, TypeError):
                key = -1
                break
        _GENERATOR_KEY.append(key)
    return _GENERATOR_KEY[0]


class BlockCompiler(DataOps):
    """Compiles blocks for one chip.

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip` (memory views, watch
            flags, timing, access offsets).
        table: the list of block functions by hub address (filled in here).
        stub: what ``table`` holds for an address with no compiled block.
    """

    def __init__(self, chip, table: list, stub):
        self.chip = chip
        self.T = chip.timing
        self.acc = chip.access_at
        self.mem = chip.mem
        self.table = table
        self.boundaries: set = set(chip.interpret_only)   # addresses a block must start at (busy-loop heads)
        self.interpret_only = chip.interpret_only          # ... and ones no block may start at
        self.interpret_calls = chip.interpret_calls        # calls stay interpreted (runtime checks)
        self.checks = chip.checks if chip.checks is not None and chip.checks.wants("waitcnt-passed") else None
        self.compiled: dict = {}          # start -> end of every compiled block
        self.compiled_private: dict = {}  # ... and of every private variant
        self._timing_key = None
        self.env = {
            "L": chip.mem_longs, "W": chip.mem_words, "mem": chip.mem, "WATCH": chip.watch,
            "B": table, "STUB": stub, "RF": random_forward, "RR": random_reverse,
            "P": chip._pblocks, "PSTUB": chip._pstub, "CLAIM": CLAIM, "WANT_RO": WANT_RO,
            "AH": chip._ahead, "WANT": chip._want, "HOLE": _hole_in, "OPEN": chip._open,
            "CHECKS": chip.checks,
        }
        for f, fn in enumerate(BINARY):
            if fn is not None:
                self.env[f"B{f:02X}"] = fn
        for f, fn in enumerate(UNARY):
            if fn is not None:
                self.env[f"U{f:02X}"] = fn
        for f, table_f in enumerate(self.T._math):
            self.env[f"MT{f:02X}"] = tuple(table_f)
        self.count = 0

    # ------------------------------------------------------------------ public
    def compile(self, pc: int):
        """The block function for hub address ``pc``, or ``None`` if its first bytecode is not compiled."""
        return self._compile(pc, False)

    def compile_private(self, pc: int):
        """The private variant of the block at ``pc`` (ahead.py), or ``None``.

        It holds the bytecodes from ``pc`` on that touch only the cog's code,
        stack, local variables and read-only hub longs, checks at entry that
        those lie in the cog's window (returning ``ahead.CLAIM`` if not) or
        are read-only (``ahead.WANT_RO``), and leaves before a computed
        address that is neither; it runs whatever the other cogs do.
        """
        return self._compile(pc, True)

    def _compile(self, pc: int, private: bool):
        if pc in self.interpret_only:           # (runtime checks: the interpreter's checking handler runs it)
            return None
        cache = self.chip.code_cache
        if cache is None or _generator_key() == -1:
            made = self._generate(pc, private)
        else:
            # a block generated before (in this run or an earlier one) from the same inputs: the
            # bytes it read, the block starts it could meet, the compiler's settings
            known = cache.blocks_at(_generator_key(), (pc, private) + self._settings())
            for inputs, made in known:
                if self._inputs(pc, inputs[0]) == inputs:
                    break
            else:
                made = self._generate(pc, private)
                if made is not None:
                    if len(known) >= _KEEP_PER_START:       # (code that keeps changing there)
                        del known[0]
                    known.append((self._inputs(pc, made[-1]), made))
                    cache.added_block()
        if made is None:
            return None
        src, end, loops, foot, locs, ro, privatable, _last = made
        if not self._code_free(pc, end, private):
            return None
        return self._install(pc, end, private, src, loops, foot, locs, ro, privatable)

    def _settings(self) -> tuple:
        """What besides the bytes and the generator's own code decides the code generated: calls
        interpreted (runtime checks), the WAITCNT check, the timing table."""
        if self._timing_key is None:
            import zlib
            self._timing_key = zlib.crc32(repr(sorted(self.T.data.items())).encode())
        return (bool(self.interpret_calls), self.checks is not None, self._timing_key)

    def _inputs(self, pc: int, last: int) -> tuple:
        """The inputs of a block at ``pc`` whose generation read the bytes up to ``last``."""
        bounds = self.boundaries
        return (last, bytes(self.mem[pc:last + 1]), pc in bounds,
                tuple(a for a in range(pc + 1, last + 1) if a in bounds))

    def _generate(self, pc: int, private: bool):
        """Generate the block at ``pc``: ``(source, end, loops, foot, locals, read-only longs, privatable,
        last byte read)``, or None if its first bytecode is not compiled."""
        b = _Block(pc, private)
        last = pc
        while True:
            if b.pc >= 0xFFF0 or b.n >= MAX_OPS or (b.n and b.pc in self.boundaries):
                break
            b.op_pc, b.op_off = b.pc, b.off
            saved = b.snapshot()
            try:
                self._op(b)
            except _Stop:
                last = max(last, b.pc)      # (what it read before it stopped decided that too)
                b.restore(saved)
                break
            last = max(last, b.pc)          # (b.pc itself too: an access moment reads the next byte)
            b.n += 1
            if b.end:
                break
        if b.n == 0:
            return None
        if not b.end:
            b.exit_lines(str(b.pc), n=b.n)
            b.emit(f"return {b.t_start}")
        return (self._source(b), b.pc, b.loops, (b.lo, b.hi, b.dlo, b.dhi), tuple(sorted(b.locs)),
                tuple(sorted(b.ro, key=str)), not b.shared, last)

    def _code_free(self, start: int, end: int, private: bool) -> bool:
        """May code at ``[start, end)`` be compiled?  Not where a cog's window is (a private block not at all,
        an exact one not while that cog is ahead: the fetch must be seen by the guarded interpreter)."""
        own = self.chip.own
        k0, k1 = start >> 2, ((end - 1) >> 2) + 1
        if all(own[k] == 0 or own[k] > 8 for k in range(k0, k1)):
            return True
        if private:
            return False
        cogs = self.chip.cogs
        for k in range(k0, k1):
            o = own[k]
            if 1 <= o <= 8 and cogs[o - 1].cp is not None:
                return False
        return True

    def add_boundary(self, pc: int) -> None:
        """Make ``pc`` a block start: no block runs through it (the fast-forward stops there)."""
        if pc in self.boundaries:
            return
        self.boundaries.add(pc)
        for compiled, table, stub in ((self.compiled, self.table, self.env["STUB"]),
                                      (self.compiled_private, self.chip._pblocks, self.chip._pstub)):
            for start, (end, loops) in list(compiled.items()):
                if start < pc < end or (start == pc and loops):
                    table[start] = stub
                    del compiled[start]

    # ------------------------------------------------------------------ assembly
    def _source(self, b: _Block) -> str:
        """The Python source of the generated block ``b``."""
        start, end = b.start, b.pc
        table, stub = ("P", "PSTUB") if b.private else ("B", "STUB")
        head = ["def blk(c, tf, limit):",
                f"    if tf + {b.segments[0] if b.segments else b.reach} >= limit: return -1",
                f"    if mem[{start}:{end}] != K: {table}[{start}] = {stub}; return -1",
                "    sp = c.sp"]
        # the stack bytes the block touches must be in hub RAM and away from its own code
        lo, hi = b.lo, b.hi
        head.append(f"    if sp & 3 or sp < {max(-lo, end - lo)} or sp > {0x10000 - hi}:")
        head.append(f"        if sp & 3 or sp < {-lo} or sp > {min(0x10000 - hi, start - hi)}: return -1")
        head.append("    i = sp >> 2")
        for field in sorted(b.bases):
            head.append(f"    {_BASE_LOCALS[field]} = c.{field}")
        locs = b.dlo < b.dhi
        if locs:
            head.append("    if db & 3: return -1")
            if lo < hi:         # (lazy stack stores: no local variable may lie in the stack slots)
                head.append(f"    if db + {b.dhi} > sp + ({lo}) and sp + {hi} > db + ({b.dlo}): return -1")
        if b.private:
            # everything it touches lies in the cog's window, everything else it reads is read-only
            head += ["    wl = c.wlo", "    wh = c.whi"]
            inside = []
            if lo < hi:
                inside += [f"sp + ({lo}) < wl", f"sp + {hi} > wh"]
            if locs:
                inside += [f"db + ({b.dlo}) < wl", f"db + {b.dhi} > wh"]
            if inside:
                head.append(f"    if {' or '.join(inside)}: return CLAIM")
                s_rng = f"sp + ({lo}), sp + {hi}" if lo < hi else "0, 0"
                d_locs = f"db, {tuple(sorted(b.locs))}" if locs else "0, ()"
                head.append(f"    if c.holes and HOLE(c.holes, {s_rng}, {d_locs}): return -1")
            if b.ro:
                longs = " & ".join(f"WATCH[(({base} + {off}) & 0xFFFF) >> 2]" if base else f"WATCH[{off >> 2}]"
                                   for base, off in sorted(b.ro, key=str))
                head.append(f"    if not {longs} & {RO}: return WANT_RO")
            head.append("    if c.cp is None: OPEN(c)")      # from here on it may run past the scheduler's limit
        else:
            if b.loc_writes:    # a watched local (a parked loop reads it): the interpreter writes it
                longs = " | ".join(f"WATCH[(db + {off}) >> 2]" for off in sorted(b.loc_writes))
                head.append(f"    if {longs}: return -1")
            # while a cog is ahead (ahead.py) nothing here may touch its window: the stack and
            # locals must lie in this cog's own window, the hub variables read outside any window
            inside = []
            if lo < hi:
                inside += [f"sp + ({lo}) < c.wlo", f"sp + {hi} > c.whi"]
            if locs:
                inside += [f"db + ({b.dlo}) < c.wlo", f"db + {b.dhi} > c.whi"]
            if inside:
                head.append(f"    if AH and ({' or '.join(inside)}): return CLAIM")
                # ... and not on a hole of it (another cog reads or writes that long, maybe ahead or
                # read-only: the guarded interpreter checks each access there)
                s_rng = f"sp + ({lo}), sp + {hi}" if lo < hi else "0, 0"
                d_locs = f"db, {tuple(sorted(b.locs))}" if locs else "0, ()"
                head.append(f"    if AH and c.holes and HOLE(c.holes, {s_rng}, {d_locs}): return -1")
            if b.var_reads:
                longs = " | ".join(f"WATCH[((vb + {off}) & 0xFFFF) >> 2]" for off in sorted(b.var_reads))
                head.append(f"    if AH and ({longs}) & {AHEAD}: return -1")
        if b.waits:
            head.append("    ph = tf & 15")
        body = b.lines
        if b.loops:
            head += ["    nb = 0", "    while True:"]
            body = ["    " + line for line in body]
        src = "\n".join(head + body) + "\n"
        src = src.replace(_NB, "nb + " if b.loops else "")
        src = src.replace(_FIRST_EXIT, "if not nb: return -1" if b.loops else "return -1")
        for k, reach in enumerate(b.segments):
            src = src.replace(f"@REACH{k}@", str(reach))
        return src.replace(f"@REACH{len(b.segments)}@", str(b.reach))

    def _install(self, start: int, end: int, private: bool, src: str, loops: bool, foot, locs, ro, privatable):
        """Compile a generated block's source and make it the block at ``start``."""
        ns: dict = {}
        env = dict(self.env)
        env["K"] = bytes(self.mem[start:end])
        name = f"<spin {'private ' if private else ''}block ${start:04X}>"
        cache = self.chip.code_cache
        exec(cache.compile(src, name) if cache is not None else compile(src, name, "exec"), env, ns)
        fn = ns["blk"]
        fn.source = src
        fn.foot = foot
        fn.locs = locs
        fn.ro = ro
        fn.privatable = privatable
        (self.compiled_private if private else self.compiled)[start] = (end, loops)
        watch = self.chip.watch
        own = self.chip.own
        for k in range(start >> 2, ((end - 1) >> 2) + 1):
            if 1 <= own[k] <= 8:
                self.chip._share(k)         # code in a window (never with the cog ahead: see _code_free)
            watch[k] |= CODE
        self.count += 1
        return fn

    # ------------------------------------------------------------------ timing
    def _account(self, b: _Block, op: int, rest, worst: int = None) -> None:
        """Close bytecode ``op`` (started at the current fetch) whose path takes ``rest``.

        ``rest`` is an int or an expression (``worst``: its largest value).
        """
        b.reach = max(b.reach, b.worst + self.chip.access_offset(b.op_pc))
        if op & 3 == 2 and 0x40 <= op < 0xE0:          # an update: its write-back is its last instruction
            b.reach = max(b.reach, b.worst + (rest if isinstance(rest, int) else worst) - 4)
        if isinstance(rest, int):
            b.t_start = b.now(rest)
            b.d += _ceil16(rest + 12)
            b.worst += _ceil16(rest + 12)
        else:
            x = b.name("x")
            tf = b.name("T")
            b.emit(f"{x} = {rest} + 12")
            b.emit(f"{tf} = {b.now()} + {x} + (-{x} & 15)")
            b.t_start = f"{tf} - 12 - (-{x} & 15)"
            b.tf, b.d = tf, 0
            b.worst += _ceil16(worst + 12)

    def _terminal_rest(self, b: _Block, op: int) -> None:
        b.reach = max(b.reach, b.worst + self.chip.access_offset(b.op_pc))

    # ------------------------------------------------------------------ operands
    def _byte(self, b: _Block) -> int:
        v = self.mem[b.pc]
        b.pc += 1
        return v

    def _jump_operand(self, b: _Block):
        x = self._byte(b)
        if x & 0x80:
            v = ((x & 0x7F) << 8) | self._byte(b)
            return (v - 0x8000 if v & 0x4000 else v), True
        return (x - 0x80 if x & 0x40 else x), False

    def _jump_target(self, b: _Block, wrap: bool = False) -> tuple:
        off, long_ = self._jump_operand(b)
        target = b.pc + off
        if wrap:
            target &= 0xFFFF
        if not 0 <= target < 0x10000:
            raise _Stop
        return target, long_

    # ------------------------------------------------------------------ bytecodes
    def _op(self, b: _Block) -> None:
        b.op_pc = b.pc                              # (its access moment: chip.access_offset)
        op = self._byte(b)
        if op >= 0xE0:
            return self._math(b, op)
        if op >= 0x80:
            return self._mem(b, op)
        if op >= 0x40:
            return self._var(b, op)
        T = self.T
        if 0x34 <= op <= 0x36:
            b.push(("4294967295", "0", "1")[op - 0x34])
            return self._account(b, op, T.push_const)
        if op == 0x37:
            m = self._byte(b)
            v = (2 << (m & 0x1F)) & MASK32
            if m & 0x20:
                v = (v - 1) & MASK32
            if m & 0x40:
                v ^= MASK32
            b.push(str(v))
            return self._account(b, op, T.push_mask)
        if 0x38 <= op <= 0x3B:
            n = op - 0x37
            v = int.from_bytes(self.mem[b.pc:b.pc + n], "big")
            b.pc += n
            b.push(str(v))
            return self._account(b, op, T.push_imm[n])
        if op <= 0x03:
            return self._frame(b, op)
        if op in (0x05, 0x06):
            return self._call(b, op)
        if op in (0x32, 0x33):
            return self._return(b, op)
        if op in (0x04, 0x08, 0x09, 0x0A, 0x0B, 0x0D, 0x0E):
            return self._jump(b, op)
        if op == 0x23:
            return self._waitcnt(b, op)
        raise _Stop

    # -- control flow (the block ends, or goes round again)
    def _taken(self, b: _Block, target: int, rest: int, off: int, indent: int) -> None:
        """The jump to ``target`` (stack at ``off``) whose bytecode takes ``rest``: exit, or loop to the start."""
        if target == b.start and off == 0 and b.start not in self.boundaries:
            b.loops = True
            b.emit(f"t0 = {b.now(rest)}", indent)           # the next pass's first bytecode starts here
            b.emit(f"nb += {b.n + 1}", indent)
            b.emit(f"tf = {b.tf} + {b.d + _ceil16(rest + 12)}", indent)
            b.emit("if tf + @REACH0@ < limit: continue", indent)
            b.emit(f"c.pc = {target}", indent)
            b.emit(f"c.sp = {b.sp_expr(off)}", indent)
            b.emit("c.bytecodes += nb", indent)
            b.emit("return t0", indent)
            return
        keep = b.off
        b.off = off
        b.exit_lines(str(target), indent)
        b.off = keep
        b.emit(f"return {b.now(rest)}", indent)

    def _branch(self, b: _Block, op: int, cond: str, yes, no, yes_off: int = None, no_off: int = None) -> None:
        """End the block: go to ``yes = (pc, rest)`` if ``cond`` holds, else to ``no``."""
        self._terminal_rest(b, op)
        b.flush()
        off = b.off
        b.emit(f"if {cond}:")
        self._taken(b, yes[0], yes[1], off if yes_off is None else yes_off, 1)
        self._taken(b, no[0], no[1], off if no_off is None else no_off, 0)
        b.end = True

    def _jump(self, b: _Block, op: int) -> None:
        T = self.T
        target, long_ = self._jump_target(b)
        nxt = b.pc
        if op == 0x04:                                  # JMP
            self._terminal_rest(b, op)
            b.flush()
            self._taken(b, target, T.jmp[long_], b.off, 0)
            b.end = True
            return
        if op == 0x08:                                  # TJZ: pop only when jumping
            v = b.peek()
            return self._branch(b, op, f"{v} == 0", (target, T.tjz[(long_, True)]), (nxt, T.tjz[(long_, False)]),
                                yes_off=b.off - 4, no_off=b.off)
        if op == 0x09:                                  # DJNZ
            v = b.let(f"({b.peek()} - 1) & 0xFFFFFFFF")
            b.touch(b.off - 4)
            self._terminal_rest(b, op)
            b.flush()
            b.emit(f"if {v}:")
            b.emit(f"{b.slot(b.off - 4)} = {v}", 1)     # written back only when it loops (0 is not)
            self._taken(b, target, T.djnz[(long_, True)], b.off, 1)
            self._taken(b, nxt, T.djnz[(long_, False)], b.off - 4, 0)
            b.end = True
            return
        if op in (0x0A, 0x0B):                          # JZ / JNZ
            v = b.pop()
            table = T.jz if op == 0x0A else T.jnz
            cond = f"{v} == 0" if op == 0x0A else f"{v} != 0"
            return self._branch(b, op, cond, (target, table[(long_, True)]), (nxt, table[(long_, False)]))
        if op == 0x0D:                                  # CASE value
            v = b.pop()
            cur = b.peek()
            return self._branch(b, op, f"{v} == {cur}", (target, T.case_value[(long_, True)]),
                                (nxt, T.case_value[(long_, False)]))
        # CASE range (0x0E)
        hi = b.pop()
        lo = b.pop()
        x = b.peek()
        s = lambda e: f"(({e} ^ 0x80000000) - 0x80000000)"
        lo_, hi_ = b.name(), b.name()
        b.emit(f"{lo_} = {s(lo)}")
        b.emit(f"{hi_} = {s(hi)}")
        b.emit(f"if {lo_} > {hi_}: {lo_}, {hi_} = {hi_}, {lo_}")
        return self._branch(b, op, f"{lo_} <= {s(x)} <= {hi_}", (target, T.case_range[(long_, True)]),
                            (nxt, T.case_range[(long_, False)]))

    def _waitcnt(self, b: _Block, op: int) -> None:
        """WAITCNT: the next bytecode starts when the wait ends; the block goes on if the rest still fits."""
        T = self.T
        issue = T.waitcnt_issue + T.waitcnt_min
        if b.private and self.checks is not None:   # a count already passed: the interpreter runs it (and
            b.deopt(f"(({b.peek()}) - ({b.now(issue)})) & 0x80000000")    # warns) in the exact order
        target = b.pop()
        self._terminal_rest(b, op)
        tn = b.name("t")
        if self.checks is None or b.private:
            b.emit(f"{tn} = {b.now(issue + T.waitcnt_after)} + (({target} - ({b.now(issue)})) & 0xFFFFFFFF)")
        else:                                           # the runtime check for a count already passed
            w = b.name("w")
            b.emit(f"{w} = ({target} - ({b.now(issue)})) & 0xFFFFFFFF")
            b.emit(f"if {w} & 0x80000000:")
            b.emit(f"c.pc = {b.pc}", 1)                 # (the check names the WAITCNT before it)
            b.emit(f"CHECKS.waitcnt(c, {target}, {w}, {b.now()})", 1)
            b.emit(f"{tn} = {b.now(issue + T.waitcnt_after)} + {w}")
        b.t_start = tn
        # the segment after the wait: its fetches are on the hub window from the end of the wait
        b.waits = True
        k = len(b.segments)
        b.segments.append(b.reach)
        nf = b.name("T")
        b.emit(f"{nf} = {tn} + 12")
        b.emit(f"{nf} += (ph - {nf}) & 15")
        b.flush()
        b.emit(f"if {nf} + @REACH{k + 1}@ >= limit:")
        b.emit(f"c.pc = {b.pc}", 1)
        b.emit(f"c.sp = {b.sp_expr()}", 1)
        b.emit(f"c.bytecodes += {_NB}{b.n + 1}", 1)
        b.emit(f"return {tn}", 1)
        b.tf, b.d, b.worst, b.reach = nf, 0, 0, 0

    def _frame(self, b: _Block, op: int) -> None:
        o = b.off
        b.touch(o, 12)
        b.flush()
        sp = b.sp_expr()
        b.emit(f"s = {sp}")
        b.emit(f"W[s >> 1] = (c.pbase | {op}) & 0xFFFF")
        b.emit("W[(s + 2) >> 1] = c.vbase")
        b.emit("W[(s + 4) >> 1] = c.dbase")
        b.emit("W[(s + 6) >> 1] = c.dcall & 0xFFFF")
        b.emit("c.dcall = s + 6")
        b.vals.pop(o, None)
        b.vals.pop(o + 4, None)
        b.write(o + 8, "0")
        b.off = o + 12
        self._account(b, op, self.T.frame)

    def _call(self, b: _Block, op: int) -> None:
        if b.private:
            raise _Stop                         # it reads the object's method table
        b.shared = True
        T = self.T
        if self.interpret_calls:
            raise _Stop
        if op == 0x06:
            obj = self._byte(b)
        m = self._byte(b)
        ret = b.pc
        if ret > 0xFFFF:
            raise _Stop
        self._terminal_rest(b, op)
        b.flush()
        b.emit("pb = c.pbase")
        b.emit("pbh = c.pbase_hi")
        if op == 0x06:
            b.emit(f"e = L[((pb + {4 * obj}) & 0xFFFF) >> 2]")
            b.emit("full = ((pbh << 16 | pb) + e) & 0xFFFFFFFF")
            b.emit("pb = full & 0xFFFF")
            b.emit("pbh = full >> 16")
            b.emit("vbn = (c.vbase + (e >> 16)) & 0xFFFF")
        b.emit(f"ent = L[((pb + {4 * m}) & 0xFFFF) >> 2]")
        b.emit("f6 = c.dcall")
        b.emit(f"nsp = {b.sp_expr()} + (ent >> 16)")
        tables = f"WATCH[((pb + {4 * m}) & 0xFFFF) >> 2]"
        if op == 0x06:
            tables += f" | WATCH[((c.pbase + {4 * obj}) & 0xFFFF) >> 2]"
        b.deopt(f"nsp > c.stack_end or not 0 <= f6 < 0x10000 or AH and ({tables} | WATCH[f6 >> 2]) & {AHEAD}")
        if op == 0x06:
            b.emit("c.pbase = pb")
            b.emit("c.pbase_hi = pbh")
            b.emit("c.vbase = vbn")
        b.emit("c.dcall = W[f6 >> 1]")
        b.emit(f"W[f6 >> 1] = {ret}")
        b.emit("c.dbase = (f6 + 2) & 0xFFFF")
        b.emit("full = (pbh << 16 | pb) + ent")
        b.emit("c.pc = full & 0xFFFF")
        b.emit("c.pc_hi = (full >> 16) & 0xFFFF")
        b.emit("c.sp = nsp")
        b.emit(f"c.bytecodes += {_NB}{b.n + 1}")
        b.emit(f"return {b.now(T.call_obj if op == 0x06 else T.call)}")
        b.end = True

    def _return(self, b: _Block, op: int) -> None:
        T = self.T
        b.loc(-8, 12)                           # the frame header and the result long
        self._terminal_rest(b, op)
        b.emit("d = db")
        b.deopt("not 8 <= d < 0x10000")
        value = b.pop() if op == 0x33 else b.let("L[d >> 2]")
        b.emit("c.pc = W[(d - 2) >> 1]")
        b.emit("c.pc_hi = 0")
        b.emit("c.dbase = W[(d - 4) >> 1]")
        b.emit("c.vbase = W[(d - 6) >> 1]")
        b.emit("flags = W[(d - 8) >> 1]")
        b.emit("c.pbase = flags & 0xFFFC")
        b.emit("c.pbase_hi = 0")
        b.emit(f"c.bytecodes += {_NB}{b.n + 1}")
        b.emit("if flags & 1:")
        b.emit("c.sp = d - 8", 1)
        b.emit(f"return {b.now(T.returns(op, 1, False))}", 1)
        b.emit(f"L[(d - 8) >> 2] = {value}")
        b.emit("c.sp = d - 4")
        b.emit(f"return {b.now(T.returns(op, 1, True))}")
        b.end = True
