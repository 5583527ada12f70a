"""Mutations of source text and bytes, the way a new user's files go wrong.

Line mutations (delete, duplicate, swap, re-indent, truncate), token
mutations (a random keyword, operator, number or odd string put in, a token
replaced or deleted), huge and malformed numbers, deep nesting, comments and
strings holding quote marks and backslashes, odd characters (control
characters, NUL, non-ASCII letters), other line endings, and finally other
encodings (UTF-8 with a BOM, UTF-16 with and without a BOM, Latin-1, an odd
byte count) and raw byte flips.  Every function takes a ``random.Random`` and
returns the new text or bytes; nothing here knows about spinemu.
"""
from __future__ import annotations

import random
import re

__all__ = ["Pools", "SPIN", "PBASIC", "mutate_text", "encode", "flip_bytes", "odd_number"]

_TOKEN = re.compile(r"[A-Za-z_][A-Za-z_0-9]*|\$[0-9A-Fa-f_]+|%%?[0-4_]+|\d[\d_.eE]*|:=|[^\sA-Za-z_0-9]")

ODD_TEXT = ['"""', "'''", "\\", "\\n", "\\x00", "{", "}", "{{", "}}", "\"", "'", "''", "\t", "\x00", "\x1a",
            "\x7f", "\u00e9", "\u00fc", "\u2028", "\u0085", "\ufeff", "\U0001f600", "\ud7ff", "#", "$", "%",
            "@@", "`", "~", "\r", "\x0c", "\x0b", "{ ", " }", "}}}}", "\"\"\"\"\"\"", "\\\"\"\"", "%%"]


class Pools:
    """The words a mutation inserts for one language."""

    def __init__(self, keywords, operators, snippets):
        self.keywords = list(keywords)
        self.operators = list(operators)
        self.snippets = list(snippets)


SPIN = Pools(
    keywords="""CON VAR OBJ PUB PRI DAT if elseif elseifnot else ifnot repeat while until from to step next
        quit return abort case other lookup lookupz lookdown lookdownz byte word long string constant float
        round trunc cognew coginit cogstop cogid locknew lockset lockclr lockret waitcnt waitpeq waitpne
        waitvid reboot strsize strcomp bytefill wordfill longfill bytemove wordmove longmove result spr dira
        dirb outa outb ina inb cnt clkfreq clkmode chipver clkset par ctra ctrb frqa frqb phsa phsb vcfg vscl
        _clkmode _xinfreq _clkfreq _stack _free org orgx res fit file mov add sub jmp call ret djnz wrlong
        rdlong cmp if_z if_nc wc wz nr wr true false posx negx pi rcfast xtal1 pll16x not and or self class
        lambda None def print import __init__ spin Frame""".split(),
    operators=""":= + - * / // ** ~ ~~ ++ -- ? ! @ @@ # ^^ || |< >| <- -> ~> >< & | ^ == <> < > =< => +=
        -= *= /= //= **= <<= >>= ~>= ->= <-= ><= &= |= ^= and= or= := ( ) [ ] , : . .. \\ $ = <<
        >> #> <# #>= <#= -- ++""".split(),
    snippets=["x := 1", "repeat 3", "  outa[0] := 1", "result := 0", "return", "abort 5", "case x",
              "  1: y := 2", "  other: y := 3", "DAT org 0", "long 1, 2, 3", "byte \"hi\", 0",
              "word $FFFF[10]", "PUB f(a, b) : r | c", "PRI g", "OBJ c : \"child\"", "CON K = 1/0",
              "VAR long v[10]", "x := lookup(2: 1, 2, 3)", "x := y // 0", "x := ((((((1))))))",
              "cognew(f, @stack)", "{{ doc \"\"\" \\ }}", "' comment \"\"\" \\", "x := string(\"a\\b\")",
              "waitcnt(cnt + 1000)", "repeat i from 0 to 10 step 0", "x := @@0", "spr[20] := 1",
              "outa[31..0] := -1", "dira[40] := 1", "x := constant(1.0 / 0.0)", "x := float(1)",
              "if x", "else", "elseif y", "next", "quit", "x := 1 #> 2 <# 3"],
)

