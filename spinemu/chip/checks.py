"""Where the bytecode engine looks for the classic mistakes (spinemu.runtime_warnings).

Every check sits where the chip already leaves its fast path, so a program
that makes none of these mistakes runs at the same speed with the checks on:

* ``waitcnt-passed``: in WAITCNT's handler and the compiled block's WAITCNT
  (one bit test of the wait it computes anyway).
* ``stack-overflow``: the call's stack check (``Spin._enter``, the block's
  call guard) compares the new stack top with ``Cog.stack_end``, which is
  the end of hub RAM unless ``cognew`` gave the cog an array this program
  names (then the end of that array).
* ``no-free-cog``: COGINIT, when it finds no stopped cog.
* ``pin-conflict``: after a cog changes DIRA/OUTA (already the slow path
  that records pin changes; ``Chip.pin_hooks``).
* ``write-outside-hub``: the hub-write paths' existing ``addr < $8000``
  test gets an ``else``.
* ``write-into-code``: the longs holding object tables and method code get
  a ``Chip.watch`` bit (:data:`PROGRAM`); a write to a watched long already
  leaves the fast path (``Chip.watch_hit``; a PASM cog's hub write,
  ``Chip.pasm_write_hit``), which now also looks at it.
* ``uninitialized``: a flow analysis of each method's bytecode (below) finds
  the few reads of a local that some path reaches before any write; only
  those bytecodes, the writes of those locals and the calls are then run
  through a checking handler (and not compiled into blocks), so that the
  warning is exact: it fires only when a read really happens first.
  A program with no such read pays nothing.

The texts are in :mod:`spinemu.runtime_warnings`, shared with other engines.
"""
from __future__ import annotations

from ..bytecode import TABLE, decode_assign, decode_signed, decode_unsigned, instruction_length
from ..image import ObjectTable
from .. import runtime_warnings as rw
from .blocks import PROGRAM
from .cog import STOPPED

__all__ = ["RuntimeChecks", "program_code_ranges", "uninitialized_reads", "local_access", "write_size"]

_MASK = 0xFFFFFFFF


def program_code_ranges(mem, pbase: int = 0x0010) -> list:
    """``(start, end)`` hub ranges of every object's table and of its method code and strings.

    Read from the image itself (object tables, Propeller Manual "Memory
    Organization"): an object's DAT lies between its table and its first
    method, and is not included.
    """
    out, seen, todo = [], set(), [pbase]
    while todo:
        base = todo.pop()
        if base in seen or not 0x10 <= base < 0x8000:
            continue
        seen.add(base)
        try:
            table = ObjectTable.parse(mem[:0x8000], base)
        except Exception:  # an odd image: check what can be read
            continue
        table_end = base + 4 * (1 + len(table.methods) + len(table.children))
        out.append((base, table_end))
        if table.methods:
            code = base + min(off for off, _ in table.methods)
            if table_end <= code < base + table.size:
                out.append((code, base + table.size))
        for off, _var in table.children:
            todo.append((base + off) & 0xFFFF)
    return sorted(out)


# ----------------------------------------------------------------------------- flow analysis
_TERMINAL = frozenset((0x30, 0x31, 0x32, 0x33, 0x3C))
_BRANCHES = frozenset((0x08, 0x09, 0x0A, 0x0B, 0x0D, 0x0E))


def _assign_pos(code, pos: int):
    """Offset of the assignment-operator byte of a USING instruction at ``pos`` (``None`` if not one)."""
    op = code[pos]
    entry = TABLE[op]
    main = entry.fmt.split("+")[0]
    if main == "reg":
        return pos + 2 if (code[pos + 1] >> 5) & 3 == 2 else None
    if not entry.fmt.endswith("+using"):
        return None
    if main == "offset":
        return decode_unsigned(code, pos + 1)[1]
    return pos + 1


def _successors(code, pos: int, ends) -> list:
    """Where control can go after the instruction at ``pos`` (``ends``: possible case/lookup ends)."""
    op = code[pos]
    nxt = pos + instruction_length(code, pos)
    if op in _TERMINAL:
        return []
    if op == 0x04:
        off, p = decode_signed(code, pos + 1)
        return [p + off]
    if op in _BRANCHES:
        off, p = decode_signed(code, pos + 1)
        return [nxt, p + off]
    if op == 0x0C:
        return list(ends)
    if 0x10 <= op <= 0x13:
        return [nxt, *ends]
    a = _assign_pos(code, pos)
    if a is not None:
        aop = decode_assign(code[a])
        if aop is not None and aop.has_jump:
            off, q = decode_signed(code, a + 1)
            return [nxt, q + off]
    return [nxt]


