"""A serial terminal as text: the BASIC Stamp Debug Terminal and Parallax Serial Terminal codes.

Both terminals read a byte stream with the same control characters (BASIC
Stamp Syntax and Reference Manual v2.2, DEBUG, table "DEBUG control
characters"; the Parallax Serial Terminal keeps them and adds 16 for clear
screen): CLS 0, HOME 1, CRSRXY 2 x y, CRSRLF 3, CRSRRT 4, CRSRUP 5, CRSRDN 6,
BELL 7, BKSP 8, TAB 9, LF 10, CLREOL 11, CLRDN 12, CR 13, CRSRX 14 x,
CRSRY 15 y.

:class:`TextStream` turns such a stream into plain text for a console as it
arrives (CR, CR LF and LF start a new line, TAB is kept, cursor controls and
the other control characters are dropped), :func:`stream_text` does it for a
whole stream, and :func:`screen` replays it on a virtual screen and returns
the lines the terminal would show.
"""
from __future__ import annotations

__all__ = ["TextStream", "stream_text", "screen"]


class TextStream:
    """Console rendering of a terminal byte stream that arrives in pieces.

    A CR at the end of one piece and an LF at the start of the next make one
    new line; a cursor command split across pieces still swallows its
    argument bytes.

    >>> s = TextStream()
    >>> s.feed(b"x = 5\\r") + s.feed(b"\\ndone\\x07\\x02")  + s.feed(b"\\x03\\x04!")
    'x = 5\\ndone!'
    """

    def __init__(self):
        self._after_cr = False
        self._skip = 0

    def feed(self, data: bytes) -> str:
        """The text ``data`` adds."""
        out = []
        for b in data:
            if self._skip:
                self._skip -= 1
                continue
            after_cr, self._after_cr = self._after_cr, False
            if b == 13:
                out.append("\n")
                self._after_cr = True
            elif b == 10:
                if not after_cr:
                    out.append("\n")
            elif b == 9:
                out.append("\t")
            elif b == 2:
                self._skip = 2                  # CRSRXY x y
            elif b in (14, 15):
                self._skip = 1                  # CRSRX x / CRSRY y
            elif b >= 32:
                out.append(chr(b))
        return "".join(out)


def stream_text(data: bytes) -> str:
    """Console rendering of a whole stream (see :class:`TextStream`).

    >>> stream_text(b"x = 5\\rdone\\x07")
    'x = 5\\ndone'
    """
    return TextStream().feed(data)


def screen(data: bytes, width: int = 80, height: int = 24) -> list[str]:
    """The Debug Terminal's screen after receiving ``data`` (trailing blanks removed).

    >>> screen(b"abc\\x02\\x01\\x00Z")      # CRSRXY 1, 0 then "Z"
    ['aZc']
    """
    rows = [[" "] * width for _ in range(height)]
    x = y = 0

    def scroll():
        nonlocal y
        while y >= height:
            rows.pop(0)
            rows.append([" "] * width)
            y -= 1

    i, n = 0, len(data)
    while i < n:
        b = data[i]
        if b == 0:
            rows = [[" "] * width for _ in range(height)]
            x = y = 0
        elif b == 1:
            x = y = 0
        elif b == 2 and i + 2 < n:
            x, y = min(data[i + 1], width - 1), min(data[i + 2], height - 1)
            i += 2
        elif b == 3:
            x = max(0, x - 1)
        elif b == 4:
            x = min(width - 1, x + 1)
        elif b == 5:
            y = max(0, y - 1)
        elif b == 6 or b == 10:
            y += 1
            scroll()
        elif b == 7:
            pass
        elif b == 8:
            if x > 0:
                x -= 1
                rows[y][x] = " "
        elif b == 9:
            x = min(width - 1, (x // 8 + 1) * 8)
        elif b == 11:
            rows[y][x:] = [" "] * (width - x)
        elif b == 12:
            rows[y][x:] = [" "] * (width - x)
            for r in range(y + 1, height):
                rows[r] = [" "] * width
        elif b == 13:
            x = 0
            y += 1
            scroll()
        elif b == 14 and i + 1 < n:
            x = min(data[i + 1], width - 1)
            i += 1
        elif b == 15 and i + 1 < n:
            y = min(data[i + 1], height - 1)
            i += 1
        elif b >= 32:
            if x >= width:
                x = 0
                y += 1
                scroll()
            rows[y][x] = chr(b)
            x += 1
        i += 1
    lines = ["".join(r).rstrip() for r in rows]
    while lines and not lines[-1]:
        lines.pop()
    return lines
