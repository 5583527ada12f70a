"""Turn observations (timing names, measured cycles) into the timing table.

Part of derive_timing.py.  An observation is ``(names, rest, ...)``: the
measured cycles ``rest`` must equal the sum of the values of ``names``.
Names are plain strings (one number each) or tuples for the value-dependent
paths, resolved here into table entries:

* ``("assign", byte, stack, jumped)``: an assignment operator; MATH operators
  add the same value-dependent cycles as the plain math bytecode;
* ``("math", op, x, y)``: a math bytecode, indexed by the parameter its loop
  depends on (:func:`spinemu.chip.timing.math_param`);
* ``("strsize", n)`` and the other loops: ``base + per * n``, checked;
* ``("return", op, frames, _)``, ``("run", params)``.
"""
from __future__ import annotations

import collections
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))))

from spinemu.chip.timing import MATH_REF, math_param  # noqa: E402

LOOPS = ("strsize", "strcomp_eq", "strcomp_ne", "bytefill", "wordfill", "longfill", "bytemove", "wordmove", "longmove")


def assign_name(a: int, stack, jumped: bool, family: str, long_jump: bool = False):
    """``(table name, math op or None, math operands)`` for an assignment operator byte.

    ``family`` is ``"mem"`` (the target is hub memory) or ``"reg"`` (a cog
    register): the ROM writes the two back differently, so each has its own
    operator costs.
    """
    b = a & 0x7F
    if b & 0x40:
        f = b & 0x1F
        return f"math_assign/{family}/{0xE0 | f:02x}" + ("/push" if a & 0x80 else ""), 0xE0 | f, stack
    if b in (0x02, 0x06):
        return (f"repeat/{family}/{'step' if b == 6 else 'plain'}/{'loop' if jumped else 'exit'}"
                + ("/long" if long_jump else ""), None, None)
    return f"assign/{family}/{a:02x}", None, None


