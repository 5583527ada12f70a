"""The Python engine: translated Spin objects running on spinemu's chip model.

* :class:`PythonChip` is a :class:`spinemu.chip.Chip` whose Spin cogs run
  translated Python instead of bytecode.  The chip boots and starts cogs
  itself (``start_spin_cog``); the scheduler hands such a cog to
  :meth:`Engine.run` (``PythonChip._run_spin``) and asks it when it next
  touches shared state (:meth:`Engine.key`, the engine hook in
  ``spinemu.chip.scheduler``).  The engine switches into the cog's greenlet,
  which runs the translated method as plain synchronous Python until its
  next shared access would pass another cog's, or it waits.  So cogs meet at
  the hub in the same order as bytecode cogs do.
* Time: the generated module carries a table ``SPIN_CYCLES`` (Python line ->
  cycles).  :func:`spinemu.translate.weave.prepare` weaves those charges into
  the class's methods when the class is first run, so the readable source
  stays free of bookkeeping and each statement still costs exactly what its
  bytecode costs.
* :func:`instantiate` builds the object tree at the hub addresses the
  image's object tables give.

Hot path: the charges :mod:`spinemu.translate.inline` writes out in each woven
method (the arithmetic of :func:`tick` and :func:`tick_at`, which still serve the
charges inside conditions); :func:`pause_tick`/:func:`pause_tick_at` are their hand-overs.
"""
from __future__ import annotations

import greenlet

from ..chip.chip import Chip
from ..chip.cog import PIN_WAIT, STOPPED
from ..chip.control import Reschedule
from ..chip.rom import INTERPRETER_ENTRY
from ..chip.timing import MATH_REF, access_offsets, load_timing
from . import spin
from .costs import drop_result_delta
from .spin import RT, Abort

__all__ = ["PythonChip", "Engine", "instantiate", "run_class", "tick", "tick_at", "tick_read", "add",
           "pause_tick", "pause_tick_at", "defer_store"]

_NEVER = 1 << 62
_ACCESS = access_offsets()
_SPINSIM_START = -4


def tick(k: int) -> None:
    """Charge the current cog a run of bytecodes: fetch alignment, then ``k`` cycles. (Hot path.)

    The run touches no shared state, so it may start as soon as its first
    fetch is before every other cog's next hub access (as in the bytecode
    engine, which orders cogs by those moments).
    """
    c = RT.cog
    t = c.t + 12
    t += (c.hub_phase - t) & 15
    if t >= RT.limit:
        pause_tick(t)
    c.t = t + k


def tick_at(k: int, access: int, last: int = -1) -> None:
    """:func:`tick` for a run whose first shared access (hub variable, register, lock) comes ``access`` cycles after its first fetch.

    The run must not pass another cog's earlier access, so the cog hands over
    to the scheduler at that moment, not at the run's start.  ``last``: its
    last shared access; a run that would end it at or after the end of the
    whole run is not started (the bytecode engine stops before that write too).
    """
    c = RT.cog
    t = c.t + 12
    t += (c.hub_phase - t) & 15
    if t + access >= RT.limit or t + last >= RT.final:
        pause_tick_at(t, access)
    c.t = t + k


def pause_tick(t: int) -> None:
    """:func:`tick`'s hand-over to the scheduler (also for the charges spinemu.translate.inline writes out)."""
    RT.keys[RT.cog.id] = t
    RT.pause()


def pause_tick_at(t: int, access: int) -> None:
    """:func:`tick_at`'s hand-over to the scheduler: at its shared access, or at the run's end."""
    RT.keys[RT.cog.id] = t + access if t + access >= RT.limit else RT.final
    RT.pause()


def defer_store(size: int, addr: int, value: int, key: int) -> None:
    """A store (``size``: 0 byte, 1 word, 2 long) whose moment ``key`` comes after another cog's next
    access: the chip makes it then, in the cogs' order (``Scheduler.defer_write``), as the bytecode engine
    does an update's write-back; the cog goes on to its next shared access, where it hands over."""
    c = RT.cog
    c.engine.chip.defer_write(c, size, addr, value, key, key, preempt=False)


