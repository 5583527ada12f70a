"""The cog's half of :mod:`spinemu.translate.spin`: registers, waits, cog control, locks, strings.

Everything here acts on the cog running the code (``RT.cog``) and goes
through the chip: register reads and writes at the cycle the bytecode would
do them (the statement has paid for the bytecodes before), waits and cog
starts through :class:`spinemu.translate.runtime.Engine`, string and block
loops pay their counts.  Translated modules reach these names as ``spin.X``
(and ``cog``).

Hot paths: :data:`cog`'s register properties.
"""
from __future__ import annotations

from ..chip.spin import _reverse_bits as _reverse
from .spin import M32, RT, byte, flag, long, word, wrap

__all__ = [
    "Register", "cog", "cogid", "clkfreq", "clkmode", "waitcnt", "waitpeq", "waitpne", "waitvid", "cognew",
    "coginit", "cogstop", "reboot", "clkset", "locknew", "lockret", "lockset", "lockclr", "strsize",
    "strcomp", "string", "bytefill", "wordfill", "longfill", "bytemove", "wordmove", "longmove",
]


# ----------------------------------------------------------------------------- cog registers
_REG = {"PAR": 0x1F0, "CNT": 0x1F1, "INA": 0x1F2, "INB": 0x1F3, "OUTA": 0x1F4, "OUTB": 0x1F5,
        "DIRA": 0x1F6, "DIRB": 0x1F7, "CTRA": 0x1F8, "CTRB": 0x1F9, "FRQA": 0x1FA, "FRQB": 0x1FB,
        "PHSA": 0x1FC, "PHSB": 0x1FD, "VCFG": 0x1FE, "VSCL": 0x1FF}


#: registers whose value depends on what the other cogs have done up to the read (INA, PHSA, PHSB)
_PIN_REGS = frozenset({0x1F2, 0x1FC, 0x1FD})


def _fetched() -> int:
    """The cycle at which the current cog's next bytecode has been fetched (on its hub window)."""
    c = RT.cog
    t = c.t + 12
    return t + ((c.hub_phase - t) & 15)


def _read(reg: int, op: int) -> int:
    return _read_at(reg, RT.T.reg_read_at[(op, 0)])


def _read_at(reg: int, read_at: int) -> int:
    """Read ``reg`` ``read_at`` cycles after the reading bytecode's fetch; the read pays the statement's rest."""
    c = RT.cog
    tf = _fetched()
    at = tf + read_at
    if at >= RT.limit and reg in _PIN_REGS:     # INA/PHS depend on other cogs' pins: let them run up to the read
        RT.keys[c.id] = at
        RT.pause()
    value = RT.chip.registers.read(c, reg, at)
    if RT.pending is not None:          # the statement's bytecodes from this read on
        c.t = tf + RT.pending
        RT.pending = None
    return value


def _write(reg: int, value: int) -> None:
    # the statement already paid for the writing bytecode: its last instruction writes
    c = RT.cog
    chip = RT.chip
    chip.registers.write(c, reg, value & M32, c.t - 4, spin=True)
    if chip._preempt:                   # the write woke a WAITPEQ/WAITPNE cog: let the scheduler see it
        chip._end_preemption()
        RT.limit = -1


def _field(key):
    """``(low bit, width, reversed)`` of a register index: a bit ``[n]`` or a range ``[hi:lo]``."""
    if isinstance(key, slice):
        a, b = key.start & 31, key.stop & 31
        rev = a < b
        lo, hi = (a, b) if rev else (b, a)
        return lo, hi - lo + 1, rev
    return key & 31, 1, False


class Register(int):
    """A register's value (an int) that also writes bit fields back: ``cog.OUTA[7:4] = %1001``."""

    __slots__ = ()
    reg = 0

    def __getitem__(self, key) -> int:
        lo, width, rev = _field(key)
        v = (_read(self.reg, 0x3E if isinstance(key, slice) else 0x3D) >> lo) & ((1 << width) - 1)
        return wrap(_reverse(v, width) if rev else v)

    def __setitem__(self, key, value: int) -> None:
        lo, width, rev = _field(key)
        field = (1 << width) - 1
        value &= field
        if rev:
            value = _reverse(value, width)
        old = RT.chip.registers.read(RT.cog, self.reg, RT.cog.t)
        _write(self.reg, (old & ~(field << lo)) | (value << lo))


def _register_class(name: str, reg: int):
    return type(name, (Register,), {"__slots__": (), "reg": reg})


_REG_CLASSES = {name: _register_class(name, reg) for name, reg in _REG.items()}


def _reg_property(name: str):
    reg, cls = _REG[name], _REG_CLASSES[name]

    def get(self):
        return cls(wrap(_read(reg, 0x3F)))

    def set(self, value):
        _write(reg, value)

    return property(get, set, doc=f"{name} of the cog running this code")


class _Cog:
    """The cog that runs the current code: its registers (``OUTA``, ``DIRA``, ``INA``, ``CNT``, ...).

    ``cog.OUTA[n]`` is bit ``n``, ``cog.OUTA[hi:lo]`` the bits ``hi..lo`` (Spin's
    ``outa[hi..lo]``; ``[lo:hi]`` reverses them, as in Spin).
    """

    __slots__ = ()
    for _name in _REG:
        locals()[_name] = _reg_property(_name)
    del _name

    @property
    def spr(self):
        """Spin's ``spr[i]``: special register ``$1F0 + i``."""
        return _Spr()

    def __repr__(self) -> str:
        return "<the cog running this code>"