def local_access(code, pos: int):
    """How the instruction at ``pos`` touches its frame: ``(kind, offset, exact)`` or ``None``.

    ``kind``: ``"r"`` read, ``"w"`` write, ``"rw"`` read then write.  An
    indexed or address access (``exact`` False) may reach any long from
    ``offset`` up: it counts as a write of all of them, never as a read.
    """
    op = code[pos]
    if 0x60 <= op <= 0x7F:
        off, access = op & 0x1C, op & 3
    elif 0x80 <= op <= 0xDF and (op >> 2) & 3 == 3:
        off = decode_unsigned(code, pos + 1)[0]
        access = op & 3
        if op & 0x10:
            return ("w", off, False)
        off &= ~3                               # a byte or word of one long: that long
    else:
        return None
    if access == 3:
        return ("w", off, False)
    if access == 0:
        return ("r", off, True)
    if access == 1:
        return ("w", off, True)
    a = decode_assign(code[_assign_pos(code, pos)])
    b = a.code & 0x7F if a is not None else 0
    if b == 0 or (b in (0x18, 0x1C) and not a.push):
        return ("w", off, True)                 # := or a dropped x~ / x~~: the old value is not used
    return ("rw", off, True)


def uninitialized_reads(code, method_start: int, method_end: int, obj_base: int, tracked) -> dict:
    """Reads of locals that some path reaches before any write to them.

    A forward "definitely assigned" analysis over the method's bytecode (paths
    joined by intersection).  ``code`` is hub RAM (indexed by hub address);
    ``tracked`` the frame offsets of the scalar locals.  The end of a
    ``case`` or ``lookup`` is an object address pushed as a constant: every
    constant pushed in the method that lands inside it counts as a possible
    end (extra paths can only add reads, never hide one).

    Returns:
        ``{hub address of the read: frame offset}``.

    >>> code = bytearray(0x40)
    >>> code[0x20:0x26] = bytes([0x64, 0x65, 0x35, 0x65, 0x64, 0x32])   # push x; x := ; x := 0; push x
    >>> uninitialized_reads(code, 0x20, 0x26, 0x10, {4})
    {32: 4}
    """
    tracked = frozenset(tracked)
    if not tracked:
        return {}
    starts: set = set()
    consts: set = set()

    def reach(todo, ends):
        while todo:
            p = todo.pop()
            if p in starts or not method_start <= p < method_end:
                continue
            starts.add(p)
            op = code[p]
            if op == 0x38:
                consts.add(obj_base + code[p + 1])
            elif op == 0x39:
                consts.add(obj_base + ((code[p + 1] << 8) | code[p + 2]))
            todo.extend(_successors(code, p, ends))

    reach([method_start], ())
    ends = frozenset(a for a in consts if method_start <= a < method_end)
    reach(list(ends), ends)
    succs = {p: [s for s in _successors(code, p, ends) if s in starts] for p in starts}
    state = dict.fromkeys(starts, tracked)
    state[method_start] = frozenset()
    work = [method_start]
    while work:
        p = work.pop()
        out = state[p]
        acc = local_access(code, p)
        if acc is not None:
            kind, off, exact = acc
            if not exact:
                out = out | {o for o in tracked if o >= off}
            elif off in tracked:
                out = out | {off}
        for s in succs[p]:
            new = state[s] & out
            if new != state[s]:
                state[s] = new
                work.append(s)
    reads = {}
    for p in starts:
        acc = local_access(code, p)
        if acc is not None and acc[2] and acc[0] != "w" and acc[1] in tracked and acc[1] not in state[p]:
            reads[p] = acc[1]
    return reads