def tick_read(k, access, rest: int) -> None:
    """Charge ``k`` (``None``: nothing) as :func:`tick_at`/:func:`tick`, and leave ``rest`` for the register read that follows."""
    if k is not None:
        if access is not None:
            tick_at(k, access)
        else:
            tick(k)
    RT.pending = rest


def then(k, value):
    """Charge ``k`` (as :func:`tick`, ``None``: nothing) once ``value`` is computed; returns it.

    The weaver writes a case value that calls a method as ``then(k, x == self.f())``.
    """
    if k is not None:
        tick(k)
    return value


def pay_call(k, helper, *args):
    """Charge ``k`` (as :func:`tick`), then call ``helper`` (one that pays value-dependent cycles, such as
    ``spin.div``): the weaver's form of such a call after another timed event of its statement."""
    tick(k)
    return helper(*args)


def add(k: int) -> None:
    """Charge ``k`` cycles that need no alignment (a taken jump's extra cost)."""
    RT.cog.t += k


class _CogStopped(BaseException):
    """Raised inside a greenlet whose cog was stopped, so it unwinds without running more code."""


class Engine:
    """Runs translated cogs for one :class:`PythonChip`.

    Args:
        chip: the chip.
        epilogue: cycles of the ROM's ``COGID``/``COGSTOP`` bytecodes a top
            method returns into (from the cost model).
    """

    def __init__(self, chip, epilogue: int):
        self.chip = chip
        self.T = chip.timing
        self.epilogue = epilogue
        self.greenlets = {}
        self.scheduler = None
        #: (cog, first, end): where each started Spin cog's stack begins, and what RUN wrote at least
        self.stacks: list = []

    # ---------------------------------------------------------------- scheduler side
    def run(self, c, limit: int) -> None:
        """The scheduler's hook: run cog ``c`` while its next shared access is before ``limit``."""
        RT.cog = c
        RT.limit = limit
        RT.engine = self
        RT.keys[c.id] = None
        if self.chip._preempt:              # a preemption meant for a bytecode cog's loop
            self.chip._end_preemption()
        self.scheduler = greenlet.getcurrent()
        self.greenlets[c.id].switch()

    def key(self, c) -> int:
        """When cog ``c`` next touches shared state (the scheduler's order; see spinemu.chip.timing.access_offsets)."""
        k = RT.keys[c.id]
        if k is not None:
            return k
        t = c.t + 12
        return t + ((c.hub_phase - t) & 15)

    def pause(self) -> None:
        """Back to the scheduler; returns when the scheduler runs this cog again."""
        c = RT.cog
        self.scheduler.switch()
        RT.cog = c
        if c.state == STOPPED:
            raise _CogStopped()

    def attach(self, c, method, args) -> None:
        """Cog ``c`` was just started by the chip (registers, frame and first cycle set): run ``method(*args)`` in it."""
        c.engine = self
        self.chip._cogs_changed = True      # the scheduler lists running cogs (and their engines) again
        RT.keys[c.id] = None
        self.stacks.append((c.id, (c.dbase - 8) & 0xFFFF, max(c.par + 12, c.dbase)))
        self.greenlets[c.id] = greenlet.greenlet(lambda: self._cog_main(c, method, args))

    def _cog_main(self, c, method, args) -> None:
        try:
            try:
                method(*args)
                # the top method returns (its frame drops the result) into the ROM's COGID, COGSTOP
                add(drop_result_delta(self.T))
            except Abort as stop:
                stop.charge(False)
            tick(self.epilogue)
            spin.long[c.dbase - 8] = c.id      # COGID's push lands on the return frame
            t = spin._fetched()
            self.chip.stop_cog(c, t + self.T.cogstop_at, "returned from its top method")
        except _CogStopped:
            pass
        except RecursionError:
            raise self.chip.fault(c, 0, "stack overflow: the translated methods call each other too deeply "
                                        "(Python's recursion limit)") from None

    # ---------------------------------------------------------------- cog side (called by spin.*)
    def _fetched_in_turn(self, access: int) -> int:
        """The fetch cycle of a bytecode whose shared access (pins, another cog) is ``access`` cycles after it.

        Statements pay the bytecodes before a wait or a cog start/stop without
        that bytecode; before it acts, the cog lets every other cog whose
        access comes earlier go first, as the bytecode engine's scheduler does.
        """
        tf = spin._fetched()
        if tf + access >= RT.limit:
            pause_tick(tf + access)
        return tf

    def waitcnt(self, target: int) -> None:
        c, T = RT.cog, self.T
        tf = spin._fetched()
        issue = tf + T.waitcnt_issue
        wait = (target - issue - T.waitcnt_min) & 0xFFFFFFFF
        c.t = tf + T.waitcnt_issue + T.waitcnt_min + wait + T.waitcnt_after

    def waitvid(self, colors: int, pixels: int) -> None:
        c = RT.cog
        tf = spin._fetched()
        c.t = tf + self.chip.waitvid(c, colors & 0xFFFFFFFF, pixels & 0xFFFFFFFF, tf)

    def wait_pins(self, state: int, mask: int, equal: bool) -> None:
        c = RT.cog
        tf = self._fetched_in_turn(_ACCESS[0x1B])
        try:
            c.t = tf + self.chip.wait_pins(c, mask & 0xFFFFFFFF, state & 0xFFFFFFFF, equal, tf)
        except Reschedule:
            while c.state == PIN_WAIT:
                self.pause()

    def coginit(self, cog_id: int, method, args, stack: int) -> int:
        """COGINIT/COGNEW of a translated method: what RUN and COGINIT do on the chip."""
        chip, c = self.chip, RT.cog
        tf = self._fetched_in_turn(_ACCESS[0x2C])
        RT.limit = -1           # the scheduler must look again (the bytecode engine reschedules too)
        if not callable(method):                        # PASM: cognew(@code, par)
            par = args[0] if args else stack
            return spin.wrap(chip.coginit(c, cog_id, method, par, tf))
        par = _write_run_frame(stack, method, args)
        chip.next_python = (method, args)
        return spin.wrap(chip.coginit(c, cog_id, INTERPRETER_ENTRY, par, tf))

    def cogstop(self, cog_id: int) -> None:
        """COGSTOP: the target stops when the bytecode's hub instruction runs."""
        chip, c = self.chip, RT.cog
        t = self._fetched_in_turn(_ACCESS[0x21]) + self.T.cogstop_at
        target = chip.cogs[cog_id]
        if target is c:
            chip.stop_cog(c, t, "COGSTOP of itself")
            self.pause()
        elif target.state != STOPPED:
            chip.stop_cog(target, t, f"stopped by cog {c.id}")
            RT.limit = -1

    def reboot(self) -> None:
        """CLKSET with bit 7: the chip reboots when the bytecode's fetch completes (as the bytecode engine stops)."""
        from ..chip.control import RebootRequested
        c = RT.cog
        c.t = spin._fetched()
        raise RebootRequested(0)


