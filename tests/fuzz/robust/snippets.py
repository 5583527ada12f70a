"""Small, odd Spin programs built from templates: the corners a new user trips over.

Not the well-typed random program generator (that one checks *values*); these
only have to reach every part of the front end, compiler, translator and
chip with unusual material: names that are Python keywords or clash with the
translator's own names, comments and strings full of quote marks and
backslashes, huge numbers and constants that fold to errors, undefined names
in odd places (``case`` selectors, ``lookup`` lists, DAT operands), deep
nesting, child objects with odd file names, PASM with odd operands.  Some are
valid programs, most are almost valid.
"""
from __future__ import annotations

import random

from .mutate import ODD_TEXT, odd_number

__all__ = ["spin_program"]

NAMES = ["x", "y", "count", "lambda", "class", "None", "True", "self", "print", "spin", "Frame", "result_",
         "__init__", "_", "_x", "def", "import", "yield", "await", "async", "from_", "pass", "chip", "cog",
         "hub", "int", "len", "object", "type", "list", "A" * 200, "\u00e9t\u00e9", "x1", "main"]

UNARY = ["-", "!", "not ", "||", "|<", ">|", "^^", "~", "~~", "++", "--", "?", "@", "@@", "float(", "round(",
         "trunc("]
BINARY = ["+", "-", "*", "**", "/", "//", "#>", "<#", "~>", "<<", ">>", "<-", "->", "><", "&", "|", "^",
          "and", "or", "==", "<>", "<", ">", "=<", "=>", "+=", "-=", ":=", "/=", "//=", "><="]


def _comment(rng: random.Random) -> str:
    odd = "".join(rng.choice(ODD_TEXT) for _ in range(rng.randrange(0, 6)))
    return rng.choice([f"' {odd}", f"'' {odd}", f"{{ {odd} }}", f"{{{{ {odd} }}}}", f"'' {odd} \"\"\" \\"])


def _atom(rng: random.Random, names) -> str:
    pick = rng.random()
    if pick < 0.3:
        return str(rng.randrange(-5, 50))
    if pick < 0.4:
        return odd_number(rng)
    if pick < 0.7:
        return rng.choice(names)
    if pick < 0.75:
        return rng.choice(["undefined_name", "v[99999]", "b.byte[3]", "cnt", "ina[3..0]", "outa[40]",
                           "spr[$10]", "$", "result", "long[0]", "word[@v][1]", "@v", "@@v", "c#K", "c.f(1)"])
    if pick < 0.85:
        return f"lookup({_atom(rng, names)}: 1, 2, {_atom(rng, names)}..{_atom(rng, names)})"
    if pick < 0.9:
        return f'string("{rng.choice(ODD_TEXT)}", {rng.randrange(300)})'
    return f"constant({_atom(rng, ['K', 'F', '1.5', '2'])} {rng.choice(BINARY[:20])} {_atom(rng, ['K', '0', '0.0', '-1'])})"


def _expr(rng: random.Random, names, depth: int = 0) -> str:
    if depth > 3 or rng.random() < 0.3:
        return _atom(rng, names)
    pick = rng.random()
    if pick < 0.2:
        op = rng.choice(UNARY)
        inner = _expr(rng, names, depth + 1)
        return f"{op}{inner})" if op.endswith("(") else (f"{inner}{op}" if op in ("++", "--", "~", "~~") and
                                                         rng.random() < 0.5 else f"{op}{inner}")
    if pick < 0.85:
        return f"{_expr(rng, names, depth + 1)} {rng.choice(BINARY)} {_expr(rng, names, depth + 1)}"
    return f"({_expr(rng, names, depth + 1)})"


