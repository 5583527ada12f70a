"""The library that translated Spin programs import: ``from spinemu.translate import spin``.

Everything a translated module calls lives here, so that the generated code
reads as ordinary Python:

* values: Spin longs are kept as signed Python ints (-2**31 .. 2**31-1);
  :func:`wrap` brings a result back into that range after ``+ - * <<``;
  :data:`TRUE` is -1, as in Spin; :func:`div`, :func:`mod`, :func:`shr`,
  :func:`rol`, ... are Spin's operators that Python spells differently
  (Propeller Manual v1.2, "Operators");
* memory: :class:`Object` (a Spin object instance) and the descriptors
  :class:`Long`, :class:`Word`, :class:`Byte` put VAR and DAT variables in hub
  RAM at the addresses the compiler gave them; :data:`long`, :data:`word`,
  :data:`byte` are Spin's ``long[addr]``, ``word[addr]``, ``byte[addr]``;
* the cog: :data:`cog` is the cog running the code (``cog.OUTA[7:4] = 5``,
  ``cog.CNT``); :func:`waitcnt`, :func:`cognew`, :func:`cogstop`, ... hand
  control to the chip's scheduler (spinemu.translate.runtime).

Time: the runtime charges each statement the cycles of its bytecode
(docs/translate.md); the helpers here add what depends on values (a
division's loop, a wait) and put pin changes at the cycle the bytecode
would.  Hot paths: the descriptors and :data:`cog`'s registers.
"""
from __future__ import annotations

from ..chip import mathops as _m
from ..chip.spin import random_forward as _rnd_fwd, random_reverse as _rnd_rev

__all__ = [
    "TRUE", "FALSE", "POSX", "NEGX", "wrap", "u32", "flag", "div", "mod", "shr", "rol", "ror", "rev",
    "mul_high", "sqrt", "encode", "decode", "sign_extend_byte", "sign_extend_word",
    "random_forward", "random_reverse", "within", "lookup", "lookupz", "lookdown", "lookdownz",
    "Object", "Long", "Word", "Byte", "Child", "long", "word", "byte", "cog", "Abort", "trap",
    "cognew", "coginit", "cogstop", "cogid", "waitcnt", "waitpeq", "waitpne", "clkfreq", "clkmode",
    "clkset", "locknew", "lockret", "lockset", "lockclr", "strsize", "strcomp", "bytefill",
    "wordfill", "longfill", "bytemove", "wordmove", "longmove", "string", "reboot", "repeat_step",
]

M32 = 0xFFFFFFFF
TRUE, FALSE = -1, 0
POSX, NEGX = 0x7FFFFFFF, -0x80000000


class _State:
    """What the running chip shares with this module (set by spinemu.translate.runtime)."""

    __slots__ = ("cog", "limit", "final", "engine", "chip", "T", "mem", "L", "Ls", "W", "pause", "pending", "keys",
                 "div_extra")

    def __init__(self):
        self.cog = self.engine = self.chip = self.T = self.pause = self.pending = self.div_extra = None
        self.keys = [None] * 8
        self.limit = 0
        self.final = 1 << 62
        self.mem = bytearray(0x10000)
        self._views()

    def _views(self):
        v = memoryview(self.mem)
        self.L, self.Ls, self.W = v.cast("I"), v.cast("i"), v.cast("H")

    def attach(self, mem: bytearray) -> None:
        self.mem = mem
        self._views()


RT = _State()


# ----------------------------------------------------------------------------- values
def wrap(v: int) -> int:
    """``v`` as a Spin long: the low 32 bits, signed.

    >>> wrap(0x7FFFFFFF + 1), wrap(-1), wrap(2**32 + 5)
    (-2147483648, -1, 5)
    """
    return ((v + 0x80000000) & M32) - 0x80000000


def u32(v: int) -> int:
    """The unsigned 32-bit pattern of ``v`` (``repeat n`` counts this many times)."""
    return v & M32


def flag(condition) -> int:
    """Spin's truth value: TRUE (-1) or FALSE (0)."""
    return -1 if condition else 0


def _delta(op: int, x: int, y: int) -> None:
    """Charge the cycles a value-dependent math loop takes beyond the reference the statement paid."""
    T = RT.T
    if T is not None and RT.cog is not None:
        table = T._math[op & 0x1F]
        RT.cog.t += table[_mparam(op, x & M32, y & M32)] - table[_MREF.get(op, 0)]