PBASIC = Pools(
    keywords="""HIGH LOW TOGGLE PAUSE GOTO GOSUB RETURN FOR TO STEP NEXT IF THEN ELSE ELSEIF ENDIF DO LOOP WHILE
        UNTIL SELECT CASE ENDSELECT DEBUG DEBUGIN SERIN SEROUT PULSOUT PULSIN RCTIME FREQOUT BUTTON COUNT
        SHIFTIN SHIFTOUT READ WRITE DATA VAR CON PIN LOOKUP LOOKDOWN BRANCH ON END STOP NAP SLEEP INPUT OUTPUT
        REVERSE RANDOM EXIT Bit Nib Byte Word DEC HEX BIN CR CLS STR SDEC IHEX ASC OUTA OUTB OUTC OUTD OUTH
        OUTL INS OUTS DIRS IN0 OUT15 DIR7 W0 B1 INA DCD NCD SQR ABS COS SIN ATN HYP MIN MAX REP WAIT SKIP
        LSB MSB LOWBIT HIGHBIT LOWNIB HIGHNIB AND OR XOR NOT PWM POLLIN RUN GET PUT""".split(),
    operators="""= + - * ** */ / // << >> & | ^ &/ |/ ^/ ~ <> < > <= >= , : ( ) ? [ ] . ' # @ $ % \\ "
        {$STAMP BS2} {$PBASIC 2.5} {$PBASIC 2.0} {$STAMP BS2SX} {$PORT COM1}""".split(),
    snippets=["x VAR Byte", "y VAR Word", "K CON 10", "Led PIN 15", "HIGH 0", "PAUSE 100", "GOTO Main",
              "Main:", "FOR x = 0 TO 10", "NEXT", "DEBUG DEC x, CR", "DO", "LOOP", "IF x > 1 THEN",
              "ENDIF", "SELECT x", "CASE 1", "ENDSELECT", "SEROUT 16, 84, [\"hi\"]", "DEBUGIN DEC x",
              "x = x / 0", "x = 65535 * 65535", "t DATA \"abc\", 0", "READ t + 1000, x", "GOSUB Sub",
              "Sub:", "RETURN", "END", "x = LOOKUP 9, [1, 2]", "BRANCH x, [Main]", "PULSOUT 0, 65535",
              "FREQOUT 0, 1000, 65535", "x VAR Bit(400)", "ON x GOTO Main", "w VAR Word(13)"],
)


def odd_number(rng: random.Random) -> str:
    """A number a user might type that is too big, too small, or not quite a number."""
    return rng.choice([
        "99999999999999999999999999999999", "4294967296", "4294967295", "2147483648", "-2147483649",
        "$FFFFFFFFF", "$1_0000_0000", "%" + "1" * 40, "%%" + "3" * 20, "%%4", "%2", "$G", "$", "%", "%%",
        "1e39", "3.4e38", "1.0e-50", "1.0e50", "0.0", "1.", ".5", "1e", "1_", "_1", "1__0", "0x10", "1.5e+",
        "123456789012345678901234567890.0", "1" * 400, "$" + "F" * 300, "9" * 5000, "1e-400", "2.5e-45",
        str(rng.randrange(-2 ** 40, 2 ** 40)), str(rng.random() * 10 ** rng.randrange(-40, 40)),
    ])


def _lines(text: str) -> list:
    return text.splitlines(keepends=True) or [""]


def _deep(rng: random.Random, lang: str) -> str:
    depth = rng.choice([30, 100, 300, 1000, 3000])
    if rng.random() < 0.5:
        expr = "(" * depth + "1" + ")" * depth
    else:
        expr = " + ".join(["1"] * depth) if rng.random() < 0.5 else "-" * depth + "1"
    if lang == "spin":
        if rng.random() < 0.3:
            body = "".join("  " * (i + 1) + "if 1\n" for i in range(min(depth, 400)))
            return "PUB deep | x\n" + body + "  " * (min(depth, 400) + 1) + "x := 1\n"
        return f"PUB deep | x\n  x := {expr}\n" if rng.random() < 0.7 else f"CON\n  DEEP = {expr}\n"
    return f"x VAR Word\nx = {expr}\n"


