"""Compile the BS2's commands: argument shapes and checks, then the run-time
bodies of :mod:`.commands` and :mod:`.serial`.

``HANDLERS`` maps a statement kind (grammar rule) to ``handler(compiler, st)``.
A statement without a handler here or in :mod:`.compiler` is reported as
"not supported by spinemu yet" (currently only XOUT).
"""
from __future__ import annotations

from typing import Callable

from . import access
from . import commands as C
from . import messages as M
from . import nodes as N
from . import serial as S

__all__ = ["HANDLERS"]

HANDLERS: dict[str, Callable] = {}


def handler(*kinds: str):
    def register(fn):
        for k in kinds:
            HANDLERS[k] = fn
        return fn
    return register


# ------------------------------------------------------------------ pins, time
@handler("high", "low", "toggle", "input", "output", "reverse")
def _pin_op(c, st):
    kind = st.kind
    c.emit(kind, C.make_pin_op(kind, c.pin(st.args[0])), st)


@handler("pause")
def _pause(c, st):
    c.emit("pause", C.make_pause(c.expr(st.args[0])), st)


@handler("nap")
def _nap(c, st):
    c.emit("nap", C.make_nap(c.expr(st.args[0])), st)


@handler("sleep")
def _sleep(c, st):
    c.emit("sleep", C.make_sleep(c.expr(st.args[0])), st)


@handler("pulsout")
def _pulsout(c, st):
    pin, dur = st.args
    c.emit("pulsout", C.make_pulsout(c.pin(pin, "pulsout.pin"), c.expr(dur)), st)


@handler("pulsin", "rctime", "count")
def _measure(c, st):
    pin, arg, ref = st.args
    write, _, _ = c.target(ref)
    make = {"pulsin": C.make_pulsin, "rctime": C.make_rctime, "count": C.make_count}[st.kind]
    c.emit(st.kind, make(c.pin(pin, st.kind + ".pin"), c.expr(arg), write), st)


@handler("freqout")
def _freqout(c, st):
    pin, dur, f1, f2 = st.args
    c.emit("freqout", C.make_freqout(
        c.pin(pin), c.expr(dur, "freqout.duration"), c.expr(f1, "freqout.freq1"),
        c.expr(f2, "freqout.freq2") if f2 is not None else None, c.warner(st.pos)), st)


@handler("dtmfout")
def _dtmfout(c, st):
    pin, on, off, *tones = st.args
    c.emit("dtmfout", C.make_dtmfout(
        c.pin(pin), c.expr(on, "dtmfout.on") if on is not None else None,
        c.expr(off, "dtmfout.off") if off is not None else None,
        [c.expr(t, "dtmfout.tone") for t in tones], c.warner(st.pos)), st)


@handler("pwm")
def _pwm(c, st):
    pin, duty, cycles = st.args
    c.emit("pwm", C.make_pwm(c.pin(pin, "pwm.pin"), c.expr(duty), c.expr(cycles, "pwm.cycles"),
                             c.warner(st.pos)), st)


@handler("button")
def _button(c, st):
    pin, down, delay, rate, ws, target, label = st.args
    write, read, width = c.target(ws, "button.index")
    if width < 8:
        raise c.error(M.BUTTON_WORKSPACE, ws.pos)
    c.emit("button", C.make_button(
        c.pin(pin, "button.pin"), c.expr(down), c.expr(delay, "button.delay"),
        c.expr(rate, "button.rate"), read, write, c.expr(target, "button.target"),
        c.label_target(label)), st)


@handler("random")
def _random(c, st):
    write, read, _ = c.target(st.args[0])
    c.emit("random", C.make_random(read, write, c.warner(st.pos)), st)


# ------------------------------------------------------------------ EEPROM, tables
@handler("read")
def _read(c, st):
    addr, *items = st.args
    if len(items) > 1 and c.tree.language != "2.5":
        raise c.error(M.NEEDS_25.format("READ with several variables"), items[1].pos)
    addr_f = c.expr(addr)
    targets = []
    for it in items:
        word, ref = it.args
        write, _, width = c.target(ref)
        if word is not None and width != 16:
            raise c.error(M.EXPECTED_WORD_VARIABLE, ref.pos)
        targets.append((word is not None, write))
    pos = st.pos

    def run(m):
        a = addr_f(m)
        for is_word, write in targets:
            if is_word:
                v = m.ee_read(a, pos) | (m.ee_read(a + 1, pos) << 8)
                a += 2
            else:
                v = m.ee_read(a, pos)
                a += 1
            write(m, v)
    c.emit("read", run, st)


