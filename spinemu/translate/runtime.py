"""The Python engine: translated Spin objects running on spinemu's chip model.

* :class:`PythonChip` is a :class:`spinemu.chip.Chip` whose Spin cogs run
  translated Python instead of bytecode.  The chip's scheduler hands such a
  cog to :meth:`Engine.run` (the engine hook in ``Chip._run_spin``); the
  engine switches into the cog's greenlet, which runs the translated method
  as plain synchronous Python until the cog's time passes the limit the
  scheduler gave it, or it waits.  So cogs stay in time order exactly as
  bytecode cogs do: a cog runs ahead only until another runnable cog is
  earlier.
* Time: the generated module carries a table ``SPIN_CYCLES`` (Python line ->
  cycles).  :func:`prepare` weaves those charges into the class's methods
  when the class is first run (:mod:`spinemu.translate.weave`), so the
  readable source stays free of bookkeeping and each statement still costs
  exactly what its bytecode costs.
* :func:`instantiate` builds the object tree at the hub addresses of the
  compiler's :class:`~spinemu.compiler.InstanceLayout`.

Hot path: :func:`tick` (called once or twice per statement).
"""
from __future__ import annotations

import greenlet

from ..chip.chip import COG_LOAD_CYCLES, Chip
from ..chip.cog import PIN_WAIT, RUNNING, STOPPED
from ..chip.control import Reschedule
from ..chip.rom import INTERPRETER_ENTRY
from ..chip.timing import load_timing
from . import spin
from .costs import drop_result_delta
from .spin import RT, Abort

__all__ = ["PythonChip", "Engine", "instantiate", "run_class", "tick", "tick_at", "tick_read", "add"]

_NEVER = 1 << 62
_SPINSIM_START = -4


def tick(k: int) -> None:
    """Charge the current cog a run of bytecodes: fetch alignment, then ``k`` cycles. (Hot path.)"""
    c = RT.cog
    t = c.t
    if t >= RT.limit:
        RT.pause()
        t = c.t
    t += 12
    c.t = t + ((c.hub_phase - t) & 15) + k


def tick_at(k: int, access: int) -> None:
    """:func:`tick` for a run whose first shared hub access starts ``access`` cycles after its fetch.

    The run must not pass another cog before that access (the bytecode
    engine would let the other cog's earlier writes land first), so the
    cog waits for the scheduler at that moment, not at the run's start.
    """
    c = RT.cog
    t = c.t + 12
    t += (c.hub_phase - t) & 15
    if t + access >= RT.limit:
        c.t = t + access
        RT.pause()
    c.t = t + k


def tick_read(k, access, rest: int) -> None:
    """Charge ``k`` (``None``: nothing) as :func:`tick_at`/:func:`tick`, and leave ``rest`` for the register read that follows."""
    if k is not None:
        if access is not None:
            tick_at(k, access)
        else:
            tick(k)
    RT.pending = rest


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
        """The scheduler's hook: run cog ``c`` while its time is before ``limit``."""
        RT.cog = c
        RT.limit = limit
        RT.engine = self
        self.scheduler = greenlet.getcurrent()
        g = self.greenlets[c.id]
        g.switch()

    def pause(self) -> None:
        """Back to the scheduler; returns when the scheduler runs this cog again."""
        c = RT.cog
        self.scheduler.switch()
        RT.cog = c
        if c.state == STOPPED:
            raise _CogStopped()

    def start(self, c, method, args, t_first: int, dbase: int, frame_end: int = 0) -> None:
        """Make cog ``c`` run ``method(*args)``, its first statement at the interpreter's first bytecode.

        ``dbase``: where the bytecode interpreter would put the method's frame
        (its stack starts 8 bytes below, at the return frame).
        """
        c.engine = self
        c.dbase = dbase
        self.stacks.append((c.id, (dbase - 8) & 0xFFFF, max(frame_end, dbase)))
        c.state = RUNNING
        c.started_at = t_first
        c.t = self.T.interpreter_start(t_first, c.hub_phase)
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

    # ---------------------------------------------------------------- cog side (called by spin.*)
    def waitcnt(self, target: int) -> None:
        c, T = RT.cog, self.T
        tf = spin._fetched()
        issue = tf + T.waitcnt_issue
        wait = (target - issue - T.waitcnt_min) & 0xFFFFFFFF
        c.t = tf + T.waitcnt_issue + T.waitcnt_min + wait + T.waitcnt_after

    def wait_pins(self, state: int, mask: int, equal: bool) -> None:
        c = RT.cog
        tf = spin._fetched()
        try:
            c.t = tf + self.chip.wait_pins(c, mask & 0xFFFFFFFF, state & 0xFFFFFFFF, equal, tf)
        except Reschedule:
            while c.state == PIN_WAIT:
                self.pause()

    def coginit(self, cog_id: int, method, args, stack: int) -> int:
        chip, c = self.chip, RT.cog
        tf = spin._fetched()
        if not callable(method):                        # PASM: cognew(@code, par)
            par = args[0] if args else stack
            RT.limit = -1
            return spin.wrap(chip.coginit(c, cog_id, method, par, tf))
        done = tf + self.T.coginit_done
        if cog_id >= 8:
            free = [k for k in chip.cogs if k.state == STOPPED]
            if not free:
                return -1
            target = free[0]
        else:
            target = chip.cogs[cog_id]
        if target.state != STOPPED:
            chip.stop_cog(target, done, f"restarted by cog {c.id}")
        _write_run_frame(stack, args)
        t_first = done + (_SPINSIM_START if chip.spinsim else COG_LOAD_CYCLES)
        keep = (target.dira, target.outa) if chip.spinsim else (0, 0)
        target.reset_registers()
        target.dira, target.outa = keep
        target.par = (stack + 12 + 4 * len(args)) & 0xFFFC
        # RUN leaves the frame, the arguments and the new interpreter's words at PAR+2..PAR+11
        self.start(target, method, args, t_first, stack + 8, target.par + 12)
        chip.cog_events.append((t_first, target.id, "start",
                                f"Python method {method.__qualname__} (started by cog {c.id})"))
        if keep != (0, 0):
            chip.note_pins(target, t_first)
        RT.limit = -1           # the scheduler must look again (the bytecode engine reschedules too)
        return target.id

    def cogstop(self, cog_id: int) -> None:
        chip, c = self.chip, RT.cog
        t = spin._fetched() + self.T.cogstop_at
        target = chip.cogs[cog_id]
        if target is c:
            chip.stop_cog(c, t, "COGSTOP of itself")
            self.pause()
        elif target.state != STOPPED:
            chip.stop_cog(target, t, f"stopped by cog {c.id}")
            RT.limit = -1

    def reboot(self) -> None:
        from ..chip.control import RebootRequested
        raise RebootRequested(0)


