"""The debugger on PASM cogs: stepping by instruction, breakpoints on cog addresses and DAT labels, registers.

A PASM cog runs ahead of the others between shared accesses
(:mod:`spinemu.chip.pasm_cog`), so the debugger cannot look at it between
two instructions from the outside.  While something needs that (a PASM
breakpoint, a step of a PASM cog, a watchpoint or a pin breakpoint, which a
PASM cog's write may hit), the debugger traces every PASM cog
(``Chip.trace_cog``): the engine then runs them one instruction at a time
(``PasmEngine.run_traced``), at the same cycles, and calls
:meth:`PasmDebugging.pasm_before` before each instruction (breakpoints, the
end of a ``next`` over a call) and :meth:`PasmDebugging.pasm_after` after it
(steps, watchpoints, pin changes, a cog that stopped).  Either raises
:class:`~spinemu.chip.control.Halted` to stop the whole chip there.  With
nothing to look for, PASM cogs run at full speed even in a session.

Names come from the compiler: a DAT label names cog address ``k`` of a cog
loaded from hub address ``code`` when the label lies at ``code + 4 * k``
(as in ``spinemu run --trace-cog``; ``res`` labels after it share its hub
address and name the cog addresses that follow), and the source line of an
instruction is that of the hub long it was loaded from.
"""
from __future__ import annotations

from typing import Optional

from .. import pasm as isa
from ..chip.cog import STOPPED
from .frames import short_path, signed

__all__ = ["PasmDebugging", "PasmProbe", "is_pasm", "is_code_line"]

_LOAD = 496         # longs a PASM cog loads from hub RAM ($000-$1EF)
_JMPRET = 0x17


def is_pasm(c) -> bool:
    """Whether cog ``c`` runs PASM (an engine object with cog RAM)."""
    return c.engine.__class__ is not str and getattr(c, "ram", None) is not None


def is_code_line(text: str) -> bool:
    """Whether a DAT source line holds an instruction (not ``long``/``res``/...).

    >>> is_code_line("loop    djnz    n, #loop"), is_code_line("n       long    5"), is_code_line("  if_z jmp #x")
    (True, False, True)
    """
    words = text.split("'", 1)[0].split()
    if words and not text[:1].isspace():
        words = words[1:]                       # the label
    if not words:
        return False
    w = words[0].lower()
    return w in isa.INSTRUCTIONS or w in isa.CONDITIONS


class PasmProbe:
    """The tracer the debugger gives the PASM engine for every cog (``Chip.trace_cog``)."""

    def __init__(self, dbg: "PasmDebugging"):
        self.dbg = dbg

    def __call__(self, step) -> None:
        self.dbg.pasm_after(step)

    def before(self, c) -> None:
        self.dbg.pasm_before(c)