@handler("write")
def _write(c, st):
    addr, *items = st.args
    if len(items) > 1 and c.tree.language != "2.5":
        raise c.error(M.NEEDS_25.format("WRITE with several values"), items[1].pos)
    addr_f = c.expr(addr, "write.address")
    values = [(it.args[0] is not None, c.expr(it.args[1])) for it in items]
    pos = st.pos

    def run(m):
        a = addr_f(m)
        n = 0
        for is_word, f in values:
            v = f(m)
            m.ee_write(a, v & 0xFF, pos)
            a += 1
            n += 1
            if is_word:
                m.ee_write(a, v >> 8, pos)
                a += 1
                n += 1
        if m.eeprom_write_us:
            m.warn(pos, M.W_WRITE_TIME)
            m.advance(m.eeprom_write_us * n)
    c.emit("write", run, st)


def _value_list(c, exprs, slot) -> list:
    """LOOKUP/LOOKDOWN lists: a quoted string is one entry per character."""
    out = []
    for e in exprs:
        if isinstance(e, N.Str) and len(e.text) != 1:
            out.extend((lambda v: lambda m: v)(ord(ch) & 0xFF) for ch in e.text)
        else:
            out.append(c.expr(e, slot))
    if len(out) > 256:
        raise c.error(M.LIST_TOO_LONG.format("LOOKUP/LOOKDOWN", 256), st_pos(exprs[0]))
    return out


def st_pos(e) -> N.Pos:
    from .exprs import leftmost_leaf
    return leftmost_leaf(e).pos


@handler("lookup")
def _lookup(c, st):
    index, *values, ref = st.args
    idx = c.expr(index)
    vals = _value_list(c, values, "lookup.value")
    write, _, _ = c.target(ref)
    n = len(vals)

    def run(m):
        i = idx(m)
        if i < n:
            write(m, vals[i](m))
    c.emit("lookup", run, st)


@handler("lookdown")
def _lookdown(c, st):
    from .exprs import _COMPARE
    value, *values, ref = st.args
    op = values.pop(0) if values and not isinstance(values[0], (N.Num, N.Str, N.Ref, N.Unary,
                                                                 N.Binary)) else None
    key = {"=<": "<=", "=>": ">=", "><": "<>"}.get(str(op), str(op)) if op is not None else "="
    cmp = _COMPARE[key]
    f = c.expr(value)
    vals = _value_list(c, values, "lookdown.value")
    write, _, _ = c.target(ref)

    def run(m):
        x = f(m)
        for i, g in enumerate(vals):
            if cmp(x, g(m)):
                write(m, i)
                return
    c.emit("lookdown", run, st)


# ------------------------------------------------------------------ serial
def _show_text(item) -> str:
    text = item.text
    return text.split("?", 1)[1].strip() if "?" in text else text.strip()


def _out_items(c, items, prefix: str) -> list:
    out = []
    for it in items:
        k, a = it.kind, it.args
        if k == "out_value":
            e = a[0]
            if isinstance(e, N.Str) and len(e.text) != 1:
                data = e.text.encode("latin-1", "replace")
                out.append(lambda m, d=data: d)
            else:
                f = c.expr(e, prefix + ".item")
                out.append(lambda m, f=f: bytes([f(m) & 0xFF]))
        elif k == "out_fmt":
            fmt, f = str(a[0]).upper(), c.expr(a[1], prefix + ".item")
            out.append(lambda m, fmt=fmt, f=f: S.format_number(fmt, f(m)).encode())
        elif k in ("out_fmt_show", "out_show"):
            fmt = str(a[0]).upper() if k == "out_fmt_show" else "DEC"
            f = c.expr(a[-1], prefix + ".item")
            name = _show_text(it)
            out.append(lambda m, fmt=fmt, f=f, name=name:
                       f"{name} = {S.format_number(fmt, f(m))}\r".encode())
        elif k == "out_asc_show":
            f = c.expr(a[0], prefix + ".item")
            name = _show_text(it)
            out.append(lambda m, f=f, name=name:
                       f"{name} = '".encode() + bytes([f(m) & 0xFF]) + b"'\r")
        elif k == "out_str":
            var = c.array_view(a[0])
            read = access.byte_reader(var.bitoff, var.width, c.warner(it.pos))
            length = c.expr(a[1], prefix + ".str.length") if a[1] is not None else None
            out.append(_str_emitter(read, var, length))
        elif k == "out_rep":
            ch = c.expr(a[0], prefix + ".rep.char")
            n = c.expr(a[1], prefix + ".rep.count")
            out.append(lambda m, ch=ch, n=n: bytes([ch(m) & 0xFF]) * n(m))
    return out


def _str_emitter(read, var, length):
    limit = (256 - var.bitoff) // var.width

    def emit(m):
        if length is not None:
            return bytes(read(m, i) & 0xFF for i in range(length(m)))
        out = bytearray()
        for i in range(limit):
            b = read(m, i) & 0xFF
            if b == 0:
                break
            out.append(b)
        return bytes(out)
    return emit