# ----------------------------------------------------------------------------- the checks of one chip
class RuntimeChecks:
    """The runtime checks of one :class:`~spinemu.chip.chip.Chip`.

    Args:
        chip: the chip (booted or not).
        log: a :class:`spinemu.runtime_warnings.WarningLog` that gets the warnings.
        debug_info: the program's :class:`spinemu.debuginfo.DebugInfo`, if known:
            names in messages, the stack arrays and the uninitialized-local
            analysis need it; the other checks work on any image.
    """

    def __init__(self, chip, log, debug_info=None):
        self.chip = chip
        self.log = log
        self.info = debug_info
        self.clock_hz = chip.clock_hz
        #: hub address -> ("r" | "w" | "rw", frame offset, MethodDebug) of the uninitialized-local checks
        self.sites: dict = {}
        #: method start addresses whose frames are followed
        self.entries: set = set()
        self._assigned: dict = {}          # (cog id, dbase) -> frame offsets written so far
        self._code_ranges = []

    def wants(self, kind: str) -> bool:
        return self.log.wants(kind)

    def frames_state(self) -> tuple:
        """What the uninitialized-local check remembers between bytecodes (per frame, the locals written
        so far), comparable: a period the steady-state skip repeats must leave it as it found it."""
        return tuple(sorted((k, tuple(sorted(v))) for k, v in self._assigned.items()))

    def _where(self, c) -> int:
        """The bytecode a Spin cog is executing; -1 for a cog another engine runs (no bytecode address)."""
        return (c.pc - 1) & 0xFFFF if c.engine == "spin" else -1

    def _warn(self, kind: str, message: str, c, addr: int, t: int) -> None:
        self.log.warn(kind, message, c.id, addr, t)

    # ------------------------------------------------------------------ set-up
    def install(self) -> None:
        """Mark the code, register the listeners and wrap the handlers the checks need."""
        chip = self.chip
        if self.wants("write-into-code"):
            self._code_ranges = program_code_ranges(chip.mem, chip.header.pbase)
            watch = chip.watch
            for start, end in self._code_ranges:
                # a corrupt image's method table can point past the hub: only hub longs are marked
                for k in range(min(start, len(watch) << 2) >> 2, min(((end - 1) >> 2) + 1, len(watch))):
                    watch[k] |= PROGRAM
            chip.write_hooks.append(self.on_watched_write)
        if self.wants("pin-conflict"):
            chip.pin_hooks.append(self.on_pins)
        if self.wants("uninitialized") and self.info is not None:
            self._find_uninitialized()

    def _find_uninitialized(self) -> None:
        mem = self.chip.mem
        for m in self.info.methods:
            tracked = {s.offset for s in m.locals if s.count == 1}
            obj = self.info.object_at(m.start)
            if not tracked or obj is None:
                continue
            reads = uninitialized_reads(mem, m.start, m.end, obj.base, tracked)
            if not reads:
                continue
            watched = set(reads.values())
            self.entries.add(m.start)
            p = m.start
            while p < m.end:
                n = instruction_length(mem, p)
                acc = local_access(mem, p)
                if acc is not None:
                    kind, off, exact = acc
                    if p in reads:
                        self.sites[p] = (kind, off, m)
                    elif not exact and any(o >= off for o in watched):
                        self.sites[p] = ("w*", frozenset(o for o in watched if o >= off), m)
                    elif exact and off in watched and kind != "r":
                        self.sites[p] = ("w", off, m)
                p += n
        if not self.sites:
            return
        chip = self.chip
        ops = {mem[a] for a in self.sites} | {0x05, 0x06, 0x07}
        for op in ops:
            chip.wrap_handler(op, self._wrap(op, chip.handlers[op]), lambda inner, op=op: self._wrap(op, inner))
        chip.interpret_only |= set(self.sites)
        chip.interpret_calls = True

    def _wrap(self, op: int, inner):
        sites, entries, assigned = self.sites, self.entries, self._assigned
        L = self.chip.mem_longs
        if op in (0x05, 0x06, 0x07):
            def call(c, op, t):
                rest = inner(c, op, t)
                if c.pc in entries:
                    assigned[(c.id, c.dbase)] = set()
                return rest
            return call
        warn = self._uninitialized

        def checked(c, op, t):
            site = sites.get((c.pc - 1) & 0xFFFF)
            if site is not None:
                kind, off, m = site
                seen = assigned.get((c.id, c.dbase))
                if seen is not None:
                    if kind == "w*":
                        seen.update(off)
                    else:
                        if kind != "w" and off not in seen:
                            warn(c, off, m, L[((c.dbase + off) & 0xFFFF) >> 2], t)
                        seen.add(off)
            return inner(c, op, t)
        return checked

    def _uninitialized(self, c, off: int, m, value: int, t: int) -> None:
        slot = m.slot_at(off)
        name = slot.name if slot is not None else f"+{off}"
        v = value - (1 << 32) if value & 0x80000000 else value
        self._warn("uninitialized", rw.uninitialized_local(name, m.name, v), c, self._where(c), t)

    # ------------------------------------------------------------------ cogs
    def cog_started(self, c) -> None:
        """A Spin cog starts: find the stack array cognew gave it; follow its frame if it needs it."""
        if c.pc in self.entries:
            self._assigned[(c.id, c.dbase)] = set()
        c.stack_end = 0x8000
        c.stack_info = None
        if self.info is None or not self.wants("stack-overflow"):
            return
        stack = (c.dbase - 8) & 0xFFFF
        found = self.info.variable_at(stack)
        if found is None:
            return
        inst, var = found
        method = self.info.method_at(c.pc)
        c.stack_end = var.end
        c.stack_info = (var, inst, method.name if method else f"the method at ${c.pc:04X}")

    def stack_past_array(self, c, sp: int, site: int, callee_pc: int) -> None:
        """A call at ``site`` in cog ``c`` needs the stack up to ``sp``, past its cognew array."""
        var, inst, method = c.stack_info
        c.stack_end = 0x8000                # once per cog start
        callee = self.info.method_at(callee_pc)
        where = f"{var.section} of {_base(inst.obj.path)}"
        text = rw.stack_overflow(c.id, var.describe(), where, var.addr, var.size * var.count, method,
                                 callee.name if callee else f"the method at ${callee_pc:04X}", sp,
                                 sp - var.end)
        self._warn("stack-overflow", text, c, site, c.t)

    def no_free_cog(self, c, code: int, par: int, t: int) -> None:
        if (code & 0xFFFC) == 0xF004:
            start = self.chip.mem_words[((par & 0xFFFC) + 8 & 0xFFFF) >> 1]   # the new cog's pcurr
            m = self.info.method_at(start) if self.info is not None else None
            what = f"{m.name} (a Spin method)" if m is not None else f"the Spin method at ${start:04X}"
        else:
            what = f"the PASM code at ${code & 0xFFFC:04X}"
        self._warn("no-free-cog", rw.no_free_cog(what), c, self._where(c), t)

    # ------------------------------------------------------------------ time
    def waitcnt(self, c, target: int, wait: int, t: int) -> None:
        """WAITCNT in cog ``c`` for ``target`` waits ``wait`` cycles past the shortest wait (>= 2**31: passed)."""
        T = self.chip.timing
        late = (-wait) & _MASK
        stall = wait + T.waitcnt_min
        self._warn("waitcnt-passed", rw.waitcnt_passed(target, late, stall, self.clock_hz),
                   c, self._where(c), t)

    # ------------------------------------------------------------------ pins
    def on_pins(self, c, t: int) -> None:
        d = c.dira
        if not d:
            return
        for k in self.chip.cogs:
            if k is c or k.state == STOPPED:
                continue
            clash = k.dira & d & (k.outa ^ c.outa)
            if clash:
                pins = [p for p in range(32) if clash >> p & 1]
                low, high = (c.id, k.id) if not c.outa >> pins[0] & 1 else (k.id, c.id)
                self._warn("pin-conflict", rw.pin_conflict(pins, low, high), c, self._where(c), t)

    # ------------------------------------------------------------------ hub writes
    def write_outside(self, c, addr: int, size: int, t: int) -> None:
        self._warn("write-outside-hub", rw.write_outside_hub(size, addr), c, self._where(c), t)

    def on_watched_write(self, c, addr: int, size: int, t: int) -> None:
        """A write of ``size`` bytes to a watched long (a bytecode's or a PASM cog's): is it into the program's code?"""
        if not self.chip.watch[addr >> 2] & PROGRAM:
            return
        a = addr & ~(size - 1)
        for start, end in self._code_ranges:
            if a < end and a + size > start:
                where = self._where(c)
                if c.engine.__class__ is not str and c.ram is not None and c.pc < 496:
                    where = (c.code_addr + 4 * c.pc) & 0xFFFF      # a PASM cog: its instruction's DAT line
                self._warn("write-into-code", rw.write_into_code(size, a, self._describe_code(max(a, start))),
                           c, where, t)
                return

    def _describe_code(self, addr: int) -> str:
        if self.info is not None:
            m = self.info.method_at(addr)
            if m is not None:
                return f"method {m.name} of {_base(m.path)}"
            o = self.info.object_at(addr)
            if o is not None:
                return f"the object table of {_base(o.path)}"
        return f"code at ${addr:04X}"


def write_size(op: int) -> int:
    """Bytes a hub write by bytecode ``op`` writes at once (1, 2 or 4)."""
    if 0x80 <= op <= 0xDF:
        return (1, 2, 4)[(op >> 5) & 3]
    if op in (0x18, 0x1C):
        return 1
    if op in (0x19, 0x1D):
        return 2
    return 4


def _base(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1]