class PasmDebugging:
    """The PASM half of :class:`~spinemu.debugger.session.Debugger` (a mixin; see the module docstring)."""

    def _init_pasm(self) -> None:
        self._dat = self.program.dat_symbols()      # (hub address, cog address, label)
        self._symbols: dict = {}                    # code address -> {cog address: label}
        self._pasm_hubs: dict = {}                  # hub address -> [Breakpoint]
        self._pasm_at: dict = {}                    # (cog, cog address) -> [Breakpoint]
        self._pasm_skip: dict = {}                  # cog -> (pc, t): resume there without stopping again
        self._pasm_probe = PasmProbe(self)
        self._pasm_traced = False
        self._pasm_steps: list = []                 # the stepped cog's instructions in this step

    # ------------------------------------------------------------------ names
    def pasm_symbols(self, cog: int) -> dict:
        """Cog address -> DAT label for the code PASM cog ``cog`` was loaded from."""
        code = self.chip.cogs[cog].code_addr
        table = self._symbols.get(code)
        if table is None:
            by_hub: dict = {}
            for hub, k, name in self._dat:
                by_hub.setdefault(hub, []).append((k, name))
            table = self._symbols[code] = {}
            for hub, labels in by_hub.items():
                # a label at code + 4k names cog address k; RES labels after it share its hub address
                if hub >= code and hub - code == 4 * min(k for k, _ in labels):
                    table.update((k, name) for k, name in labels if k < 0x1F0)
        return table

    def _pasm_register(self, c, name: str) -> Optional[int]:
        low = name.lower()
        for k, label in self.pasm_symbols(c.id).items():
            if label.lower() == low:
                return k
        return None

    @staticmethod
    def _pasm_hub(c, pc: int) -> Optional[int]:
        """The hub address cog address ``pc`` of PASM cog ``c`` was loaded from (``None`` past $1EF)."""
        return (c.code_addr + 4 * pc) & 0xFFFF if pc < _LOAD else None

    def pasm_where(self, c, pc: Optional[int] = None) -> str:
        """``$003 (loop, hub.spin:20): rdlong x, p``: a cog address, its label and line, its instruction."""
        pc = c.pc & 511 if pc is None else pc
        symbols = self.pasm_symbols(c.id)
        parts = [symbols[pc]] if pc in symbols else []
        hub = self._pasm_hub(c, pc)
        pos = self.info.position(hub) if hub is not None else None
        if pos is not None:
            parts.append(f"{short_path(pos[0])}:{pos[1]}")
        word = c.ir if pc == c.pc and c.ir is not None else c.ram[pc]
        text = " ".join(isa.disassemble(word & 0xFFFFFFFF, None, symbols,
                                        ret_as_jmp=bool(symbols) and 0 in symbols).split())
        return f"${pc:03X}" + (f" ({', '.join(parts)})" if parts else "") + f": {text}"

    def pasm_line(self, cog: Optional[int] = None) -> Optional[tuple]:
        """``(path, line)`` of the DAT line the selected PASM cog's next instruction was loaded from."""
        c = self.chip.cogs[self.selected if cog is None else cog]
        if not is_pasm(c) or c.state == STOPPED:
            return None
        hub = self._pasm_hub(c, c.pc)
        pos = self.info.position(hub) if hub is not None else None
        return pos[:2] if pos else None

    def registers(self, cog: Optional[int] = None) -> list:
        """``(cog address, label, value)`` of the registers a PASM cog's DAT labels name (data, not code)."""
        n = self.selected if cog is None else cog
        c = self.chip.cogs[n]
        if not is_pasm(c) or c.state == STOPPED:
            raise self._error(f"cog {n} does not run PASM")
        out = []
        for k, label in sorted(self.pasm_symbols(n).items()):
            hub = self._pasm_hub(c, k)
            pos = self.info.position(hub) if hub is not None else None
            line = self.info.source_line(pos[0], pos[1]) if pos is not None else None
            if line is not None and is_code_line(line):
                continue
            out.append((k, label, c.ram[k]))
        return out

    # ------------------------------------------------------------------ breakpoints
    def break_pasm(self, cog: int, where, condition: Optional[str] = None, temporary: bool = False):
        """Stop PASM cog ``cog`` before it runs the instruction at cog address ``where`` (an int or a DAT label)."""
        from .expr import Expression

        if not 0 <= cog < 8:
            raise self._error(f"there is no cog {cog} (cogs are 0..7)")
        if isinstance(where, str):
            c = self.chip.cogs[cog]
            k = self._pasm_register(c, where) if is_pasm(c) else None
            if k is None:
                raise self._error(f"cog {cog} runs no PASM code with a label '{where}' (give its cog address, @$01A)")
            text = f"cog {cog} @{where} (${k:03X})"
        else:
            k = where
            if not 0 <= k < 512:
                raise self._error(f"cog address ${k:X} is outside the cog ($000-$1FF)")
            text = f"cog {cog} @${k:03X}"
        cond = Expression(condition) if condition else None
        return self._add(self._breakpoint("pasm", text, cog_addr=(cog, k), condition=cond, temporary=temporary))

    def _add_pasm(self, bp) -> None:
        if bp.cog_addr is not None:
            self._pasm_at.setdefault(bp.cog_addr, []).append(bp)
        for a in bp.hubs:
            self._pasm_hubs.setdefault(a, []).append(bp)

    def _delete_pasm(self, bp) -> None:
        for table, keys in ((self._pasm_at, [bp.cog_addr] if bp.cog_addr is not None else []),
                            (self._pasm_hubs, bp.hubs)):
            for key in keys:
                table[key].remove(bp)
                if not table[key]:
                    del table[key]

    def _pasm_location(self, addrs: list):
        """Split a line's hub addresses into Spin bytecode and DAT (PASM instructions)."""
        spin = [a for a in addrs if self.info.method_at(a) is not None]
        return spin, [a for a in addrs if a not in spin]

    def _pasm_label(self, name: str):
        """The hub address of a DAT label (``label`` or ``obj.label``) and how to show it, or ``None``."""
        found = self.info.find_variable(name) or self._unique_variable(name)
        if found is None or found[1].section != "DAT":
            return None
        inst, v = found
        pos = self.info.position(v.addr)
        place = f"{short_path(pos[0])}:{pos[1]}" if pos else f"hub ${v.addr:04X}"
        return v.addr, f"{name} ({place})"

    # ------------------------------------------------------------------ the engine's hooks
    def _sync_pasm(self) -> None:
        """Trace the PASM cogs (one instruction at a time) while something needs to see their instructions."""
        step = self._step
        want = bool(self._pasm_hubs or self._pasm_at or self._watch_bps or self._pin_bps
                    or (step is not None and step.kind.startswith("pasm")))
        if want != self._pasm_traced:
            for n in range(8):
                self.chip.trace_cog(n, self._pasm_probe if want else None)
            self._pasm_traced = want

    def pasm_before(self, c) -> None:
        """Before PASM cog ``c`` runs an instruction: breakpoints, the end of a ``next``."""
        if self._interrupt:
            self._interrupt = False
            raise self._pasm_halt("interrupted", c, f"interrupted in cog {c.id}")
        pc, t = c.pc, c.t
        if self._pasm_skip.get(c.id) == (pc, t):
            return
        step = self._step
        if step is not None and step.cog == c.id and step.kind == "pasm-next" and pc == step.target:
            raise self._pasm_halt("step", c, f"cog {c.id} at {self.pasm_where(c)}")
        hub = self._pasm_hub(c, pc)
        bps = self._pasm_at.get((c.id, pc), []) + self._pasm_hubs.get(hub, [])
        for bp in bps:
            if bp.condition is None or self._holds(bp.condition, c):
                bp.hits += 1
                if bp.temporary:
                    self.delete(bp.number)
                raise self._pasm_halt("breakpoint", c, f"breakpoint {bp.describe()}: cog {c.id} at "
                                      f"{self.pasm_where(c)}", bp)

    def pasm_after(self, step) -> None:
        """After PASM cog ``step.cog`` ran an instruction: steps, watchpoints, pin changes, a stop."""
        c = self.chip.cogs[step.cog]
        self._pasm_skip.pop(c.id, None)
        if self._pending is not None:
            stop, self._pending = self._pending, None
            if stop.reason == "watchpoint":
                stop.detail += f" -> {self._read_var(stop.breakpoint.var[1])}"
            if c.state != STOPPED:
                self.chip.now = c.t
                self._pasm_skip[c.id] = (c.pc, c.t)
            raise self._halt(stop)
        s = self._step
        if s is None or s.cog != c.id:
            return
        self._pasm_steps.append(step)
        if c.state == STOPPED:
            raise self._pasm_halt("step", c, self._pasm_trace(c) + f"cog {c.id} stopped ({self._stop_reason(c.id)})")
        if s.kind == "pasm-stepi":
            s.count -= 1
            if s.count <= 0:
                raise self._pasm_halt("step", c, self._pasm_trace(c) + f"cog {c.id} at {self.pasm_where(c)}")

    def _pasm_trace(self, c) -> str:
        symbols = self.pasm_symbols(c.id)
        return "".join(s.text(symbols) + "\n" for s in self._pasm_steps)

    def _pasm_halt(self, reason: str, c, detail: str, bp=None):
        from .session import Stop

        hub = None
        if c.state != STOPPED:                  # (a cog that stopped itself set the chip's time)
            self.chip.now = c.t
            self._pasm_skip[c.id] = (c.pc, c.t)     # going on from here does not stop here again
            hub = self._pasm_hub(c, c.pc)
        return self._halt(Stop(reason, c.id, self.chip.now, detail, bp, hub if hub is not None else -1,
                               steps=list(self._pasm_steps)))

    def _pasm_writer(self, c) -> tuple:
        """How a watchpoint or a pin stop names the PASM instruction that did it, and its hub address."""
        hub = self._pasm_hub(c, c.pc)
        return self.pasm_where(c, c.pc), hub if hub is not None else -1

    # ------------------------------------------------------------------ stepping
    def _start_pasm_step(self, kind: str, n: int, count: int) -> None:
        from .session import _Step

        c = self.chip.cogs[n]
        if kind == "finish":
            raise self._error(f"cog {n} runs PASM: it has no method to finish (stepi N, next over a call, "
                              f"until LABEL)")
        word = c.ir if c.ir is not None else c.ram[c.pc]
        if kind == "next" and word >> 26 == _JMPRET and word & isa.R_BIT and (word >> 18) & 15:
            self._step = _Step("pasm-next", n, target=(c.pc + 1) & 511)      # over the call: to the next long
        else:
            self._step = _Step("pasm-stepi", n, count=count if kind == "stepi" else 1)
        self._pasm_steps = []
        self.selected = n

    def _set_pasm_register(self, c, name: str, value: int, index: Optional[int]) -> bool:
        k = self._pasm_register(c, name)
        if k is None:
            return False
        k += index or 0
        if not 0 <= k < 0x1F0:
            raise self._error(f"{name}[{index}] is outside the cog's RAM ($000-$1EF)")
        c.ram[k] = value & 0xFFFFFFFF
        if k == c.pc:
            c.ir = None                 # the poked long is the one that runs next
        return True

    def _pasm_value(self, c, name: str, index: Optional[int]) -> Optional[int]:
        k = self._pasm_register(c, name)
        if k is None:
            return None
        return signed(c.ram[(k + (index or 0)) & 511])