def _in_items(c, items, prefix: str) -> list:
    out = []
    for it in items:
        k, a = it.kind, it.args
        if k == "in_byte":
            write, _, _ = c.target(a[0])
            out.append(S.in_byte(write))
        elif k == "in_fmt":
            write, _, _ = c.target(a[1])
            out.append(S.in_number(str(a[0]).upper(), write))
        elif k == "in_str":
            var = c.array_view(a[0])
            bw = access.byte_writer(var.bitoff, var.width, c.warner(it.pos))
            length = c.expr(a[1], prefix + ".str.length")
            end = c.expr(a[2]) if a[2] is not None else None
            out.append(S.in_str(bw, length, end))
        elif k == "in_waitstr":
            var = c.array_view(a[0])
            br = access.byte_reader(var.bitoff, var.width, c.warner(it.pos))
            length = c.expr(a[1], prefix + ".waitstr.length") if a[1] is not None else None
            out.append(S.in_waitstr(br, length))
        elif k == "in_wait":
            vals = []
            for i, e in enumerate(a):
                if isinstance(e, N.Str) and len(e.text) != 1:
                    vals.extend((lambda v: lambda m: v)(ord(ch) & 0xFF) for ch in e.text)
                else:
                    vals.append(c.expr(e, prefix + (".wait" if i == 0 else ".wait.more")))
            out.append(S.in_wait(vals))
        elif k == "in_skip":
            out.append(S.in_skip(c.expr(a[0], prefix + ".skip")))
    return out


@handler("debug")
def _debug(c, st):
    c.emit("debug", S.make_debug(_out_items(c, st.args, "debug")), st)


@handler("debugin")
def _debugin(c, st):
    c.emit("debugin", S.make_debugin(_in_items(c, st.args, "debugin"), st.pos), st)


def _split_serial(st):
    pin, fpin, baud, *rest = st.args
    extras = [x for x in rest if not isinstance(x, N.Stmt)]
    items = [x for x in rest if isinstance(x, N.Stmt)]
    return pin, fpin, baud, extras, items


def _is_label(c, e) -> bool:
    if not isinstance(e, N.Ref) or e.mods or e.index is not None:
        return False
    sym = c.syms.lookup(e.name)
    return sym is not None and sym.kind == "label"


@handler("serout")
def _serout(c, st):
    pin, fpin, baud, extras, items = _split_serial(st)
    pace = timeout = tlabel = None
    if fpin is None:
        if len(extras) > 1:
            raise c.error(M.EXPECTED_BRACKET, st_pos(extras[1]))
        if extras:
            pace = c.expr(extras[0], "serout.pace")
    else:
        if len(extras) == 1:
            raise c.error(M.SEROUT_FORMS, st_pos(extras[0]))
        if len(extras) >= 2:
            if len(extras) > 2 or not _is_label(c, extras[1]):
                raise c.error(M.EXPECTED_LABEL, st_pos(extras[1]))
            timeout = c.expr(extras[0], "serout.timeout")
            tlabel = c.label_target(extras[1])
    c.emit("serout", S.make_serout(
        c.pin(pin, "serout.pin", highest=16), c.pin(fpin, "serout.fpin") if fpin is not None else None,
        c.expr(baud, "serout.baud"), pace, timeout, tlabel, _out_items(c, items, "serout")), st)


@handler("serin")
def _serin(c, st):
    pin, fpin, baud, extras, items = _split_serial(st)
    timeout = tlabel = None
    if len(extras) in (1, 3):
        if not _is_label(c, extras[0]):
            raise c.error(M.EXPECTED_LABEL, st_pos(extras[0]))
        c.label_target(extras[0])          # parity-error label: checked, never taken
        extras = extras[1:]
    if len(extras) == 2:
        if not _is_label(c, extras[1]):
            raise c.error(M.EXPECTED_LABEL, st_pos(extras[1]))
        timeout = c.expr(extras[0], "serin.timeout")
        tlabel = c.label_target(extras[1])
    elif extras:
        raise c.error(M.SERIN_FORMS, st_pos(extras[0]))
    c.emit("serin", S.make_serin(
        c.pin(pin, "serin.pin", highest=16), c.pin(fpin, "serin.fpin") if fpin is not None else None,
        c.expr(baud, "serin.baud"), timeout, tlabel, _in_items(c, items, "serin"), st.pos), st)


@handler("shiftout")
def _shiftout(c, st):
    d, k, mode, *items = st.args
    compiled = [(c.expr(it.args[0], "shiftout.value"),
                 c.expr(it.args[1], "shiftout.bits") if it.args[1] is not None else None)
                for it in items]
    c.emit("shiftout", S.make_shiftout(c.pin(d, "shiftout.dpin"), c.pin(k, "shiftout.cpin"),
                                       c.expr(mode), compiled), st)


@handler("shiftin")
def _shiftin(c, st):
    d, k, mode, *items = st.args
    compiled = []
    for it in items:
        write, _, width = c.target(it.args[0], "shiftin.index")
        bits = c.expr(it.args[1], "shiftin.bits") if it.args[1] is not None else None
        compiled.append((write, width, bits))
    c.emit("shiftin", S.make_shiftin(c.pin(d, "shiftin.dpin"), c.pin(k, "shiftin.cpin"),
                                     c.expr(mode), compiled), st)
