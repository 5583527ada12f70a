"""Where each cog is: call stacks with parameters, locals and results by name.

A Spin cog's frames are found in hub RAM from its ``dbase`` (Propeller Manual
v1.2, "Memory Organization"; :mod:`spinemu.debuginfo`): the frame's result,
parameters and locals from ``dbase`` up, and below it the caller's return
address (``dbase - 2``), dbase (``- 4``), vbase (``- 6``) and pbase with the
frame flags (``- 8``).  The chain ends at the frame the boot loader or
``cognew`` made, whose return address is the ROM's ``$FFF9``.

A cog is described by a view chosen by what runs it (``Cog.engine``):
:class:`SpinCogView` for the Spin interpreter, :class:`PasmCogView` for a
PASM cog (its cog address, the instruction there, the DAT label it was loaded
from), :class:`OtherCogView` for anything else (the Python engine).
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Optional

__all__ = ["Frame", "SpinCogView", "PasmCogView", "OtherCogView", "cog_view", "signed", "short_path"]

_MAX_FRAMES = 64


def signed(v: int) -> int:
    """A long as Spin sees it (two's complement).

    >>> signed(0xFFFFFFFF), signed(5)
    (-1, 5)
    """
    return v - (1 << 32) if v & 0x80000000 else v


def short_path(path: Optional[str]) -> str:
    """``path`` relative to the working directory when it lies under it."""
    if not path:
        return "?"
    if os.path.isabs(path):
        rel = os.path.relpath(path, os.getcwd())
        if not rel.startswith(".."):
            return rel
    return path


@dataclass
class Frame:
    """One method activation of a Spin cog.

    Attributes:
        method: the :class:`~spinemu.debuginfo.MethodDebug` (``None`` if unknown).
        pc: the hub address it is at (for a caller: its call instruction).
        dbase: its frame base.
        instance: the object instance it runs in (:class:`~spinemu.debuginfo.Instance`).
        path, line, col: the Spin place of ``pc``.
        values: ``(FrameSlot, value)`` for the result, each parameter and each
            local long (arrays: their first long; ``array_values`` has all).
    """

    method: object
    pc: int
    dbase: int
    instance: object = None
    path: Optional[str] = None
    line: Optional[int] = None
    col: Optional[int] = None
    values: list = field(default_factory=list)
    array_values: dict = field(default_factory=dict)

    @property
    def name(self) -> str:
        return self.method.name if self.method is not None else f"${self.pc:04X}"

    def place(self) -> str:
        """``file:line`` (or the hub address)."""
        if self.path is None:
            return f"${self.pc:04X}"
        return f"{short_path(self.path)}:{self.line}"

    def value(self, name: str) -> Optional[int]:
        low = name.lower()
        for slot, v in self.values:
            if slot.name.lower() == low:
                return v
        return None

    def signature(self) -> str:
        """``setMode(m=3)``: the method with its parameters' values."""
        params = ", ".join(f"{s.name}={signed(v)}" for s, v in self.values if s.kind == "param")
        return f"{self.name}({params})"

    def describe(self) -> str:
        """``setMode(m=3) at stepper.spin:54  result=0  c=12``."""
        rest = [f"{s.name}={signed(v)}" for s, v in self.values if s.kind != "param"]
        return f"{self.signature()} at {self.place()}" + ("  " + "  ".join(rest) if rest else "")


class SpinCogView:
    """A cog running the Spin interpreter, read from the chip (nothing is changed)."""

    kind = "spin"

    def __init__(self, chip, cog, info):
        self.chip, self.cog, self.info = chip, cog, info

    @property
    def id(self) -> int:
        return self.cog.id

    @property
    def state(self) -> str:
        return self.cog.state

    def frames(self) -> list:
        """The call stack, innermost first."""
        c, info = self.cog, self.info
        W = self.chip.mem_words
        peek = self.chip.peek
        out = []
        pc, dbase, pbase, vbase = c.pc, c.dbase, c.pbase, c.vbase
        for _ in range(_MAX_FRAMES):
            method = info.method_at(pc) if info is not None else None
            frame = Frame(method, pc, dbase)
            if info is not None:
                frame.instance = info.instance(pbase, vbase)
                where = info.position(pc)
                back = pc
                while where is None and method is not None and back > method.start:
                    back -= 1                       # the method's closing RETURN: its last line
                    where = info.position(back)
                if where is not None:
                    frame.path, frame.line, frame.col = where
            if method is not None:
                for slot in method.slots:
                    a = (dbase + slot.offset) & 0xFFFF
                    frame.values.append((slot, peek(a)))     # (with a write-back still on its way)
                    if slot.count > 1:
                        frame.array_values[slot.name] = [peek((a + 4 * k) & 0xFFFF) for k in range(slot.count)]
            out.append(frame)
            if not 8 <= dbase < 0x8000:
                break
            ret = W[((dbase - 2) & 0xFFFF) >> 1]
            if ret >= 0x8000:                       # the boot or cognew frame: the ROM's $FFF9
                break
            pc = (ret - 1) & 0xFFFF                 # inside the call instruction
            vbase = W[((dbase - 6) & 0xFFFF) >> 1]
            pbase = W[((dbase - 8) & 0xFFFF) >> 1] & 0xFFFC
            dbase = W[((dbase - 4) & 0xFFFF) >> 1]
        return out

    def place(self) -> str:
        """Where the cog is: ``file:line in method`` (or its address)."""
        frames = self.frames()
        f = frames[0]
        return f"{f.place()} in {f.name}"

    def describe(self) -> str:
        return f"cog {self.id} ({self.state}): " + self.place()


class OtherCogView:
    """A cog not running Spin bytecode (PASM, or another engine): what the chip knows of it."""

    kind = "other"

    def __init__(self, chip, cog, info):
        self.chip, self.cog, self.info = chip, cog, info

    @property
    def id(self) -> int:
        return self.cog.id

    @property
    def state(self) -> str:
        return self.cog.state

    def frames(self) -> list:
        return []

    def place(self) -> str:
        engine = self.cog.engine if isinstance(self.cog.engine, str) else type(self.cog.engine).__name__
        return f"{engine} cog, PAR ${self.cog.par:04X}"

    def describe(self) -> str:
        return f"cog {self.id} ({self.state}): " + self.place()


class PasmCogView(OtherCogView):
    """A cog running PASM: where it is in its cog RAM and what it runs there."""

    kind = "pasm"

    def place(self) -> str:
        c = self.cog
        pc = c.pc & 511
        text = f"PASM at cog ${pc:03X}"
        try:
            from ..pasm import disassemble
            text += ": " + " ".join(disassemble(c.ram[pc] & 0xFFFFFFFF).split())
        except Exception:  # a register the view cannot read: the address is enough
            pass
        hub = (c.code_addr + 4 * pc) & 0xFFFF if c.code_addr is not None else None
        if hub is not None and pc < 496:
            found = self.info.variable_at(hub) if self.info is not None else None
            if found is not None:
                inst, var = found
                off = hub - var.addr
                text += f" ({var.name}{f'+{off}' if off else ''} in {short_path(inst.obj.path)})"
            else:
                text += f" (loaded from hub ${c.code_addr:04X})"
        return text + f", PAR ${c.par:04X}"


def cog_view(chip, cog, info=None):
    """The view of ``cog`` that fits what runs it (``None`` for a stopped cog)."""
    if cog.state == "stopped":
        return None
    if cog.engine == "spin":
        return SpinCogView(chip, cog, info)
    if getattr(cog, "ram", None) is not None and getattr(cog, "code_addr", None) is not None:
        return PasmCogView(chip, cog, info)
    return OtherCogView(chip, cog, info)