def _write_run_frame(stack: int, method, args) -> int:
    """What Spin's RUN bytecode leaves on a new cog's stack; returns the new cog's PAR.

    The return frame, a zero result and the arguments, then the words the new
    cog's interpreter starts from at PAR+2: pbase, vbase, dbase (= stack + 8),
    the method's code address and its stack pointer.
    """
    L, W = RT.L, RT.W
    base = stack & 0xFFFC
    for k, v in enumerate((0xFFFFFFFF, 0xFFF9FFFF, 0, *args)):
        a = (base + 4 * k) & 0xFFFF
        if a < 0x8000:
            L[a >> 2] = v & 0xFFFFFFFF
    par = (base + 12 + 4 * len(args)) & 0xFFFF
    obj = method.__self__
    code, frame = _method_entry(obj, method.__name__)
    for k, v in enumerate((obj._pbase, obj._vbase, base + 8, code, par + frame)):
        a = (par + 2 + 2 * k) & 0xFFFF
        if a < 0x8000:
            W[a >> 1] = v & 0xFFFF
    return par


def _method_entry(obj, name: str) -> tuple:
    """``(code address, locals bytes)`` of method ``name`` of ``obj`` from its object table in hub RAM."""
    import sys
    index = getattr(sys.modules[type(obj).__module__], "SPIN_METHODS", {}).get(name)
    if index is None:
        return 0, 0
    entry = obj._pbase + 4 * index
    return (obj._pbase + RT.W[entry >> 1]) & 0xFFFF, RT.W[(entry + 2) >> 1]