from ..chip.timing import MATH_REF as _MREF, math_param as _mparam  # noqa: E402


def _divide(a: int, b: int) -> tuple:
    """Both operands as Spin longs; pays the division loop's cycles (by the divisor's bit length)."""
    a = ((a + 0x80000000) & M32) - 0x80000000
    b = ((b + 0x80000000) & M32) - 0x80000000
    if RT.div_extra is not None:
        RT.cog.t += RT.div_extra[abs(b).bit_length()]
    return a, b


def div(a: int, b: int) -> int:
    """Spin ``a / b``: signed, rounded toward zero; dividing by zero gives 0."""
    if 0 <= a <= POSX and 0 < b <= POSX:       # both non-negative longs: the common case, short (hot path)
        if RT.div_extra is not None:
            RT.cog.t += RT.div_extra[b.bit_length()]
        return a // b
    a, b = _divide(a, b)
    if b == 0:
        return 0
    q = abs(a) // abs(b)
    return wrap(-q if (a < 0) != (b < 0) else q)


def mod(a: int, b: int) -> int:
    """Spin ``a // b``: the remainder, with the sign of ``a``; modulo zero gives 0."""
    if 0 <= a <= POSX and 0 < b <= POSX:       # as in div
        if RT.div_extra is not None:
            RT.cog.t += RT.div_extra[b.bit_length()]
        return a % b
    a, b = _divide(a, b)
    if b == 0:
        return 0
    r = abs(a) % abs(b)
    return -r if a < 0 else r


def shr(a: int, n: int) -> int:
    """Spin ``a >> n``: logical shift right (zeros come in)."""
    return wrap((a & M32) >> (n & 31))


def rol(a: int, n: int) -> int:
    """Spin ``a <- n``: rotate left."""
    return wrap(_m.rol(a & M32, n & M32))


def ror(a: int, n: int) -> int:
    """Spin ``a -> n``: rotate right."""
    return wrap(_m.ror(a & M32, n & M32))


def rev(a: int, n: int) -> int:
    """Spin ``a >< n``: the low ``n`` bits of ``a`` in reverse order."""
    return wrap(_m.rev(a & M32, n & M32))


def mul_high(a: int, b: int) -> int:
    """Spin ``a ** b``: the upper 32 bits of the 64-bit product."""
    return wrap(_m.mul_high(a & M32, b & M32))


def sqrt(a: int) -> int:
    """Spin ``^^a``: integer square root of the unsigned value."""
    return _m.sqrt(a & M32)


def encode(a: int) -> int:
    """Spin ``>|a``: 1 + the number of the highest set bit (0 for 0)."""
    _delta(0xF1, a, 0)
    return _m.encode(a & M32)


def decode(n: int) -> int:
    """Spin ``|<n``: a long with bit ``n`` set."""
    return wrap(1 << (n & 31))


def sign_extend_byte(v: int) -> int:
    """Spin ``~x``: bit 7 copied to bits 8..31."""
    v &= 0xFF
    return v - 0x100 if v & 0x80 else v


def sign_extend_word(v: int) -> int:
    """Spin ``~~x``: bit 15 copied to bits 16..31."""
    v &= 0xFFFF
    return v - 0x10000 if v & 0x8000 else v


def random_forward(v: int) -> int:
    """Spin ``?x``: the next value of the ROM's pseudo-random generator."""
    return wrap(_rnd_fwd(v & M32))


def random_reverse(v: int) -> int:
    """Spin ``x?``: the previous value of the ROM's pseudo-random generator."""
    return wrap(_rnd_rev(v & M32))


def within(v: int, low: int, high: int) -> bool:
    """Is ``v`` in the Spin range ``low..high`` (either order)?"""
    return low <= v <= high if low <= high else high <= v <= low


def repeat_step(x: int, start: int, stop: int, step: int = 1) -> tuple:
    """One step of ``repeat x from start to stop step s``: ``(next x, loop again?)``."""
    if start <= stop:
        x += step
        return wrap(x), start <= x <= stop
    x -= step
    return wrap(x), stop <= x <= start