def solve(obs):
    problems = []
    math_obs = collections.defaultdict(lambda: collections.defaultdict(set))
    simple = collections.defaultdict(set)
    loops = collections.defaultdict(lambda: collections.defaultdict(set))
    composite = []          # (base name, assign name, rest adjusted for the math loop)
    where = {}
    # math first: the composites need its tables
    for names, rest, prog, cog, r, m, ctx in obs:
        n0 = names[0]
        if isinstance(n0, tuple) and n0[0] == "math":
            op, x, y = n0[1], n0[2], n0[3]
            f = op & 0x1F
            unary = op in (0xE6, 0xE7, 0xE9, 0xF1, 0xF3, 0xF8, 0xFF)
            param = math_param(op, y if unary else x, 0 if unary else y)
            math_obs[op][param].add(rest)
            where[("math", op, param)] = prog
    math_table = {}
    for op, by in math_obs.items():
        for param, vals in by.items():
            if len(vals) > 1:
                problems.append(f"math ${op:02X} param {param}: several values {sorted(vals)}")
        math_table[op] = {p: min(v) for p, v in by.items()}

    def math_extra(op, x, y):
        unary = op in (0xE6, 0xE7, 0xE9, 0xF1, 0xF3, 0xF8, 0xFF)
        param = math_param(op, x, 0 if unary else y)
        table = math_table.get(op)
        ref = MATH_REF.get(op, 0)
        if table is None or param not in table or ref not in table:
            if param != ref:
                problems.append(f"math ${op:02X}: no plain measurement for param {param} or {ref}")
            return 0
        return table[param] - table[ref]

    for names, rest, prog, cog, r, m, ctx in obs:
        n0 = names[0]
        if isinstance(n0, str) and len(names) == 1:
            simple[n0].add(rest)
            where.setdefault(n0, prog)
        elif isinstance(n0, str):
            _, a, stack, jumped, family, long_jump = names[1]
            aname, mop, st = assign_name(a, stack, jumped, family, long_jump)
            extra = 0
            if mop is not None:         # the target's value is x; y is on the stack
                extra = math_extra(mop, m[8] or 0, st[0] if st else 0)
            composite.append((n0, aname, rest - extra, prog))
        elif n0[0] in LOOPS:
            loops[n0[0]][n0[1]].add(rest)
        elif n0[0] == "return":
            op, frames = n0[1], n0[2]
            name = ("abort", "abort_value", "return", "return_value")[op - 0x30]
            pushed = m[6][5]
            simple[(name, frames, pushed)].add(rest)
        elif n0[0] == "run":
            simple[("run", n0[1])].add(rest)
        elif n0[0] == "wait":
            continue
    data = {}
    _event_offsets(obs, data, problems)
    for name, vals in simple.items():
        if len(vals) > 1:
            problems.append(f"{name}: several values {sorted(vals)} (first seen in {where.get(name)})")
        v = min(vals)
        if isinstance(name, str):
            data[name] = v
    # returns and aborts: a value per (kind, result pushed) for one frame, plus a per-frame cost
    rets = {k: min(v) for k, v in simple.items() if isinstance(k, tuple) and k[0] in
            ("abort", "abort_value", "return", "return_value")}
    per = set()
    for (name, frames, pushed), v in rets.items():
        for (name2, frames2, pushed2), v2 in rets.items():
            if (name2, pushed2) == (name, pushed) and frames2 > frames:
                per.add((v2 - v) // (frames2 - frames))
    if len(per) > 1:
        problems.append(f"abort per-frame cost not constant: {sorted(per)}")
    per_frame = min(per) if per else 0
    data["abort/per_frame"] = per_frame
    for (name, frames, pushed), v in rets.items():
        key = f"{name}/{'push' if pushed else 'drop'}"
        base = v - per_frame * (frames - 1)
        if data.setdefault(key, base) != base:
            problems.append(f"{key}: {base} from {frames} frames, {data[key]} elsewhere")
    # RUN: linear in the parameter count
    runs = {k[1]: min(v) for k, v in simple.items() if isinstance(k, tuple) and k[0] == "run"}
    if runs:
        if 0 in runs:
            data["run/zero"] = runs.pop(0)
        base, per_p, bad = _fit_linear(runs)
        data["run/base"], data["run/per"] = base, per_p
        if bad:
            problems.append(f"RUN not linear in params: {runs}")
    for name, by in loops.items():
        pts = {}
        for n, vals in by.items():
            if len(vals) > 1:
                problems.append(f"{name} n={n}: several values {sorted(vals)}")
            pts[n] = min(vals)
        if 0 in pts:
            data[f"{name}/zero"] = pts.pop(0)
        base, per_n, bad = _fit_linear(pts)
        data[f"{name}/base"], data[f"{name}/per"] = base, per_n
        if bad:
            problems.append(f"{name} not linear: {sorted(pts.items())}")
    for op, table in math_table.items():
        if len(set(table.values())) == 1:
            data[f"math/{op:02x}"] = next(iter(table.values()))
        else:
            data[f"math/{op:02x}"] = [table.get(p) for p in range(33)]
            missing = [p for p in range(33) if p not in table]
            if missing:
                problems.append(f"math ${op:02X}: no measurement for params {missing}")
    _solve_composites(composite, data, problems)
    return data, problems


def _fit_linear(points: dict):
    ns = sorted(points)
    if len(ns) == 1:
        return points[ns[0]], 0, False
    n0, n1 = ns[0], ns[-1]
    per = (points[n1] - points[n0]) // (n1 - n0) if n1 != n0 else 0
    base = points[n0] - per * n0
    bad = any(points[n] != base + per * n for n in ns)
    return base, per, bad


def _solve_composites(composite, data, problems):
    """base + assign = rest for every observation; gauge: assign/*/80 (WRITE, pushed) = 0."""
    value = {"assign/mem/80": 0, "assign/reg/80": 0}
    edges = collections.defaultdict(list)
    for base, aname, rest, prog in composite:
        edges[base].append((aname, rest, prog))
        edges[aname].append((base, rest, prog))
    queue = ["assign/mem/80", "assign/reg/80"]
    for g in queue:
        if g not in edges:
            problems.append(f"no USING ... WRITE ({g}) observation to fix the split")
    while queue:
        n = queue.pop()
        for other, rest, prog in edges[n]:
            v = rest - value[n]
            if other not in value:
                value[other] = v
                queue.append(other)
            elif value[other] != v:
                problems.append(f"{n} + {other} = {rest} in {prog}, but {other} = {value[other]} elsewhere")
    for n in edges:
        if n not in value:
            problems.append(f"{n}: not connected to assign/80 (add a probe that links it)")
    data.update(value)


def _instr(line):
    cyc, addr, ins, flag, text = line
    w = int(ins, 16)
    return cyc, flag, (w >> 9) & 0x1FF, w & 0x1FF, (w >> 22) & 1, text


def _event_offsets(obs, data, problems):
    """Offsets from the fetch of events inside bytecodes, read off spinsim's instruction log.

    * ``NAME/read_at``: a CNT/INA/PHS read (the ``mov`` from $1F1/$1F2/$1FC/$1FD);
    * ``waitcnt/issue``, ``waitcnt/after``: the WAITCNT instruction's first
      cycle, and the cycles from its completion (the cycle CNT equals the
      target) to the next bytecode; likewise ``waitpeq/...``, ``waitpne/...``;
    * ``coginit/done``, ``cogstop/at``: the cycle after those hub instructions;
    * pin writes are checked to be the last instruction of their bytecode.
    """
    found = collections.defaultdict(set)
    for names, rest, prog, cog, r, m, ctx in obs:
        op = m[2]
        tf = r["tf"]
        lines = r["lines"]
        n0 = names[0] if isinstance(names[0], str) else None
        for i, line in enumerate(lines):
            cyc, flag, d, s_, imm, text = _instr(line)
            if flag != " ":
                continue
            word = text.split()
            mn = word[1] if word[0].startswith("if_") else word[0]
            if mn == "mov" and not imm and s_ in (0x1F1, 0x1F2, 0x1FC, 0x1FD) and n0:
                key = "spr/read_at" if n0.startswith("spr/") else n0 + "/read_at"
                found[key].add(cyc - tf)
            if d in (0x1F4, 0x1F6) and "R=" in text:
                if "next_start" in r and r["next_start"] - (cyc + 4) != 4:
                    problems.append(f"{prog}: pin write at {cyc} is not the last instruction of its bytecode")
            if mn == "coginit":
                found["coginit/done"].add(cyc + 4 - tf)
            if mn == "cogstop":
                found["cogstop/at"].add(cyc + 4 - tf)
            if mn in ("waitcnt", "waitpeq", "waitpne") and "next_start" in r:
                first = next(ln[0] for ln in lines if ln[1] == line[1])
                found[f"{mn}/issue"].add(first - tf)
                found[f"{mn}/after"].add(r["next_start"] - cyc)
    for key, vals in found.items():
        if len(vals) > 1:
            problems.append(f"{key}: several values {sorted(vals)}")
        data[key] = min(vals)
    data["waitcnt/min"] = 0      # a target equal to the issue cycle is met at once (measured)