def _stmt(rng: random.Random, names, indent: str, depth: int = 0) -> list:
    pick = rng.random()
    inner = indent + "  "
    if depth < 3 and pick < 0.12:
        out = [f"{indent}if {_expr(rng, names)}"] + _stmt(rng, names, inner, depth + 1)
        if rng.random() < 0.5:
            out += [f"{indent}else"] + _stmt(rng, names, inner, depth + 1)
        return out
    if depth < 3 and pick < 0.22:
        head = rng.choice(["repeat 3", f"repeat {_atom(rng, names)}", "repeat i from 0 to 3",
                           f"repeat i from {_atom(rng, names)} to {_atom(rng, names)} step {_atom(rng, names)}",
                           "repeat while i++ < 3", "repeat until i-- < -3", "repeat"])
        body = _stmt(rng, names, inner, depth + 1) + [rng.choice([f"{inner}quit", f"{inner}next", f"{inner}i++"])]
        return [f"{indent}{head}"] + body
    if depth < 3 and pick < 0.32:
        out = [f"{indent}case {_expr(rng, names)}"]
        for _ in range(rng.randrange(1, 4)):
            label = rng.choice([_atom(rng, names), f"{_atom(rng, names)}..{_atom(rng, names)}", "other"])
            out += [f"{inner}{label}:"] + _stmt(rng, names, inner + "  ", depth + 1)
        return out
    if pick < 0.4:
        return [f"{indent}{rng.choice(['return', 'abort'])} {_expr(rng, names)}"]
    if pick < 0.45:
        return [f"{indent}{_comment(rng)}"]
    if pick < 0.5:
        callee = rng.choice(["f", "g", "c.f", "main", "\\f", "c[1].f", "undefined"])
        return [f"{indent}{callee}({_expr(rng, names)})"]
    if pick < 0.55:
        return [f"{indent}{rng.choice(['cognew', 'coginit'])}({rng.choice(['g', 'f(1)', '@pasm', '0'])}, "
                f"{rng.choice(['@stack', '@stack[100]', '0', '@v'])}){'' if rng.random() < 0.5 else ''}"]
    if pick < 0.6:
        return [f"{indent}{rng.choice(['outa', 'dira', 'outb', 'ctra', 'spr[9]'])}"
                f"[{_atom(rng, names)}..{_atom(rng, names)}] := {_expr(rng, names)}"]
    if pick < 0.65:
        return [f"{indent}waitcnt({rng.choice(['cnt + 1000', '0', 'cnt', _expr(rng, names)])})"]
    if pick < 0.7:
        return [f"{indent}{rng.choice(['bytefill', 'longmove', 'wordfill', 'bytemove'])}"
                f"(@v, {_atom(rng, names)}, {_atom(rng, names)})"]
    target = rng.choice(names + ["v[1]", "b", "long[@v][2]", "result", "outa[0]", "spr[$1F]"])
    return [f"{indent}{target} {rng.choice([':=', '+=', '~>=', '|<', '~~', '++'])} {_expr(rng, names)}"
            .replace("|< ", "|< ").rstrip()]


def _dat(rng: random.Random, names) -> list:
    out = ["DAT" + rng.choice(["", "  ' data", " org 0"])]
    for _ in range(rng.randrange(1, 6)):
        pick = rng.random()
        if pick < 0.3:
            size = rng.choice(["byte", "word", "long"])
            items = ", ".join(rng.choice([str(rng.randrange(300)), odd_number(rng), "$-$", f"{_atom(rng, names)}",
                                          f"{rng.choice(['byte', 'word', 'long'])} 5", "1[3]",
                                          f"2[{rng.choice(['0', '-1', '100000', 'K'])}]", '"abc"'])
                              for _ in range(rng.randrange(1, 4)))
            out.append(f"{rng.choice(['', 'tbl', 'lambda', 'x'])} {size} {items}")
        elif pick < 0.6:
            out.append(f"pasm {rng.choice(['mov', 'add', 'jmp', 'djnz', 'rdlong', 'wrlong', 'call', 'cmp'])} "
                       f"{rng.choice(['x', '#5', 'outa', '#512', '#$1FF', 'pasm', '#undefined', '$'])}, "
                       f"{rng.choice(['#1', 'x', '#pasm', '#-1', '#$200', 'outa'])} "
                       f"{rng.choice(['', 'wc', 'wz wc', 'nr'])}")
        elif pick < 0.7:
            out.append(f"  {rng.choice(['res 4', 'res -1', 'res 100000', 'fit 496', 'fit', 'org $1F0', 'orgx'])}")
        elif pick < 0.8:
            out.append(f"  file \"{rng.choice(['missing.dat', 'child.spin', '', '../x'])}\"")
        else:
            out.append(f"x{rng.randrange(5)} long {_expr(rng, names)}")
    return out