def instantiate(cls, mem, pbase: int, vbase: int):
    """A translated object of class ``cls`` (and its children) at ``pbase``/``vbase``.

    The children's addresses come from the object table in hub RAM ``mem``,
    exactly as the interpreter's CALL_OBJ finds them (word 0: offset of the
    child from ``pbase``, word 1: offset of its VAR block from ``vbase``).
    """
    obj = cls.__new__(cls)
    obj._pbase = pbase
    obj._vbase = vbase
    n_methods = mem[pbase + 2] - 1
    entry = pbase + 4 * (1 + n_methods)
    for name, decl in _children_of(cls):
        made = ObjectArray(name)
        for _ in range(decl.count):
            child_p = (pbase + int.from_bytes(mem[entry:entry + 2], "little")) & 0xFFFF
            child_v = (vbase + int.from_bytes(mem[entry + 2:entry + 4], "little")) & 0xFFFF
            made.append(instantiate(decl.cls, mem, child_p, child_v))
            entry += 4
        obj.__dict__[name] = made if decl.count != 1 else made[0]
    return obj


class ObjectArray(list):
    """The instances of an object array (``OBJ b[2] : "child"``).

    An index outside the array is a run-time fault naming the Spin line: the
    bytecode interpreter calls through whatever object-table entry lies there,
    which the translation cannot follow (a plain list would raise IndexError,
    or take ``b[-1]`` for the last instance).
    """

    __slots__ = ("name",)

    def __init__(self, name: str):
        super().__init__()
        self.name = name

    def __getitem__(self, index):
        if isinstance(index, int) and 0 <= index < len(self):
            return list.__getitem__(self, index)
        raise python_fault(f"object index {index} is outside {self.name}[0..{len(self) - 1}]: the bytecode "
                           "would call through whatever object-table entry lies there, which the Python "
                           "translation cannot follow")


def python_fault(message: str):
    """An :class:`~spinemu.diagnostics.EmulationError` for the running cog at the Spin line of the
    innermost translated statement on the call stack (its ``# L<n>`` tag)."""
    import linecache
    import re
    import sys

    from ..diagnostics import EmulationError

    frame = sys._getframe(1)
    while frame is not None and "SPIN_METHODS" not in frame.f_globals:
        frame = frame.f_back
    path = line = None
    if frame is not None:
        tag = re.search(r"# L(\d+)", linecache.getline(frame.f_code.co_filename, frame.f_lineno))
        line = int(tag.group(1)) if tag else None
        doc = re.search(r"Translated from (.+?) by spinemu\.translate", frame.f_globals.get("__doc__") or "")
        path = doc.group(1) if doc else None
    cog = f" (cog {RT.cog.id})" if RT.cog is not None else ""
    return EmulationError(message + cog, path=path, line=line)


def _children_of(cls):
    return [(k, v) for k, v in vars(cls).items() if isinstance(v, spin.Child)]


