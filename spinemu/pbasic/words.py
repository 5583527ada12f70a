"""The fixed vocabulary of PBASIC 2.5 on the BS2: reserved words, predefined
variables and constants.

Sources: BASIC Stamp Syntax and Reference Manual v2.2, chapter 4 (memory map,
"Predefined variable names", "Reserved words") and the command pages that
define symbols (SHIFTIN/SHIFTOUT modes, DEBUG control characters, XOUT
commands).  Values of the X-10 command constants follow the XOUT page.
"""
from __future__ import annotations

__all__ = [
    "RESERVED", "describe_reserved", "OTHER_STAMP_COMMANDS", "PREDEFINED_CONSTANTS",
    "predefined_variables", "MODIFIERS",
]

COMMANDS = """BRANCH BUTTON COUNT DEBUG DEBUGIN DO DTMFOUT ELSE ELSEIF END ENDIF
ENDSELECT EXIT FOR FREQOUT GOSUB GOTO HIGH IF INPUT LOOKDOWN LOOKUP LOOP LOW NAP
NEXT ON OUTPUT PAUSE PULSIN PULSOUT PWM RANDOM RCTIME READ RETURN REVERSE SELECT
CASE SERIN SEROUT SHIFTIN SHIFTOUT SLEEP STOP TOGGLE WRITE XOUT""".split()
KEYWORDS = "THEN TO STEP WHILE UNTIL VAR CON PIN DATA BIT NIB BYTE WORD".split()
LOGIC = "AND OR XOR NOT".split()
UNARY = "ABS SQR DCD NCD COS SIN".split()
BINARY = "MIN MAX DIG REV ATN HYP".split()
FORMAT_WORDS = "ASC STR REP SKIP WAIT WAITSTR".split()


def _formatters() -> list[str]:
    out = []
    for base, n in (("DEC", 5), ("SDEC", 5), ("HEX", 4), ("SHEX", 4), ("IHEX", 4),
                    ("ISHEX", 4), ("BIN", 16), ("SBIN", 16), ("IBIN", 16), ("ISBIN", 16)):
        out.append(base)
        out.extend(f"{base}{i}" for i in range(1, n + 1))
    return out


FORMATTERS = _formatters()

#: Variable modifiers: name -> (size in bits, index); index None means HIGH*
MODIFIERS = {"LOWBYTE": (8, 0), "HIGHBYTE": (8, None), "BYTE0": (8, 0), "BYTE1": (8, 1),
             "LOWNIB": (4, 0), "HIGHNIB": (4, None), "LOWBIT": (1, 0), "HIGHBIT": (1, None)}
MODIFIERS.update({f"NIB{i}": (4, i) for i in range(4)})
MODIFIERS.update({f"BIT{i}": (1, i) for i in range(16)})

RESERVED: dict[str, str] = {}
for _w in COMMANDS:
    RESERVED[_w] = "an instruction"
for _w in KEYWORDS:
    RESERVED[_w] = "a keyword"
for _w in LOGIC:
    RESERVED[_w] = "a condition operator (only allowed in IF/ELSEIF/WHILE/UNTIL)"
for _w in UNARY:
    RESERVED[_w] = "a unary operator"
for _w in BINARY:
    RESERVED[_w] = f"a binary operator (x {_w} y)"
for _w in FORMAT_WORDS + FORMATTERS:
    RESERVED[_w] = "a DEBUG/SERIN/SEROUT formatter"
for _w in MODIFIERS:
    RESERVED[_w] = "a variable modifier"


def describe_reserved(word: str) -> str:
    return RESERVED.get(word.upper(), "a reserved word")


#: Instructions of other BASIC Stamps, so that using one says so.
OTHER_STAMP_COMMANDS = {
    **{w: "BS2e, BS2sx, BS2p, BS2pe and BS2px" for w in ("GET", "PUT", "RUN")},
    **{w: "BS2p, BS2pe and BS2px" for w in (
        "STORE", "IOTERM", "AUXIO", "MAINIO", "POLLIN", "POLLOUT", "POLLMODE", "POLLRUN",
        "POLLWAIT", "I2CIN", "I2COUT", "LCDCMD", "LCDIN", "LCDOUT", "OWIN", "OWOUT")},
    **{w: "BS2px" for w in ("COMPARE", "CONFIGPIN")},
    **{w: "BS1" for w in ("SOUND", "POT", "EEPROM", "SYMBOL", "LET")},
}

#: Predefined constants of PBASIC 2.5 on the BS2.
PREDEFINED_CONSTANTS = {
    # DEBUG control characters (DEBUG command page, table "DEBUG control characters")
    "CLS": 0, "HOME": 1, "CRSRXY": 2, "CRSRLF": 3, "CRSRRT": 4, "CRSRUP": 5, "CRSRDN": 6,
    "BELL": 7, "BKSP": 8, "TAB": 9, "LF": 10, "CLREOL": 11, "CLRDN": 12, "CR": 13,
    "CRSRX": 14, "CRSRY": 15,
    # SHIFTOUT / SHIFTIN modes
    "LSBFIRST": 0, "MSBFIRST": 1, "MSBPRE": 0, "LSBPRE": 1, "MSBPOST": 2, "LSBPOST": 3,
    # XOUT commands (X-10 function codes, XOUT command page)
    "UNITON": 0b10010, "UNITOFF": 0b11010, "UNITSOFF": 0b11100, "LIGHTSON": 0b10100,
    "DIM": 0b11110, "BRIGHT": 0b10110,
}


def predefined_variables() -> dict[str, tuple[int, int]]:
    """Fixed RAM names: name -> (bit offset, width in bits).

    Word 0 is INS, 1 OUTS, 2 DIRS, 3..15 are W0..W12 (bytes B0..B25).

    >>> v = predefined_variables()
    >>> v["OUTB"], v["DIR7"], v["B0"], v["W12"]
    ((20, 4), (39, 1), (48, 8), (240, 16))
    """
    out: dict[str, tuple[int, int]] = {}
    for word, (w, lo, hi, nib, bit) in enumerate((
            ("INS", "INL", "INH", "IN", "IN"), ("OUTS", "OUTL", "OUTH", "OUT", "OUT"),
            ("DIRS", "DIRL", "DIRH", "DIR", "DIR"))):
        base = word * 16
        out[w] = (base, 16)
        out[lo] = (base, 8)
        out[hi] = (base + 8, 8)
        for i, letter in enumerate("ABCD"):
            out[f"{nib}{letter}"] = (base + 4 * i, 4)
        for i in range(16):
            out[f"{bit}{i}"] = (base + i, 1)
    for i in range(13):
        out[f"W{i}"] = (48 + 16 * i, 16)
    for i in range(26):
        out[f"B{i}"] = (48 + 8 * i, 8)
    return out