def spin_program(rng: random.Random) -> tuple:
    """One odd Spin program: ``(top source, {child file name: child source})``.

    Three in five are meant to compile (:func:`valid_program`: only declared names,
    well-formed expressions, odd text only where Spin allows it), so that the
    compiler, the chip and the translator see them; the rest are almost valid.
    """
    if rng.random() < 0.6:
        return valid_program(rng)
    return _odd_program(rng)


def _odd_program(rng: random.Random) -> tuple:
    names = rng.sample(NAMES, rng.randrange(2, 6))
    lines = []
    if rng.random() < 0.5:
        lines.append(f"{{{{ {''.join(rng.choice(ODD_TEXT) for _ in range(rng.randrange(8)))} }}}}")
    if rng.random() < 0.3:
        lines += ["''" + "".join(rng.choice(ODD_TEXT) for _ in range(rng.randrange(8)))] * rng.randrange(1, 3)
    lines += ["CON", rng.choice(["  _clkmode = xtal1 + pll16x", "  _clkmode = rcfast", "  _clkmode = 0",
                                 "  _clkmode = xtal1 + xtal2"]),
              f"  _xinfreq = {rng.choice(['5_000_000', '0', '1', odd_number(rng)])}",
              f"  K = {_expr(rng, ['1', '2', '-1', '0'])}", f"  F = {rng.choice(['1.5', '0.0', '1e38', '-0.0'])}"]
    if rng.random() < 0.3:
        lines.append(f"  #{rng.choice(['0', '-1', '5'])}, A, B[{rng.choice(['2', '0', '-3'])}], C")
    lines += ["VAR", f"  long v[{rng.choice(['4', '1', 'K', '0', '100000'])}]", "  byte b", "  long stack[40]"]
    for n in names:
        if rng.random() < 0.4:
            lines.append(f"  word {n}")
    children = {}
    if rng.random() < 0.35:
        child = rng.choice(["child", "my-obj", "1abc", "class", "spin", "Child.Spin", "UPPER", "a b"])
        lines += ["OBJ", f"  c{rng.choice(['', '[2]', '[0]'])} : \"{child}\""]
        children[child + ("" if child.lower().endswith(".spin") else ".spin")] = "\n".join(
            ["CON", "  K = 3", "PUB f(a) : r", "  r := a + K" + rng.choice(["", "  '\"\"\"", "  ' \\"]),
             "PUB lambda", "  return 1"]) + "\n"
    locals_ = ", ".join(rng.sample(["i", "j", "t", "None", "class", "k"], rng.randrange(1, 4)))
    lines.append(f"PUB main | {locals_}" + rng.choice(["", "[3]", " ' main"]))
    if rng.random() < 0.3:
        lines.append("  " + _comment(rng))
    for _ in range(rng.randrange(1, 7)):
        lines += _stmt(rng, names + ["i", "j", "t"], "  ")
    if rng.random() < 0.8:
        lines.append(rng.choice(["  cogstop(cogid)", "  repeat", "  return", "  reboot"]))
    lines += [f"PUB f(a{rng.choice(['', ', b', ', lambda'])}) : r{rng.choice(['', ' | q', ' | q[5]'])}",
              "  " + _comment(rng), f"  r := {_expr(rng, names + ['a'])}",
              "PRI g", f"  repeat {rng.randrange(1, 3)}", "    outa[1]~~"]
    if rng.random() < 0.6:
        lines += _dat(rng, names)
    text = "\n".join(lines) + rng.choice(["\n", "", "\n\n", "\n  "])
    return text, children


# ----------------------------------------------------------------------------- programs meant to compile
#: Spin names that are Python keywords, builtins or names the translator itself uses
VALID_NAMES = ["x", "count", "lambda", "class", "None", "self", "print", "spin", "Frame", "cog", "wrap", "def",
               "import", "yield", "await", "async", "from_", "pass", "chip", "hub", "int", "len", "object",
               "type", "list", "__init__", "_x", "A" * 100, "is_", "global_", "nonlocal", "raise", "with"]
#: text that may stand in a comment of each kind
_LINE_TEXT = [t for t in ODD_TEXT if t not in ("\r", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85",
                                             "\u2028", "\u2029", "\x00", "\x1a")]
_BLOCK_TEXT = [t for t in _LINE_TEXT if "{" not in t and "}" not in t]
_SAFE_BINARY = ["+", "-", "*", "**", "/", "//", "#>", "<#", "~>", "<<", ">>", "<-", "->", "><", "&", "|", "^",
                "and", "or", "==", "<>", "<", ">", "=<", "=>"]


