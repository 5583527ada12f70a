"""PASM cogs: Propeller 1 assembly run instruction by instruction, to the cycle.

A cog started on code other than the ROM's Spin interpreter (``cognew(@entry,
par)`` from Spin, ``COGINIT`` from PASM) loads 496 longs from hub RAM into its
cog RAM and runs them (Propeller Manual v1.2, "Assembly Language Reference").
:class:`PasmEngine` is the cog's engine: the chip's scheduler
(:mod:`.scheduler`) calls :meth:`PasmEngine.run` and :meth:`PasmEngine.key`
for it, as for any engine object, so Spin and PASM cogs share one clock, one
hub, one set of pins, the locks and each other's COGINIT/COGSTOP.

**Instructions are data.**  :mod:`spinemu.pasm` is the instruction table (the
assembler and disassembler read it too); :mod:`.pasm_ops` holds the ALU as
Python expressions and writes one small Python function per distinct
instruction long (condition, operands, special registers, effects and
timing folded in), cached by the long, so self-modifying code needs no
bookkeeping.

**Cog RAM** is a plain list of 512 ints, plus four slots after it:
``[512]`` the flags ``C << 1 | Z``, ``[513]`` the real PAR, ``[514]`` the
cog's hub phase, ``[515]`` the :class:`~spinemu.chip.cog.Cog`.  ``$1F0-$1FF``
hold the registers' shadow RAM: OUTA, DIRA, CTRx, FRQx, VCFG, VSCL mirror
their registers; PAR, CNT, INA, INB and PHSx as *destination* read this
shadow (what an instruction last wrote there), as *source* the register.

**Timing** (measured on spinsim 0.99 ``-p``, tests/data/chip/pasm): 4 cycles per
instruction; ``djnz``/``tjz``/``tjnz`` 4 when they jump, 8 when not; a false
condition 4; a hub instruction starting at ``t`` ends at the first cycle
``>= t + 8`` on the cog's hub window; ``waitcnt`` ends on the first cycle of
the cog's 4-cycle grid at or after its target (a target up to 3 cycles back
still counts) and the next instruction starts 4 later; ``waitpeq``/``waitpne``
poll INA every 4 cycles.  The instruction after one that writes cog RAM was
fetched before the write (the P1 pipeline): it runs its old value.

**Scheduling.**  Only some instructions touch state other cogs share: hub
instructions (at their hub window), INA reads, OUTA/DIRA writes that change
them, counter writes, PHS reads of a counter in a pin-reading mode,
``waitpeq``/``waitpne``.  A PASM cog runs ahead freely through the others
(its own cog RAM, CNT, ``waitcnt``) and stops only before a shared access at
or past the scheduler's ``until``; its key is that access's cycle.  A cog
whose write reaches the same pins or hub long in the same cycle as another
cog's read goes first when its id is lower (as spinsim steps its cogs).

**Hot paths:** :meth:`PasmEngine.run` (one dict lookup of the instruction
long, one call, no flag checks) and the generated handlers (:mod:`.pasm_ops`).
:meth:`PasmEngine.run_traced` is its instrumented twin (``--trace-cog``, the
debugger: one instruction at a time, with the same results).
"""
from __future__ import annotations

from typing import Callable, NamedTuple, Optional

from .. import pasm as isa
from .cog import PARKED, PIN_WAIT, RUNNING, STOPPED
from .control import RebootRequested
from .pasm_blocks import HOT, RECOMPILE_LIMIT, PasmBlockCompiler
from .pasm_idle import IdleSkipper
from .pasm_ops import AUX, COG, FLAGS, HUB_PHASE, PAR_REAL, RAM_SLOTS, Fetched, HandlerBuilder, Handlers, Leave, Yield

__all__ = ["PasmEngine", "PasmStep", "LOAD_LONGS", "RUN_AHEAD"]