def _search(key: int, items, costs, down: bool) -> tuple:
    """Spin's lookup/lookdown search: ``(position of the matching value counting from 0, that value)``,
    ``(None, 0)`` when nothing matches.

    ``key``: lookup's index counting from 0, or lookdown's value.  An item is a
    value, a ``range`` (``span``) or a function that gives one (an item Spin
    evaluates only when it reaches it).  ``costs`` (the weaver passes the row
    the translator listed for this call in ``SPIN_LOOKUPS``) pays what the
    statement's static charge left to the search:

    * ``(item cycles, LOOK_DONE's, extra per match)``: every item was paid
      with the statement; a match gives back the items after it and LOOK_DONE;
    * ``("each", LOOK_DONE's, ((before, after, extra), ...))``: each item is
      paid as it is reached (cycles before its call or register read, from
      there on, what a match adds); a match gives back LOOK_DONE.
    """
    T = RT.T if costs is not None else None
    each = T is not None and costs[0] == "each"
    if each:
        from .runtime import tick
    position = 0
    for k, item in enumerate(items):
        if each:
            before, after, extra = costs[2][k]
            if before is not None:
                tick(before)
        if callable(item):
            item = item()
        if each and after is not None:
            tick(after)
        if down:
            if isinstance(item, range):
                hit = key in item
                at, value, size = (item.index(key) if hit else 0), key, len(item)
            else:
                hit, at, value, size = key == item, 0, item, 1
        else:
            # 32-bit arithmetic as the ROM's LOOKUP_RANGE: a range counts (|hi - lo| + 1) & $FFFF_FFFF
            # items ($8000_0000..$7FFF_FFFF none) and matches when index - position < count, unsigned
            at = (key - position) & M32
            if isinstance(item, range):
                up = item.step > 0
                lo, hi = item.start, (item.stop - 1 if up else item.stop + 1)
                size = ((hi - lo if up else lo - hi) + 1) & M32
                hit = at < size
                value = wrap(lo + at if up else lo - at) if hit else 0
            else:
                hit, value, size = at == 0, item, 1
        if hit:
            if each:
                RT.cog.t += extra - costs[1]
            elif T is not None:
                RT.cog.t += costs[2][k] - sum(costs[0][k + 1:]) - costs[1]
            return position + at, value
        position = (position + size) & M32
    return None, 0


def lookup(index: int, items, costs=None) -> int:
    """Spin ``lookup(i: a, b, c)``: item ``i`` counting from 1, or 0."""
    return _search(index - 1, items, costs, False)[1]


def lookupz(index: int, items, costs=None) -> int:
    """Spin ``lookupz(i: a, b, c)``: item ``i`` counting from 0, or 0."""
    return _search(index, items, costs, False)[1]


def lookdown(value: int, items, costs=None) -> int:
    """Spin ``lookdown(v: a, b, c)``: the position of ``v`` counting from 1, or 0."""
    found = _search(value, items, costs, True)[0]
    return 0 if found is None else wrap(found + 1)      # a position past $7FFF_FFFF is negative, as in Spin


def lookdownz(value: int, items, costs=None) -> int:
    """Spin ``lookdownz(v: a, b, c)``: the position of ``v`` counting from 0, or 0."""
    found = _search(value, items, costs, True)[0]
    return 0 if found is None else wrap(found)


def span(low: int, high: int) -> range:
    """The Spin range ``low..high`` as a Python range, in Spin's order."""
    return range(low, high + 1) if low <= high else range(low, high - 1, -1)


# ----------------------------------------------------------------------------- hub memory
class _Memory:
    """``long[addr]``, ``word[addr]``, ``byte[addr]`` (``[base, index]`` for Spin's ``long[base][index]``)."""

    __slots__ = ("size", "name")

    def __init__(self, size: int, name: str):
        self.size = size
        self.name = name

    def _addr(self, key) -> int:
        if isinstance(key, tuple):
            base, index = key
            return (base + index * self.size) & 0xFFFF
        return key & 0xFFFF

    def __getitem__(self, key) -> int:
        a = self._addr(key)
        if self.size == 4:
            return RT.Ls[a >> 2]
        if self.size == 2:
            return RT.W[a >> 1]
        return RT.mem[a]

    def __setitem__(self, key, value: int) -> None:
        a = self._addr(key)
        if a >= 0x8000:
            return
        if self.size == 4:
            RT.L[a >> 2] = value & M32
        elif self.size == 2:
            RT.W[a >> 1] = value & 0xFFFF
        else:
            RT.mem[a] = value & 0xFF

    def __repr__(self) -> str:
        return f"spin.{self.name}"