def mutate_text(rng: random.Random, text: str, pools: Pools, lang: str, rounds: int = 0) -> str:
    """Apply 1-4 random mutations to ``text`` (``lang``: ``"spin"`` or ``"pbasic"``).

    Two times in five only mild ones (a name or number changed, a line deleted,
    duplicated or re-indented, a comment added): the result often still compiles
    and then runs, so the later stages see mutants too.
    """
    ops = _MILD_OPS if rng.random() < 0.4 else _TEXT_OPS
    for _ in range(rounds or rng.choice([1, 1, 1, 2, 2, 3, 4])):
        text = rng.choice(ops)(rng, text, pools, lang)
    return text


def _delete_lines(rng, text, pools, lang):
    lines = _lines(text)
    i = rng.randrange(len(lines))
    del lines[i: i + rng.choice([1, 1, 2, 5, 20])]
    return "".join(lines)


def _duplicate_lines(rng, text, pools, lang):
    lines = _lines(text)
    i = rng.randrange(len(lines))
    n = rng.choice([1, 1, 3, 10])
    return "".join(lines[:i] + lines[i: i + n] * rng.choice([2, 2, 3, 50]) + lines[i + n:])


def _swap_lines(rng, text, pools, lang):
    lines = _lines(text)
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    lines[i], lines[j] = lines[j], lines[i]
    return "".join(lines)


def _reindent(rng, text, pools, lang):
    lines = _lines(text)
    i = rng.randrange(len(lines))
    body = lines[i].lstrip(" \t")
    lines[i] = rng.choice(["", " ", "  ", "\t", " \t", "    " * rng.randrange(1, 12), "\t" * 3]) + body
    return "".join(lines)


def _truncate(rng, text, pools, lang):
    return text[: rng.randrange(len(text) + 1)]


def _tokens(text):
    return [m.span() for m in _TOKEN.finditer(text)]


def _insert_word(rng, text, pools, lang):
    pick = rng.random()
    if pick < 0.35:
        word = rng.choice(pools.keywords)
    elif pick < 0.6:
        word = rng.choice(pools.operators)
    elif pick < 0.75:
        word = odd_number(rng)
    elif pick < 0.9:
        word = rng.choice(ODD_TEXT)
    else:
        word = "\n" + rng.choice(pools.snippets) + "\n"
    at = rng.randrange(len(text) + 1)
    sep = rng.choice(["", " ", " "])
    return text[:at] + sep + word + sep + text[at:]


def _replace_token(rng, text, pools, lang):
    spans = _tokens(text)
    if not spans:
        return _insert_word(rng, text, pools, lang)
    a, b = rng.choice(spans)
    word = rng.choice([rng.choice(pools.keywords), rng.choice(pools.operators), odd_number(rng), ""])
    return text[:a] + word + text[b:]


def _replace_number(rng, text, pools, lang):
    spans = [(a, b) for a, b in _tokens(text) if text[a] in "0123456789$%"]
    if not spans:
        return _insert_word(rng, text, pools, lang)
    a, b = rng.choice(spans)
    return text[:a] + odd_number(rng) + text[b:]


def _swap_name(rng, text, pools, lang):
    """A name replaced by another name of the same file: still parses, often still compiles."""
    spans = [(a, b) for a, b in _tokens(text) if text[a].isalpha() or text[a] == "_"]
    if len(spans) < 2:
        return _insert_word(rng, text, pools, lang)
    a, b = rng.choice(spans)
    c, d = rng.choice(spans)
    return text[:a] + text[c:d] + text[b:]


def _nudge_number(rng, text, pools, lang):
    """A number changed to a nearby or edge value of the same shape: still parses."""
    spans = [(a, b) for a, b in _tokens(text) if text[a].isdigit()]
    if not spans:
        return _swap_name(rng, text, pools, lang)
    a, b = rng.choice(spans)
    new = rng.choice(["0", "1", "-1", "2", "31", "32", "33", "255", "256", "511", "512", "65535", "65536",
                      "2147483647", "80_000_000", str(rng.randrange(100))])
    return text[:a] + new + text[b:]