def run_class(cls, image: bytes, *, max_cycles=None, compat: str = "spinsim", inputs=None, parts=()):
    """Run translated top class ``cls`` on a :class:`PythonChip` loaded with ``image`` (``parts`` attached first)."""
    from ..image import ImageHeader, load_image
    from .weave import prepare
    prepare(cls)
    binary = load_image(bytes(image))
    header = ImageHeader.parse(binary)
    mem = bytearray(binary)
    top = instantiate(cls, mem, header.pbase, header.vbase)
    T = load_timing()
    epilogue = T.reg[(0x3F, 0)]        # the ROM's COGID ($3F $89) before COGSTOP
    chip = PythonChip(image, top, epilogue, compat=compat, inputs=inputs)
    if parts:
        from ..bench import Bench
        (parts if isinstance(parts, Bench) else Bench(parts)).attach(chip)
    RT.final = _NEVER if max_cycles is None else max_cycles
    result = chip.run(max_cycles)
    result.stats["stacks"] = list(chip.engine.stacks)
    return result


class PythonChip(Chip):
    """A :class:`~spinemu.chip.Chip` whose Spin cogs run a translated program.

    The chip boots and starts cogs itself (``start_spin_cog``: the cog's
    registers, its frame from PAR, its first cycle); this class then hands the
    cog to the Python engine instead of the bytecode interpreter.

    Args:
        image: the compiled image (its hub RAM contents: DAT, strings, VAR).
        top: the translated top object (an instance made by :func:`instantiate`).
        epilogue: see :class:`Engine`.
        compat, inputs: as for :class:`~spinemu.chip.Chip`.
    """

    def __init__(self, image: bytes, top, epilogue: int, *, compat: str = "spinsim", inputs=None):
        super().__init__(image, compat=compat, inputs=inputs, fast_forward=False)
        self.top = top
        self.engine = Engine(self, epilogue)
        self.next_python = None
        RT.attach(self.mem)
        RT.chip, RT.T, RT.engine, RT.pause = self, self.timing, self.engine, self.engine.pause
        RT.pending = None
        RT.keys = [None] * 8
        # a division's loop beyond the reference the statements paid, by the divisor's bit length
        table = self.timing._math[0xF6 & 0x1F]
        RT.div_extra = [table[n] - table[MATH_REF[0xF6]] for n in range(33)]

    def start_spin_cog(self, c, par: int, t_first: int, by) -> None:
        super().start_spin_cog(c, par, t_first, by)
        if self.next_python is not None:
            method, args = self.next_python
            self.next_python = None
            name = method.__qualname__
        elif by is not None:        # a PASM cog's COGINIT of the interpreter: its frame is in hub
            return                  # RAM, so the bytecode interpreter runs that cog
        else:                                           # the boot: the top object's first method
            method, args = _first_method(self.top), ()
            name = getattr(method, "__qualname__", None) or method.func.__qualname__
        when, cog_id, kind, detail = self.cog_events[-1]
        self.cog_events[-1] = (when, cog_id, kind, detail.replace("Spin method", f"Python {name}", 1))
        self.engine.attach(c, method, args)

    # Where the chip's scheduler hands a cog over (spinemu.chip.scheduler; it asks engine.key(c) itself):
    def _run_spin(self, c, limit: int, stop_pc: int = -1) -> None:
        """Run cog ``c`` until ``limit``: translated cogs by the Python engine."""
        if c.engine is self.engine:
            self.engine.run(c, limit)
        else:
            super()._run_spin(c, limit, stop_pc)



def _first_method(obj):
    """The top object's first method; its parameters start as zeros (the boot stack is cleared RAM)."""
    import functools
    import inspect
    method = getattr(obj, type(obj).SPIN_FIRST_METHOD)
    n = len(inspect.signature(method).parameters)
    return functools.partial(method, *([0] * n)) if n else method


assert INTERPRETER_ENTRY  # the Spin interpreter's address: PASM starts elsewhere