long, word, byte = _Memory(4, "long"), _Memory(2, "word"), _Memory(1, "byte")


class _Array:
    """Elements of a VAR/DAT variable (indexable like Spin's ``name[i]``; ``.addr`` is ``@name``)."""

    __slots__ = ("addr", "mem")

    def __init__(self, addr: int, mem: _Memory):
        self.addr = addr
        self.mem = mem

    def __getitem__(self, i: int) -> int:
        return self.mem[self.addr + i * self.mem.size]

    def __setitem__(self, i: int, value: int) -> None:
        self.mem[self.addr + i * self.mem.size] = value


class _Longs(_Array):
    """A long array in hub RAM (the common case, kept short: it is a hot path)."""

    __slots__ = ()

    def __getitem__(self, i: int) -> int:
        return RT.Ls[((self.addr + (i << 2)) & 0xFFFF) >> 2]

    def __setitem__(self, i: int, value: int) -> None:
        a = (self.addr + (i << 2)) & 0xFFFF
        if a < 0x8000:
            RT.L[a >> 2] = value & M32


class _Bytes(_Array):
    __slots__ = ()

    def __getitem__(self, i: int) -> int:
        return RT.mem[(self.addr + i) & 0xFFFF]

    def __setitem__(self, i: int, value: int) -> None:
        a = (self.addr + i) & 0xFFFF
        if a < 0x8000:
            RT.mem[a] = value & 0xFF


def _view(addr: int, mem: _Memory) -> _Array:
    if mem.size == 4:
        return _Longs(addr, mem)
    if mem.size == 1:
        return _Bytes(addr, mem)
    return _Array(addr, mem)


class _Scalar(property):
    """A VAR/DAT variable that is one value: a property reading and writing its hub address."""

    def address(self, obj) -> int:
        return (obj._pbase if self.dat else obj._vbase) + self.offset


class _Elements:
    """A VAR/DAT array: ``obj.name`` is an indexable view, made once per object (then found in its ``__dict__``)."""

    __slots__ = ("offset", "count", "dat", "mem", "name")

    def __init__(self, offset, count, dat, mem):
        self.offset, self.count, self.dat, self.mem = offset, count, dat, mem

    def __set_name__(self, owner, name):
        self.name = name

    def address(self, obj) -> int:
        return (obj._pbase if self.dat else obj._vbase) + self.offset

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        view = _view(self.address(obj), self.mem)
        obj.__dict__[self.name] = view
        return view


def _variable(offset: int, count: int, dat: bool, mem: _Memory):
    if count != 1:
        return _Elements(offset, count, dat, mem)
    base = "_pbase" if dat else "_vbase"
    if mem.size == 4:
        def get(obj):
            return RT.Ls[(getattr(obj, base) + offset) >> 2]

        def put(obj, value):
            a = getattr(obj, base) + offset
            if a < 0x8000:
                RT.L[a >> 2] = value & M32
    elif mem.size == 2:
        def get(obj):
            return RT.W[(getattr(obj, base) + offset) >> 1]

        def put(obj, value):
            a = getattr(obj, base) + offset
            if a < 0x8000:
                RT.W[a >> 1] = value & 0xFFFF
    else:
        def get(obj):
            return RT.mem[getattr(obj, base) + offset]

        def put(obj, value):
            a = getattr(obj, base) + offset
            if a < 0x8000:
                RT.mem[a] = value & 0xFF
    var = _Scalar(get, put)
    var.offset, var.count, var.dat, var.mem = offset, count, dat, mem
    return var


def Long(offset: int, count: int = 1, *, dat: bool = False):  # noqa: N802 - reads as a type in class bodies
    """A long variable (or array of ``count`` longs) at ``offset`` in the object's VAR block (or DAT: from its start)."""
    return _variable(offset, count, dat, long)


def Word(offset: int, count: int = 1, *, dat: bool = False):  # noqa: N802
    """A word variable (16 bits, read as 0..65535)."""
    return _variable(offset, count, dat, word)