def _insert_line(rng, text, pools, lang):
    lines = _lines(text)
    i = rng.randrange(len(lines) + 1)
    indent = rng.choice(["", "  ", "    ", "\t"])
    if rng.random() < 0.15:
        new = _deep(rng, lang)
    else:
        new = indent + rng.choice(pools.snippets) + "\n"
    return "".join(lines[:i] + [new] + lines[i:])


def _odd_comment(rng, text, pools, lang):
    odd = "".join(rng.choice(ODD_TEXT) for _ in range(rng.randrange(1, 6)))
    if lang == "spin":
        comment = rng.choice([f"' {odd}", f"'' {odd}", f"{{ {odd} }}", f"{{{{ {odd} }}}}", f"{{{{\n{odd}\n}}}}"])
    else:
        comment = f"' {odd}"
    lines = _lines(text)
    i = rng.randrange(len(lines) + 1)
    if rng.random() < 0.5 and i < len(lines):
        lines[i] = lines[i].rstrip("\r\n") + " " + comment + "\n"
    else:
        lines.insert(i, comment + "\n")
    return "".join(lines)


def _odd_string(rng, text, pools, lang):
    odd = "".join(rng.choice(ODD_TEXT) for _ in range(rng.randrange(1, 5)))
    spans = [m.span() for m in re.finditer(r'"[^"\n]*"', text)]
    if spans:
        a, b = rng.choice(spans)
        return text[:a] + '"' + odd + '"' + text[b:]
    return _insert_word(rng, text, pools, lang)


def _line_endings(rng, text, pools, lang):
    return text.replace("\r\n", "\n").replace("\n", rng.choice(["\r\n", "\r", "\n\r", "\x0c\n", "\u2028"]))


def _odd_char(rng, text, pools, lang):
    at = rng.randrange(len(text) + 1)
    return text[:at] + rng.choice(ODD_TEXT[9:] + [chr(rng.randrange(0x20)), chr(rng.randrange(0x80, 0x3000))]) + text[at:]


_TEXT_OPS = [_swap_name, _swap_name, _nudge_number, _nudge_number, _delete_lines, _delete_lines, _duplicate_lines, _swap_lines, _reindent, _truncate, _insert_word,
             _insert_word, _insert_word, _replace_token, _replace_token, _replace_number, _insert_line,
             _insert_line, _odd_comment, _odd_string, _line_endings, _odd_char]


_MILD_OPS = [_swap_name, _nudge_number, _nudge_number, _delete_lines, _duplicate_lines, _odd_comment]


def encode(rng: random.Random, text: str) -> bytes:
    """``text`` as bytes: mostly UTF-8, sometimes another encoding or a BOM a Windows editor writes."""
    pick = rng.random()
    if pick < 0.7:
        return text.encode("utf-8", "surrogatepass")
    if pick < 0.75:
        return b"\xef\xbb\xbf" + text.encode("utf-8", "surrogatepass")
    if pick < 0.82:
        return text.encode("utf-16", "surrogatepass")                  # with a BOM
    if pick < 0.86:
        return text.encode("utf-16-le", "surrogatepass")               # no BOM
    if pick < 0.88:
        return text.encode("utf-16-be", "surrogatepass")
    if pick < 0.91:
        data = text.encode("utf-16", "surrogatepass")
        return data[:-1] if len(data) > 2 else data + b"\x00"          # an odd byte count
    if pick < 0.96:
        return text.encode("latin-1", "replace")
    return text.encode("utf-32", "surrogatepass")


def flip_bytes(rng: random.Random, data: bytes, count: int = 0) -> bytes:
    """Overwrite, insert or delete a few random bytes."""
    buf = bytearray(data)
    for _ in range(count or rng.choice([1, 1, 2, 4, 16])):
        op = rng.random()
        at = rng.randrange(len(buf) + 1)
        if op < 0.6 and at < len(buf):
            buf[at] = rng.randrange(256) if rng.random() < 0.7 else buf[at] ^ (1 << rng.randrange(8))
        elif op < 0.8:
            buf[at:at] = bytes(rng.randrange(256) for _ in range(rng.choice([1, 2, 4])))
        else:
            del buf[at: at + rng.choice([1, 2, 4])]
    return bytes(buf)
