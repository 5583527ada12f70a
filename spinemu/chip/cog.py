"""One cog: the registers a Spin interpreter cog keeps, and its place in time.

A cog running Spin holds the interpreter's state registers (Propeller Manual
v1.2, "Spin interpreter"; register numbers as the ROM interpreter uses them and
as Spin's ``REG`` bytecodes reach them)::

    $1E9  cog id          $1EA  dcall: newest unfinished call frame (+6)
    $1EB  pbase           $1EC  vbase           $1ED  dbase
    $1EE  pcurr           $1EF  dcurr (stack pointer)

plus the special registers $1F0-$1FF (PAR, CNT, INA, INB, OUTA, OUTB, DIRA,
DIRB, CTRA, CTRB, FRQA, FRQB, PHSA, PHSB, VCFG, VSCL).

``t`` is the cycle at which the cog starts its next bytecode.  ``hub_phase``
is the value ``t mod 16`` takes when one of its hub instructions completes.

The class is engine-neutral apart from the Spin fields: ``engine`` is what
runs the cog (``"spin"`` for the bytecode interpreter, or an engine object
with ``run``/``key``: the PASM engine of :mod:`.pasm_cog`, the Python engine
of :mod:`spinemu.translate`).  A PASM cog keeps its cog RAM in ``ram``, its
program counter in ``pc``, and the long it fetched next in ``ir``.
"""
from __future__ import annotations

__all__ = ["Cog", "STOPPED", "RUNNING", "PIN_WAIT", "PARKED"]

STOPPED, RUNNING, PIN_WAIT = "stopped", "running", "pin wait"
#: running a learned busy loop, taken out of the schedule (see fastforward.py)
PARKED = "parked"


class Cog:
    """State of one of the eight cogs."""

    __slots__ = (
        "id", "state", "engine", "t", "hub_phase", "started_at",
        # Spin interpreter registers
        "pc", "pc_hi", "sp", "dbase", "pbase", "pbase_hi", "vbase", "dcall", "scratch",
        # special registers
        "par", "outa", "dira", "outb", "dirb", "ctra", "ctrb", "frqa", "frqb", "phsa", "phsb",
        "vcfg", "vscl",
        # waiting on pins: (mask, state, equal, remaining cycles after the match)
        "pin_wait",
        # PASM: cog RAM (+ flags and links, see pasm_cog.py), the prefetched long,
        # the cycle of the next shared access, the hub address it was loaded from
        "ram", "ir", "key", "code_addr",
        # statistics
        "bytecodes", "instructions",
        # fast-forward: the learned busy loop, and when to try learning next
        "busy", "learn_mark", "learn_after", "park_t0",
        # running ahead (ahead.py): the cog's private stack window [wlo, whi) in bytes,
        # and the checkpoint of its open private stretch (None while it is not ahead)
        "wlo", "whi", "cp", "holes", "pfail", "pfail_n",
        # runtime checks: where the stack array cognew gave the cog ends (else the end of hub RAM)
        "stack_end", "stack_info",
        # its last changes of DIRA/OUTA: (cycle other cogs see it from, dira, outa, running), oldest first
        "pin_hist",
    )

    def __init__(self, cog_id: int):
        self.id = cog_id
        self.state = STOPPED
        self.engine = None
        self.t = 0
        self.hub_phase = 8
        self.started_at = 0
        self.bytecodes = self.instructions = 0
        self.ram = self.ir = None
        self.key = self.code_addr = 0
        self.busy = None
        self.learn_mark = 0
        self.learn_after = 0
        self.park_t0 = 0
        self.wlo = self.whi = 0
        self.cp = None
        self.holes = []                 # longs inside [wlo, whi) that left the window
        self.pfail = -1                 # where its last private phase did nothing, and how often to skip it
        self.pfail_n = 0
        self.stack_end = 0x8000
        self.stack_info = None
        self.pin_hist = []
        self.reset_registers()

    def reset_registers(self) -> None:
        """The state of a cog just (re)started: every register zero."""
        self.pc = self.pc_hi = self.sp = self.dbase = self.pbase = self.pbase_hi = 0
        self.vbase = self.dcall = 0
        self.scratch = [0] * 16        # $1E0-$1EF as REG bytecodes see them
        self.par = 0
        self.outa = self.dira = self.outb = self.dirb = 0
        self.ctra = self.ctrb = self.frqa = self.frqb = self.phsa = self.phsb = 0
        self.vcfg = self.vscl = 0
        self.pin_wait = None

    @property
    def running(self) -> bool:
        return self.state in (RUNNING, PIN_WAIT, PARKED)

    def __repr__(self) -> str:  # pragma: no cover - debugging aid
        return f"<Cog {self.id} {self.state} t={self.t} pc=${self.pc:04X} sp=${self.sp:04X}>"