def Byte(offset: int, count: int = 1, *, dat: bool = False):  # noqa: N802
    """A byte variable (8 bits, read as 0..255)."""
    return _variable(offset, count, dat, byte)


class Child:
    """An OBJ line: ``motor = spin.Child(Stepper)`` (``count`` > 1: a list of instances)."""

    __slots__ = ("cls", "count", "name")

    def __init__(self, cls, count: int = 1):
        self.cls = cls
        self.count = count

    def __set_name__(self, owner, name):
        self.name = name


class Object:
    """A Spin object instance: its code (``_pbase``) and VAR block (``_vbase``) in hub RAM.

    Instances are made by the runtime from the compiler's layout
    (:func:`spinemu.translate.runtime.instantiate`), so that every variable
    sits at the address the compiled image gives it.
    """

    _pbase = 0
    _vbase = 0

    def at(self, name: str, index: int = 0, size: int = 0) -> _Array:
        """The variable ``name`` seen as an array (Spin's ``name[i]`` on any variable, ``name.byte[i]``)."""
        var = getattr(type(self), name)
        mem = {1: byte, 2: word, 4: long}[size] if size else var.mem
        return _view(var.address(self) + index * var.mem.size, mem)

    def addr(self, name: str, index: int = 0) -> int:
        """Spin's ``@name`` (``@name[index]``): the hub address of a VAR or DAT variable."""
        var = getattr(type(self), name)
        return var.address(self) + index * var.mem.size

    def string(self, offset: int, text: str = "") -> int:
        """Spin's ``string("...")``: the hub address of the string the compiler put at ``offset`` in this object."""
        return self._pbase + offset

    def object_base(self) -> int:
        """The hub address of this object (what Spin's ``@@`` adds)."""
        return self._pbase


# ----------------------------------------------------------------------------- abort
class Abort(Exception):
    """Spin's ``abort value``: unwinds to the nearest ``\\call`` (:func:`trap`).

    ``bare``: Spin's ``abort`` without a value (it aborts with the method's result).
    """

    def __init__(self, value: int = 0, bare: bool = False):
        super().__init__(value)
        self.value = value
        self.bare = bare

    def charge(self, kept: bool) -> None:
        """Pay what the ABORT bytecode costs beyond its one-frame price: the frames it unwound."""
        if RT.T is None or RT.cog is None:
            return
        frames = 0
        tb = self.__traceback__
        while tb is not None:
            f = tb.tb_frame
            if f.f_code.co_name in f.f_globals.get("SPIN_FRAME_SIZES", ()):
                frames += 1
            tb = tb.tb_next
        op = 0x30 if self.bare else 0x31
        RT.cog.t += RT.T.returns(op, max(frames, 1), kept) - RT.T.returns(op, 1, True)


def trap(method, *args, keep_result: bool = True) -> int:
    """Spin's ``\\method(args)``: the method's result, or the value of an ``abort`` inside it.

    ``keep_result=False``: the call is a statement (its value is dropped).
    """
    try:
        value = method(*args)
    except Abort as stop:
        stop.charge(keep_result)
        return stop.value
    if not keep_result and RT.T is not None and RT.cog is not None:
        RT.cog.t += RT.T.returns(0x32, 1, False) - RT.T.returns(0x32, 1, True)
    return value


from .spin_cog import (  # noqa: E402,F401 - the cog's half of this namespace
    Register, bytefill, bytemove, clkfreq, clkmode, clkset, cog, cogid, coginit, cognew, cogstop,
    lockclr, locknew, lockret, lockset, longfill, longmove, reboot, strcomp, string, strsize,
    waitcnt, waitpeq, waitpne, waitvid, wordfill, wordmove, _fetched,
)


# ----------------------------------------------------------------------------- hub frames
class local:
    """A local variable Spin does not initialise (``count`` longs): ``buf=spin.local(16)``."""

    __slots__ = ("count",)

    def __init__(self, count: int = 1):
        self.count = count