def _text(rng, pool) -> str:
    return "".join(rng.choice(pool) for _ in range(rng.randrange(0, 6)))


def _valid_comment(rng) -> str:
    return rng.choice([f"' {_text(rng, _LINE_TEXT)}", f"'' {_text(rng, _LINE_TEXT)}",
                       f"{{ {_text(rng, _BLOCK_TEXT)} }}", f"{{{{ {_text(rng, _BLOCK_TEXT)} }}}}"])


def _v_atom(rng, names, child) -> str:
    pick = rng.random()
    if pick < 0.3:
        return str(rng.choice([0, 1, 2, 3, 7, 31, 32, 255, -1, 1000, 0x7FFFFFFF, -0x80000000]))
    if pick < 0.6:
        return rng.choice(names)
    if pick < 0.7:
        return rng.choice(["v[1]", "v[x & 3]", "cnt", "ina[3]", "ina[7..4]", "outa[0]", "@v", "@v[2]",
                           "long[@v][1]", "byte[@v]", "word[@v][3]", "v.byte[1]", "result", "clkfreq"])
    if pick < 0.8:
        return f"lookup{rng.choice(['', 'z'])}({rng.choice(names)} & 3: 10, 20, {rng.randrange(9)}..{rng.randrange(9)})"
    if pick < 0.85 and child:
        return rng.choice(["c.f(2)", "c#K", "c.lambda", "constant(c#K * 2)"])
    if pick < 0.9:
        return f'string("{rng.choice(["abc", "a b", "q" * 40])}")'
    return f"constant({rng.randrange(100)} {rng.choice(_SAFE_BINARY[:6])} {rng.randrange(1, 9)})"


def _v_expr(rng, names, child, depth=0) -> str:
    if depth > 3 or rng.random() < 0.35:
        return _v_atom(rng, names, child)
    pick = rng.random()
    if pick < 0.15:
        return rng.choice(["-", "!", "||", "|<", ">|", "^^"]) + f"({_v_expr(rng, names, child, depth + 1)})"
    if pick < 0.25:
        name = rng.choice(names)
        return rng.choice([f"{name}++", f"--{name}", f"{name}~", f"{name}~~", f"?{name}", f"({name} += 3)",
                           f"({name} := {_v_atom(rng, names, child)})"])
    if pick < 0.9:
        return f"{_v_expr(rng, names, child, depth + 1)} {rng.choice(_SAFE_BINARY)} {_v_expr(rng, names, child, depth + 1)}"
    return f"({_v_expr(rng, names, child, depth + 1)})"


def _v_body(rng, names, child, indent, depth, loop) -> list:
    """A block's statements: at least one that is not a comment."""
    out = _v_stmt(rng, names, child, indent, depth, loop)
    if all(ln.strip().startswith(("'", "{")) for ln in out):
        out.append(f"{indent}x++")
    return out