M = 0xFFFFFFFF
NEVER = 1 << 62
#: longs a started cog loads from hub RAM ($000-$1EF)
LOAD_LONGS = 496
#: cycles a PASM cog may run past the scheduler's ``until`` through instructions only it sees
RUN_AHEAD = 1 << 16
_OUTA, _DIRA, _PAR = isa.REGISTERS["OUTA"], isa.REGISTERS["DIRA"], isa.REGISTERS["PAR"]


class PasmStep(NamedTuple):
    """One executed instruction, as :meth:`PasmEngine.run_traced` reports it.

    ``cycle`` its first cycle, ``pc`` its cog address, ``word`` the long,
    ``executed`` False when its condition was false, ``z``/``c`` the flags
    after it, ``result`` the value it wrote to D (``None``: it wrote none).
    """

    cycle: int
    cog: int
    pc: int
    word: int
    executed: bool
    z: int
    c: int
    result: Optional[int]

    def text(self, symbols: Optional[dict] = None) -> str:
        """One log line: cycle, cog, address, disassembly, flags, written value.

        ``symbols`` (cog address -> name) names registers, jump targets and
        the instruction's own address, as in ``spinemu disasm``.
        """
        # `jmp #0` and `ret` are one long: a label at $000 says it is a jump
        dis = " ".join(isa.disassemble(self.word, None, symbols, ret_as_jmp=bool(symbols) and 0 in symbols).split())
        where = f"${self.pc:03X}"
        if symbols:
            where = f"{where} {symbols.get(self.pc, '')}".ljust(17)
        tail = f"Z={self.z} C={self.c}"
        if not self.executed:
            tail = "(condition false) " + tail
        elif self.result is not None:
            tail += f" -> ${self.result:08X}"
        return f"{self.cycle:>12} cog {self.cog} {where}  {dis:<36} {tail}"


_NEXT = [(k + 1) & 511 for k in range(512)]
_LEFT = "left"
_COLD = 1 << 30                 # heat of an address that is not compiled again (soon)
_NO_HEAT = [_COLD] * 512        # the heat counted while a slice ends inside a block (it is thrown away)


class CogAux:
    """A PASM cog's engine state besides its RAM (``R[AUX]``): blocks, heat, idle-loop checks.

    ``blocks[pc]`` is the compiled block starting at ``pc`` or ``None``;
    ``heat[pc]`` counts down the interpreted visits of ``pc`` until a block
    is compiled there; ``compiles[pc]`` how often one was; ``idle_at`` the
    cycle of the next offer of the cog's loop to the idle-loop skipper,
    ``idle_every`` the interval after a refusal.
    """

    __slots__ = ("blocks", "heat", "compiles", "idle_at", "idle_every")

    def __init__(self, idle_at: int):
        self.blocks: list = [None] * 512
        self.heat = [HOT] * 512
        self.compiles = bytearray(512)
        self.idle_at = idle_at
        self.idle_every = 0