def _write_run_frame(stack: int, args) -> None:
    """What Spin's RUN bytecode leaves on a new cog's stack: the return frame, a zero result, the arguments."""
    L = RT.L
    base = stack & 0xFFFC
    for k, v in enumerate((0xFFFFFFFF, 0xFFF9FFFF, 0, *args)):
        a = (base + 4 * k) & 0xFFFF
        if a < 0x8000:
            L[a >> 2] = v & 0xFFFFFFFF


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
        made = []
        for _ in range(decl.count):
            child_p = (pbase + int.from_bytes(mem[entry:entry + 2], "little")) & 0xFFFF
            child_v = (vbase + int.from_bytes(mem[entry + 2:entry + 4], "little")) & 0xFFFF
            made.append(instantiate(decl.cls, mem, child_p, child_v))
            entry += 4
        obj.__dict__[name] = made if decl.count != 1 else made[0]
    return obj


def _children_of(cls):
    return [(k, v) for k, v in vars(cls).items() if isinstance(v, spin.Child)]


def run_class(cls, image: bytes, *, max_cycles=None, compat: str = "chip", inputs=None):
    """Run translated top class ``cls`` on a :class:`PythonChip` loaded with ``image``."""
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
    result = chip.run(max_cycles)
    result.stats["stacks"] = list(chip.engine.stacks)
    return result


class PythonChip(Chip):
    """A :class:`~spinemu.chip.Chip` whose Spin cogs run a translated program.

    Args:
        image: the compiled image (its hub RAM contents: DAT, strings, VAR).
        top: the translated top object (an instance made by :func:`instantiate`).
        epilogue: see :class:`Engine`.
        compat, inputs: as for :class:`~spinemu.chip.Chip`.
    """

    def __init__(self, image: bytes, top, epilogue: int, *, compat: str = "chip", inputs=None):
        super().__init__(image, compat=compat, inputs=inputs, fast_forward=False)
        self.top = top
        self.engine = Engine(self, epilogue)

    def _boot(self) -> None:
        self._pin_waiters = []
        self._video_ready = [0] * 8
        RT.attach(self.mem)
        RT.chip, RT.T, RT.engine, RT.pause = self, self.timing, self.engine, self.engine.pause
        RT.pending = None
        t_first = 0 if self.spinsim else COG_LOAD_CYCLES
        c = self.cogs[0]
        c.reset_registers()
        c.par = 0x0004
        first = _first_method(self.top)
        self.engine.start(c, first, (), t_first, self.header.dbase)
        name = getattr(first, "__qualname__", None) or first.func.__qualname__
        self.cog_events.append((t_first, 0, "start", f"Python method {name} (boot)"))


def _first_method(obj):
    """The top object's first method; its parameters start as zeros (the boot stack is cleared RAM)."""
    import functools
    import inspect
    method = getattr(obj, type(obj).SPIN_FIRST_METHOD)
    n = len(inspect.signature(method).parameters)
    return functools.partial(method, *([0] * n)) if n else method


assert INTERPRETER_ENTRY  # the Spin interpreter's address: PASM starts elsewhere