class Frame:
    """A method's result, parameters and locals in hub RAM, where the bytecode interpreter keeps them.

    Used by methods that take a local's address or index it (``@buf``,
    ``buf[i]``): Spin code may hand such addresses to other methods and cogs,
    so the variables must sit at the same stack addresses as on the chip.
    ``Frame(result=0, x=x, buf=spin.local(8))`` lays them out in that order
    (one long each, ``local(n)`` takes n) at the frame address the calling
    chain gives (:func:`_frame_base`); ``frame.x`` reads and writes the hub.
    """

    __slots__ = ("_base", "_fields")

    def __init__(self, **fields):
        import sys
        base = _frame_base(sys._getframe(1))
        layout = {}
        offset = 0
        for name, value in fields.items():
            count = value.count if isinstance(value, local) else 1
            layout[name] = (offset, count)
            if not isinstance(value, local):
                long[base + offset] = value
            offset += 4 * count
        if base + offset > 0x8000:
            raise RT.chip.fault(RT.cog, 0, f"stack overflow: the call needs the stack up to ${base + offset:04X}, "
                                           "past the end of hub RAM")
        object.__setattr__(self, "_base", base)
        object.__setattr__(self, "_fields", layout)

    def __getattr__(self, name: str):
        offset, count = self._fields[name]
        a = self._base + offset
        return _Array(a, long) if count != 1 else long[a]

    def __setattr__(self, name: str, value: int) -> None:
        long[self._base + self._fields[name][0]] = value

    def addr(self, name: str, index: int = 0) -> int:
        """Spin's ``@name`` (``@name[index]``) for a local."""
        return self._base + self._fields[name][0] + 4 * index

    def at(self, name: str, index: int = 0, size: int = 4) -> _Array:
        """The local ``name`` seen as an array (``name[i]``, ``name.byte[i]``)."""
        return _Array(self.addr(name, index), {1: byte, 2: word, 4: long}[size])


def left_on_stack(*offsets):
    """What locals Spin does not initialise start with: the longs at their places in the method's frame.

    Used in methods a ``cognew`` can start: there the new cog's frame holds
    what RUN wrote (the interpreter's start words), on both engines.  One
    offset gives one value, several a tuple.
    """
    import sys
    base = _frame_base(sys._getframe(1))
    values = tuple(long[base + o] for o in offsets)
    return values[0] if len(values) == 1 else values


def call_at(depth: int, method, *args, spin_pay=None, **kwargs):
    """Call a translated method whose frame starts ``depth`` stack bytes above its caller's.

    The weaver wraps the calls of a line whose calls start at different
    depths (``f(g(x), g(y))``) with this, so :func:`_frame_base` finds each one's.
    ``spin_pay``: cycles (a run of bytecodes) to pay before the call starts:
    in a statement with several calls, the bytecodes since the call before.
    """
    if spin_pay is not None and RT.T is not None:
        from .runtime import tick
        tick(spin_pay)
    return method(*args, **kwargs)


_CALL_AT = call_at.__code__


def _frame_base(pyframe) -> int:
    """The hub address of the frame (``dbase``) of the translated method running in ``pyframe``.

    The bytecode interpreter puts a called method's frame where the caller's
    stack ends: ``dbase(callee) = dbase(caller) + frame size(caller) + bytes
    the caller's expression had pushed + 8`` (the return frame).  The chain
    of translated methods is read from the Python call stack, from the cog's
    top method (whose frame the runtime knows) down to this one; each module
    lists its methods' frame sizes and its lines' stack use at calls (one
    number per line, or a :func:`call_at` between caller and callee).
    """
    chain = []
    f = pyframe
    depth = None
    while f is not None:
        code = f.f_code
        if code is _CALL_AT:
            depth = f.f_locals["depth"]
        else:
            sizes = f.f_globals.get("SPIN_FRAME_SIZES")
            if sizes is not None and code.co_name in sizes:
                chain.append((f, depth))
                depth = None
        f = f.f_back
    chain.reverse()
    dbase = RT.cog.dbase
    for caller, depth in chain[:-1]:
        g = caller.f_globals
        if depth is None:
            depth = g.get("SPIN_CALL_DEPTHS", {}).get(caller.f_lineno, 0)
            if depth.__class__ is list:     # a call the weaver did not wrap: the line's first
                depth = next((e[1] for e in depth if e[1] is not None), 0)
        dbase += g["SPIN_FRAME_SIZES"][caller.f_code.co_name] + depth + 8
    return dbase & 0xFFFF