class PasmEngine:
    """Runs the chip's PASM cogs (one engine per chip, any number of cogs).

    The scheduler calls :meth:`run` and :meth:`key`; the chip calls
    :meth:`start` from its COGINIT.

    Args:
        chip: the :class:`~spinemu.chip.chip.Chip`.
    """

    def __init__(self, chip):
        self.chip = chip
        #: the scheduler's ``until`` for the running cog (handlers read ``until[0]``)
        self.until = [0]
        self.builder = HandlerBuilder(self)
        self.handlers = Handlers(self.builder.build)
        #: cog id -> callback(PasmStep), for cogs whose instructions are traced
        self.tracers: dict = {}
        self.instructions = 0
        #: cog id -> register a waiting WAITPEQ/WAITPNE with ``wr`` writes when it ends
        self.wait_results: dict = {}
        #: hot blocks of cog RAM compiled to Python (None: every instruction through its handler)
        self.compiler = PasmBlockCompiler(self.builder) if chip.compile_blocks else None
        #: the idle-loop skipper (parks cogs in loops that wait for a change)
        self.idle = IdleSkipper(self, enabled=chip.fast_forward)

    def __repr__(self) -> str:  # the scheduler's engine name in debugging output
        return "<PasmEngine>"

    def stats(self) -> dict:
        """The run's PASM speed-up statistics (merged into ``RunResult.stats``)."""
        idle = self.idle
        return {"pasm_blocks_compiled": self.compiler.count if self.compiler is not None else 0,
                "pasm_loops_parked": idle.parked, "pasm_passes_skipped": idle.passes_skipped,
                "pasm_instructions_skipped": idle.instructions_skipped}

    # ------------------------------------------------------------------ starting
    def start(self, c, code: int, par: int, t_first: int, by) -> None:
        """COGINIT of PASM: cog ``c`` loads 496 longs from hub ``code`` and runs them.

        ``t_first`` is the cog's start cycle (its pipeline's first slot); its
        first instruction runs 4 cycles later.  PAR is ``par & $FFFC``.
        """
        chip = self.chip
        keep = (c.dira, c.outa) if chip.spinsim else (0, 0)
        if c.ctra or c.ctrb:                    # a restarted cog's counters start off
            for which in (0, 1):
                chip.counters.write(c, which, 0, t_first)
        c.reset_registers()
        c.dira, c.outa = keep
        par &= 0xFFFC
        code &= 0xFFFC
        L = chip.mem_longs
        base = code >> 2
        R = [L[(base + k) & 0x3FFF] for k in range(LOAD_LONGS)] + [0] * (RAM_SLOTS - LOAD_LONGS)
        R[_OUTA], R[_DIRA] = c.outa, c.dira
        if chip.spinsim:
            R[_PAR] = par
        R[PAR_REAL], R[HUB_PHASE], R[COG], R[FLAGS] = par, c.hub_phase, c, 0
        R[AUX] = CogAux(t_first + 4 + self.idle.first_offer)
        if c.busy is not None:                  # parked before its restart
            self.idle.forget(c)
        c.ram = R
        c.par = par
        c.pc = 0
        c.ir = None
        c.engine = self
        c.state = RUNNING
        c.code_addr = code
        chip._cogs_changed = True
        c.started_at = t_first
        c.t = c.key = t_first + 4
        label = chip.code_label(code)
        chip.cog_events.append((t_first, c.id, "start", f"PASM at ${code:04X}" + (f" {label}" if label else "")
                                + (f" (started by cog {by.id})" if by else "")))
        if keep != (0, 0):
            chip.note_pins(c, t_first)

    # ------------------------------------------------------------------ scheduler side
    def key(self, c) -> int:
        """The cycle of cog ``c``'s next access to shared state (a lower bound after it ran ahead)."""
        k = c.key
        return k if k > c.t else c.t

    def run(self, c, until: int) -> None:
        """Run cog ``c`` until its next shared access at or past ``until``. (Hot loop.)

        Instructions that only touch the cog's own RAM run on past ``until``
        (up to :data:`RUN_AHEAD` cycles and never past the run's limit), a
        compiled block (:mod:`.pasm_blocks`) at a time where there is one.
        Every :attr:`CogAux.idle_at` cycles the cog's loop is offered to the
        idle-loop skipper (:mod:`.pasm_idle`), which may park the cog.
        """
        if c.id in self.tracers:
            return self.run_traced(c, until)
        if c.state == PARKED:                   # its horizon came first: the loop ends here
            self.idle.resume(c, until)
        chip = self.chip
        self.until[0] = until
        R = c.ram
        A = R[AUX]
        B = A.blocks
        H = self.handlers
        NEXT = _NEXT
        pc = c.pc
        t = c.t
        w = c.ir
        if w is None:
            w = R[pc]
        bound = (until if until > t else t) + RUN_AHEAD
        if bound > chip.run_limit:
            bound = chip.run_limit
        n = 0
        key = None
        while key is None:
            lim = A.idle_at
            if lim > bound:
                lim = bound
            HEAT = A.heat
            try:
                while t < lim:
                    b = B[pc]
                    if b is not None:
                        x = b(R, t, w, lim)
                        if x >= 0:
                            t = x >> 17
                            n += (x >> 9) & 255
                            pc = x & 511
                            w = R[pc]
                            continue
                        if x == -2:         # the rest of the slice, instruction by instruction: not hot
                            HEAT = _NO_HEAT
                    h = HEAT[pc]
                    if h:
                        HEAT[pc] = h - 1
                    elif self._hot(A, R, pc):
                        continue            # a block starts here now: run it
                    pc1 = NEXT[pc]
                    w1 = R[pc1]
                    x = H[w](R, pc, t)
                    if x is None:
                        pc = pc1
                        w = w1
                        t += 4
                    elif x >= 0:
                        t = x >> 9
                        pc = x & 511
                        w = w1 if pc == pc1 else R[pc]
                    else:                   # its shared access must wait for its turn
                        key = -1 - x
                        break
                    n += 1
                else:
                    if t >= bound:
                        key = t
                    else:                   # time to offer the loop to the idle skipper
                        c.instructions += n
                        self.instructions += n
                        n = 0
                        if self.idle.offer(c, R, pc, t, w):
                            return          # parked: the skipper set the cog's state
            except Yield as e:
                key = e.key
            except Fetched as e:
                n += 1
                t = e.x >> 9
                pc = e.x & 511
                w = e.word
            except Leave as e:
                n += 1
                if e.x is None:             # the handler left the cog as it must be
                    c.instructions += n
                    self.instructions += n
                    return
                t = e.x >> 9
                pc = e.x & 511
                w = w1 if pc == pc1 else R[pc]
                key = t
        c.instructions += n
        self.instructions += n
        c.pc = pc
        c.t = t
        c.ir = w
        c.key = key

    def _hot(self, A: "CogAux", R: list, pc: int) -> bool:
        """Address ``pc`` was interpreted :data:`~.pasm_blocks.HOT` times: compile a block there.

        Returns whether a new block starts there.  A block that exists (it
        declined a run) is kept while its code is unchanged; an address
        recompiled :data:`~.pasm_blocks.RECOMPILE_LIMIT` times stays
        interpreted.
        """
        A.heat[pc] = _COLD
        if self.compiler is None:
            return False
        old = A.blocks[pc]
        if old is not None and old.matches(R):
            A.heat[pc] = HOT
            return False
        if A.compiles[pc] >= RECOMPILE_LIMIT:
            A.blocks[pc] = None
            return False
        A.compiles[pc] += 1
        fn = A.blocks[pc] = self.compiler.compile(R, pc)
        if fn is None:
            return False
        heat = A.heat
        for a in range(pc, fn.span[1]):         # inside the block: cold again (entered by jumps only)
            if heat[a] < HOT:
                heat[a] = HOT
        return True

    def run_traced(self, c, until: int) -> None:
        """:meth:`run` one instruction at a time, reporting each to the cog's tracer (no running ahead).

        A tracer with a ``before(cog)`` method (a debugger's) is also called
        before each instruction it may run; it may raise
        :class:`~spinemu.chip.control.Halted` to stop the run there, with the
        cog exactly as before that instruction (it may be called again for
        the same instruction when its shared access must wait for another cog).
        The results are those of :meth:`run`: each instruction runs at the
        same cycle; only the running ahead is given up.
        """
        report = self.tracers[c.id]
        before = getattr(report, "before", None)
        while c.state == RUNNING and c.engine is self and c.t < until:
            if before is not None:
                before(c)
            R = c.ram
            pc, t = c.pc, c.t
            w = c.ir if c.ir is not None else R[pc]
            executed = bool((((w >> 18) & 15) >> R[FLAGS]) & 1)
            done = self._step(c, until)
            if not done:
                return                      # its shared access comes after another cog's
            writes = executed and w & isa.R_BIT
            F = R[FLAGS]
            report(PasmStep(t, c.id, pc, w, executed, F & 1, F >> 1, R[(w >> 9) & 0x1FF] if writes else None))
            if done is _LEFT:
                return                      # the scheduler must look again

    def _step(self, c, until: int):
        """Execute one instruction of cog ``c`` unless its shared access comes at or after ``until``.

        Returns False (it did not run), True, or ``_LEFT`` (it ran and the
        scheduler must look again).
        """
        R = c.ram
        pc, t = c.pc, c.t
        w = c.ir if c.ir is not None else R[pc]
        pc1 = _NEXT[pc]
        w1 = R[pc1]
        self.until[0] = until
        try:
            x = self.handlers[w](R, pc, t)
            if x is not None and x < 0:
                raise Yield(-1 - x)
        except Yield as e:
            c.key = e.key
            return False
        except Fetched as e:
            x, w1, pc1 = e.x, e.word, e.x & 511
        except Leave as e:
            x = e.x
            c.instructions += 1
            self.instructions += 1
            if x is None:                   # the handler left the cog as it must be
                return _LEFT
            self._advance(c, R, x, pc1, w1)
            return _LEFT
        c.instructions += 1
        self.instructions += 1
        if x is None:
            c.pc, c.t, c.ir = pc1, t + 4, w1
            c.key = c.t
        else:
            self._advance(c, R, x, pc1, w1)
        return True

    @staticmethod
    def _advance(c, R, x: int, pc1: int, w1: int) -> None:
        c.t, c.pc = x >> 9, x & 511
        c.ir = w1 if c.pc == pc1 else R[c.pc]
        c.key = c.t

    # ------------------------------------------------------------------ what handlers call
    def wait_pins(self, R, pc: int, t: int, mask: int, state: int, equal: bool, dest: int = -1) -> None:
        """WAITPEQ/WAITPNE whose condition does not hold at ``t``: wait until the pins change.

        ``dest`` (with ``wr``): the register that gets ``D - (INA & S)`` when the wait ends.
        """
        chip = self.chip
        c = R[COG]
        if dest >= 0:
            self.wait_results[c.id] = dest
        c.pin_wait = (mask, state, equal, None)
        c.state = PIN_WAIT
        chip._cogs_changed = True
        chip._pin_waiters.append(c)
        if chip._ext_seen < t:
            chip._ext_seen = t
        c.pc = (pc + 1) & 511
        c.t = t
        c.ir = None
        c.key = 0
        raise Leave(None)

    def wake_time(self, c, t: int, writer, seen=None) -> int:
        """The first cycle of the instruction after a WAITPEQ/WAITPNE that the pins at ``t`` satisfy.

        ``t`` is when the pins changed: a cog's write (``writer``) shows at its
        instruction's cycle + 4, which a poll in that cycle sees when the
        writer's id is lower; an input or counter edge (``writer`` None) is
        seen by the first poll at or after it.  Polls fall on the waiting
        cog's 4-cycle grid.
        """
        if c.state == PARKED:                   # an idle loop that reads the pins
            return self.idle.wake_time(c, t, writer, seen)
        grid = c.t & 3
        base = t - 4 if writer is not None else t
        poll = base + ((grid - base) & 3)
        if writer is not None and poll == base and writer.id > c.id:
            poll += 4
        dest = self.wait_results.pop(c.id, None)
        if dest is not None:
            mask, state, _equal, _after = c.pin_wait
            value = (state - (self.chip.ina(t) & mask)) & M
            c.ram[dest] = value
            if dest >= 0x1F4:
                self.chip.registers.write(c, dest, value, poll + 4)
        return poll + 4

    def waitvid(self, R, pc: int, t: int) -> int:
        """WAITVID in chip mode: wait for the video generator to take the next frame (VSCL[11:0] clocks)."""
        chip = self.chip
        c = R[COG]
        frame = (R[0x1FF] & 0xFFF) or 4096
        start = max(t, chip._video_ready[c.id])
        chip._video_ready[c.id] = start + frame
        return ((start + 4) << 9) | ((pc + 1) & 511)

    def make_hubop(self, word: int) -> Callable:
        """The handler of a HUBOP long (CLKSET ... LOCKCLR) or of an undefined hub opcode ($04-$07)."""
        cond = (word >> 18) & 15
        op = self.hubop

        def h(R, pc, t):
            if not (cond >> R[FLAGS]) & 1:
                return None
            return op(R, pc, t, word)
        return h

    def hubop(self, R, pc: int, t: int, word: int) -> int:
        """Run a hub operation; results and flags as measured on spinsim 0.99 (docs/pasm.md)."""
        chip = self.chip
        c = R[COG]
        key = t + 8
        key += (R[HUB_PHASE] - key) & 15
        nxt = (key << 9) | ((pc + 1) & 511)
        dest = (word >> 9) & 0x1FF
        wz, wc, wr = word & isa.Z_BIT, word & isa.C_BIT, word & isa.R_BIT
        if word >> 26 != 3:                             # opcodes $04-$07: no operation, D := 0
            if wr:
                self._write_hub_result(R, c, dest, 0, key, nxt)
            return nxt
        src = word & 0x1FF
        op = (src if word & isa.I_BIT else R[src]) & 7
        if op == 1:                                     # COGID: no shared state, flags kept
            if wr:
                self._write_hub_result(R, c, dest, c.id, key, nxt)
            return nxt
        done = key - 4 if op in (2, 3) else key         # a cog op acts in its last cycle
        if done >= self.until[0]:
            raise Yield(done)
        d = R[dest]
        zero = carry = None
        leave = False
        if op == 0:                                     # CLKSET: D written back unchanged with wr
            result = d
            mode = d & 0xFF
            if mode & 0x80:
                c.t = key
                raise RebootRequested(0)
            chip.set_clock_mode(mode)
        elif op == 2:                                   # COGINIT
            free = any(k.state == STOPPED for k in chip.cogs)
            cog_id = 8 if d & 8 else d & 7
            got = chip.start_cog(c, cog_id, (d >> 2) & 0xFFFC, (d >> 16) & 0xFFFC, key)
            result = 7 if got == M else got
            carry, zero = not free, result == 0
            leave = True
        elif op == 3:                                   # COGSTOP
            free = any(k.state == STOPPED for k in chip.cogs)
            result = d & 7
            carry, zero = not free, result == 0
            target = chip.cogs[result]
            if target is c:
                self._flags(R, wz, wc, carry, zero)
                chip.stop_cog(c, key, "COGSTOP of itself", seen=key - 4)
                raise Leave(None)
            if target.state != STOPPED:
                chip.stop_cog(target, key, f"stopped by cog {c.id}", by=c, seen=key - 4)
                leave = True
        elif op == 4:                                   # LOCKNEW
            got = chip.locknew()
            result = 7 if got == M else got
            carry, zero = got == M, result == 0
        elif op == 5:                                   # LOCKRET: C = no lock was free
            result = d & 7
            carry, zero = all(chip.lock_used), result == 0
            chip.lockret(result)
        else:                                           # LOCKSET, LOCKCLR
            result = d & 7
            carry, zero = chip.lockset(result, op == 6), result == 0
        if c.state != RUNNING or c.ram is not R or c.engine is not self:    # it restarted itself
            raise Leave(None)
        if zero is not None:
            self._flags(R, wz, wc, carry, zero)
        if wr:
            self._write_hub_result(R, c, dest, result, key, nxt)
        if leave:
            raise Leave(nxt)
        return nxt

    @staticmethod
    def _flags(R, wz, wc, carry, zero) -> None:
        F = R[FLAGS]
        if wz:
            F = (F & 2) | int(zero)
        if wc:
            F = (F & 1) | (int(carry) << 1)
        R[FLAGS] = F

    def _write_hub_result(self, R, c, dest: int, value: int, key: int, nxt: int) -> None:
        R[dest] = value
        if dest >= 0x1F4:
            self.chip.registers.write(c, dest, value, key)
            if self.chip._preempt:
                self.chip._end_preemption()
                raise Leave(nxt)