def _v_stmt(rng, names, child, indent, depth=0, loop=False) -> list:
    inner = indent + "  "
    pick = rng.random()
    e = lambda: _v_expr(rng, names, child)  # noqa: E731
    if depth < 3 and pick < 0.15:
        out = [f"{indent}{rng.choice(['if', 'ifnot'])} {e()}"] + _v_body(rng, names, child, inner, depth + 1, loop)
        if rng.random() < 0.4:
            out += [f"{indent}elseif {e()}"] + _v_body(rng, names, child, inner, depth + 1, loop)
        if rng.random() < 0.5:
            out += [f"{indent}else"] + _v_body(rng, names, child, inner, depth + 1, loop)
        return out
    if depth < 3 and pick < 0.27:
        var = rng.choice(names)
        head = rng.choice(["repeat 3", f"repeat {var} from 0 to 3", f"repeat {var} from 5 to 1 step 2",
                           f"repeat while {var}++ < 3", f"repeat until {var}-- < 1", "repeat (x & 3)"])
        body = _v_body(rng, names, child, inner, depth + 1, True)
        return [f"{indent}{head}"] + body + ([f"{inner}{rng.choice(['quit', 'next'])}"] if rng.random() < 0.3 else [])
    if depth < 3 and pick < 0.37:
        out = [f"{indent}case {e()}"]
        labels = rng.sample(["0", "1", "2..4", "-1", "10, 11"], rng.randrange(1, 4))
        for label in labels + (["other"] if rng.random() < 0.4 else []):
            out += [f"{inner}{label}:"] + _v_body(rng, names, child, inner + "  ", depth + 1, loop)
        return out
    if pick < 0.42:
        return [f"{indent}{_valid_comment(rng)}"]
    if pick < 0.47:
        callee = rng.choice(["f", "\\f"])
        return [f"{indent}{callee}({e()})" if rng.random() < 0.5 else f"{indent}g"]
    if pick < 0.52 and child:
        call = rng.choice(["c.f(1)", "x := c.lambda", "x := \\c.f(x)"])
        return [f"{indent}{call}"]
    if pick < 0.57:
        hi, lo = sorted(rng.sample(range(32), 2), reverse=True)
        return [f"{indent}{rng.choice(['outa', 'dira'])}[{hi}..{lo}] := {e()}"]
    if pick < 0.6:
        return [f"{indent}waitcnt(cnt + {rng.choice([400, 1000, 5000])})"]
    if pick < 0.63:
        return [f"{indent}{rng.choice(['bytefill(@v, 0, 4)', 'longmove(@v, @v[1], 2)', 'wordfill(@v, 7, 2)'])}"]
    if pick < 0.66 and loop:
        return [f"{indent}{rng.choice(['quit', 'next'])}"]
    target = rng.choice(names + ["v[1]", "v[x & 3]", "long[@v][2]", "result", "outa[3]"])
    return [f"{indent}{target} {rng.choice([':=', '+=', '-=', '&=', '|=', '^=', '#>=', '<#=', '->='])} {e()}"]


def valid_program(rng: random.Random) -> tuple:
    """A Spin program meant to compile, full of names and comment text that are odd for Python."""
    names = ["x"] + rng.sample(VALID_NAMES[1:], rng.randrange(1, 6))
    lines = []
    if rng.random() < 0.6:
        lines.append(f"{{{{ {_text(rng, _BLOCK_TEXT)}\n   {_text(rng, _BLOCK_TEXT)} }}}}")
    if rng.random() < 0.4:
        lines += ["'' " + _text(rng, _LINE_TEXT) for _ in range(rng.randrange(1, 3))]
    lines += ["CON", rng.choice(["  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000", "  _clkmode = rcfast",
                                 "  _clkmode = xinput\n  _xinfreq = 0", ""]).rstrip(),
              f"  K = {rng.randrange(1, 9)} {_valid_comment(rng)}", "  FLT = 1.5"]
    lines += ["VAR", "  long v[4]"] + [f"  long {n}" for n in names[1:]]
    child = rng.random() < 0.3
    children = {}
    if child:
        name = rng.choice(["child", "my-obj", "1abc", "class", "spin", "UPPER", "a b", "import"])
        lines += ["OBJ", f"  c : \"{name}\""]
        children[name + ".spin"] = ("CON\n  K = 3\nPUB f(a) : r\n  '' doc \"\"\" \\\n  r := a + K\n"
                                    "PUB lambda\n  return 1\n")
    lines.append("PUB main | " + ", ".join(["x"] + rng.sample(["i", "tmp", "lambda_", "t"], rng.randrange(0, 3))))
    if rng.random() < 0.5:
        lines += ["  '' " + _text(rng, _LINE_TEXT) for _ in range(rng.randrange(1, 3))]
    for _ in range(rng.randrange(1, 8)):
        lines += _v_stmt(rng, names, child, "  ")
    lines.append(rng.choice(["  cogstop(cogid)", "  repeat", "  return", ""]))
    lines += ["PUB f(a) : r", f"  {_valid_comment(rng)}", f"  r := a * {rng.randrange(1, 5)} + K",
              "PRI g", "  repeat 2", "    outa[1]~~", "    outa[1]~"]
    if rng.random() < 0.5:
        lines += ["DAT", f"tbl long 1, 2, {rng.randrange(100)}  {_valid_comment(rng)}",
                  "    byte \"abc\", 0", "    word $FFFF[2]"]
        if rng.random() < 0.5:
            lines += ["    org 0", "entry mov dira, #1", "    jmp #entry"]
    return "\n".join(ln for ln in lines if ln is not None) + "\n", children