class _Spr:
    __slots__ = ()

    def __getitem__(self, i: int) -> int:
        return wrap(_read_at(0x1F0 + (i & 15), RT.T.spr_read_at))

    def __setitem__(self, i: int, value: int) -> None:
        _write(0x1F0 + (i & 15), value)


cog = _Cog()


# ----------------------------------------------------------------------------- cog control, waits
def cogid() -> int:
    """The number of the cog running this code."""
    return RT.cog.id


def clkfreq() -> int:
    """The system clock frequency in Hz (``long[0]``)."""
    return RT.Ls[0]


def clkmode() -> int:
    """The clock mode byte (``byte[4]``)."""
    return RT.mem[4]


def waitcnt(target: int) -> None:
    """Wait until the system counter equals ``target`` (a full 2**32-cycle turn if it just passed)."""
    RT.engine.waitcnt(target)


def waitpeq(state: int, mask: int, port: int = 0) -> None:
    """Wait until ``INA & mask == state``."""
    RT.engine.wait_pins(state, mask, True)


def waitvid(colors: int, pixels: int) -> None:
    """Wait for the cog's video generator to take the next frame (VSCL sets its length)."""
    RT.engine.waitvid(colors, pixels)


def waitpne(state: int, mask: int, port: int = 0) -> None:
    """Wait until ``INA & mask != state``."""
    RT.engine.wait_pins(state, mask, False)


def cognew(method, *args, stack: int) -> int:
    """Start ``method(*args)`` in a free cog with its stack at hub address ``stack``; the cog's id or -1.

    ``method`` may also be a hub address (PASM code, Spin's ``cognew(@entry, par)``):
    then ``args`` holds the PAR value.
    """
    return RT.engine.coginit(8, method, args, stack)


def coginit(cog_id: int, method, *args, stack: int) -> int:
    """Start ``method(*args)`` in cog ``cog_id`` (restarting it if it runs)."""
    return RT.engine.coginit(cog_id & 7, method, args, stack)


def cogstop(cog_id: int) -> None:
    """Stop cog ``cog_id``."""
    RT.engine.cogstop(cog_id & 7)


def reboot() -> None:
    """Restart the chip (Spin compiles it as ``clkset($80, 0)``)."""
    clkset(0x80, 0)


def clkset(mode: int, freq: int) -> None:
    """Set the clock mode and frequency (stored in hub RAM, as Spin does); mode bit 7 reboots."""
    RT.L[0] = freq & M32
    RT.mem[4] = mode & 0xFF
    if mode & 0x80:
        RT.engine.reboot()
    RT.chip.set_clock(mode & 0xFF, freq & M32)


def locknew() -> int:
    """Check out a free lock: its id, or -1."""
    return wrap(RT.chip.locknew())


def lockret(lock: int) -> None:
    RT.chip.lockret(lock & 7)


def lockset(lock: int) -> int:
    """Set lock ``lock``; TRUE if it was already set."""
    return flag(RT.chip.lockset(lock & 7, True))


def lockclr(lock: int) -> int:
    """Clear lock ``lock``; TRUE if it was set."""
    return flag(RT.chip.lockset(lock & 7, False))


# ----------------------------------------------------------------------------- strings and blocks
def strsize(addr: int) -> int:
    """Length of the zero-terminated string at ``addr``."""
    mem = RT.mem
    n = 0
    while mem[(addr + n) & 0xFFFF]:
        n += 1
    if RT.T is not None:
        RT.cog.t += RT.T.strsize(n) - RT.T.strsize(0)
    return n


def strcomp(a: int, b: int) -> int:
    """TRUE if the zero-terminated strings at ``a`` and ``b`` are equal."""
    mem = RT.mem
    n = 0
    while True:
        x, y = mem[(a + n) & 0xFFFF], mem[(b + n) & 0xFFFF]
        n += 1
        if x != y or x == 0:
            break
    if RT.T is not None:
        RT.cog.t += RT.T.strcomp(n, x == y) - RT.T.strcomp(1, False)
    return flag(x == y)


def string(address: int) -> int:
    """Spin's ``string("...")``: the address of the string kept with the method's code."""
    return address


def _fill(size: int, addr: int, value: int, count: int) -> None:
    mem = (byte, word, long)[size]
    step = 1 << size
    for i in range(count & M32 if count & M32 < 0x10000 else 0x10000):
        mem[addr + i * step] = value
    if RT.T is not None:
        RT.cog.t += RT.T.fill(size, count & M32) - RT.T.fill(size, 0)


def _move(size: int, dst: int, src: int, count: int) -> None:
    mem = (byte, word, long)[size]
    step = 1 << size
    n = count & M32 if count & M32 < 0x10000 else 0x10000
    align = ~(step - 1)
    order = range(n) if (dst & 0xFFFF & align) <= (src & 0xFFFF & align) else range(n - 1, -1, -1)
    for i in order:
        mem[dst + i * step] = mem[src + i * step]
    if RT.T is not None:
        RT.cog.t += RT.T.move(size, count & M32) - RT.T.move(size, 0)


def bytefill(addr: int, value: int, count: int) -> None:
    """Set ``count`` bytes from ``addr`` on to ``value``."""
    _fill(0, addr, value, count)


def wordfill(addr: int, value: int, count: int) -> None:
    _fill(1, addr, value, count)


def longfill(addr: int, value: int, count: int) -> None:
    _fill(2, addr, value, count)


def bytemove(dst: int, src: int, count: int) -> None:
    """Copy ``count`` bytes from ``src`` to ``dst``."""
    _move(0, dst, src, count)


def wordmove(dst: int, src: int, count: int) -> None:
    _move(1, dst, src, count)


def longmove(dst: int, src: int, count: int) -> None:
    _move(2, dst, src, count)
