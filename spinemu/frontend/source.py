"""Reading Spin source files: encodings, line endings and positions.

The Propeller Tool saves sources as UTF-8 or as UTF-16 (little-endian, with a
byte-order mark); OpenSpin reads both.  :func:`read_source` returns the text
unchanged except that it always ends with a newline, so that positions
(1-based line and column, counted in characters) point at the user's text.
"""
from __future__ import annotations

import os
import zlib
from dataclasses import dataclass, field
from typing import NamedTuple, Optional

from ..diagnostics import ParseError, split_lines
from .. import messages as msg

__all__ = ["SourceText", "Pos", "decode_source", "read_source", "utf16_char_byte", "split_lines"]

# How OpenSpin 1.00.81 turns a character of a UTF-16 source into a byte (in
# strings and DAT data).  Observed by compiling every BMP character in a
# ``byte "x"`` line: characters below U+0100 keep their value; above, the
# result depends on the high byte's class below (index = high byte - 1):
# ``I`` keeps the low byte (unless it is one of the bytes the tables below
# produce: then $FF), ``B`` gives $FF, and ``A``/``C``/``D`` look the low
# byte up in a small table (the Parallax font's arrows, bullets, box drawing;
# anything else gives $FF).
_U16_CLASS = ("ABCBDBBIABCBDBBIABCBDBBIABCBDBBAACCDDBBAACCDDBBIABCBDBBIABCBDBBIABCBDBBI"
              "ABCBDBBIABCBDBBIABCBDBBAACCDDBBAACCDDBBIABCBDBBIABCBDBBIABCBDBBIABCBDBBI"
              "ABCBDBBIABCBDBBAACCDDBBAACCDDBBIABCBDBBIABCBDBBIABCBDBBIABCBDBBIABCBDBBI"
              "IIIIIIIAACCDDBBAACCDDBBIABCBDBBIABCBDBB")
_U16_TABLES = {
    "A": {0x22: 0x0F, 0x23: 0x0E, 0x90: 0x02, 0x91: 0x04, 0x92: 0x03, 0x93: 0x05, 0xAC: 0xA4},
    "B": {},
    "C": {0x1A: 0x15, 0x48: 0x14, 0x94: 0x10, 0xA3: 0x12, 0xA9: 0x13, 0xC0: 0x11},
    "D": {0x00: 0x90, 0x02: 0x91, 0x0C: 0x9F, 0x10: 0x9E, 0x14: 0x9D, 0x18: 0x9C, 0x1C: 0x95,
          0x23: 0x99, 0x24: 0x94, 0x2B: 0x98, 0x2C: 0x97, 0x33: 0x9B, 0x34: 0x96, 0x3B: 0x9A,
          0x3C: 0x92, 0x4B: 0x93, 0xB6: 0x07, 0xC0: 0x06},
}


_U16_TAKEN = frozenset([*range(0x00, 0x09), 0x0B, 0x0C, 0x0E, 0x0F, *range(0x10, 0x16),
                        *range(0x90, 0xA0), 0xA4, 0xFF])


def utf16_char_byte(ch: str) -> int:
    """The byte OpenSpin stores for character ``ch`` of a UTF-16 source.

    >>> hex(utf16_char_byte("\u00e9")), hex(utf16_char_byte("\u2190")), hex(utf16_char_byte("\u20ac"))
    ('0xe9', '0x2', '0xa4')
    """
    code = ord(ch)
    if code < 0x100:
        return code
    if code > 0xFFFF:
        return 0xFF
    cls = _U16_CLASS[(code >> 8) - 1]
    if cls == "I":
        low = code & 0xFF
        return 0xFF if low in _U16_TAKEN else low
    return _U16_TABLES[cls].get(code & 0xFF, 0xFF)


class Pos(NamedTuple):
    """A place in a source file: path, 1-based line and column (a tuple: cheap to make)."""

    path: str
    line: int
    col: int

    def __str__(self) -> str:
        return f"{self.path}:{self.line}:{self.col}"


@dataclass
class SourceText:
    """The text of one source file and its lines (for diagnostics).

    >>> s = SourceText("demo.spin", "PUB main\\n  x := 1")
    >>> s.text.endswith("\\n"), s.line(2)
    (True, '  x := 1')
    """

    path: str
    text: str
    encoding: str = "utf-8"
    _lines: Optional[list] = field(default=None, repr=False)
    #: ``(size, CRC-32)`` of the file's bytes as read (:func:`read_source`), for the program cache
    digest: Optional[tuple] = field(default=None, repr=False, compare=False)

    def __post_init__(self):
        lines = split_lines(self.text)
        if self.text.endswith(("\n", "\r")) or not lines:
            self.eof = (len(lines) + 1, 1)
        else:
            self.eof = (len(lines), len(lines[-1]) + 1)
        if not self.text.endswith(("\n", "\r")):
            self.text += "\n"

    def line(self, number: int) -> Optional[str]:
        """The 1-based line ``number`` without its line ending (or ``None``)."""
        if self._lines is None:
            self._lines = split_lines(self.text)
        if 1 <= number <= len(self._lines):
            return self._lines[number - 1]
        return None

    def pos(self, line: int, col: int) -> Pos:
        return Pos(self.path, line, col)

    def end_position(self) -> tuple[int, int]:
        """Line and column just after the file's last character (where OpenSpin reports "end of file")."""
        return self.eof

    def string_bytes(self, text: str) -> bytes:
        """The bytes a string literal stands for, as OpenSpin reads this file.

        UTF-8 and Latin-1 files give their own bytes; UTF-16 files go through
        :func:`utf16_char_byte`.
        """
        if self.encoding == "utf-16":
            return bytes(utf16_char_byte(ch) for ch in text)
        return text.encode(self.encoding, errors="replace")


def decode_source(data: bytes, path: str = "<input>") -> tuple[str, str]:
    """Decode a source file's bytes; returns ``(text, encoding)``.

    UTF-16 needs its byte-order mark (the Propeller Tool always writes one).
    Bytes that are not UTF-8 are read as Latin-1 (old files use the Parallax
    font's 8-bit characters), so decoding never fails.

    >>> decode_source(b"\\xff\\xfeP\\x00U\\x00B\\x00")
    ('PUB', 'utf-16')
    >>> decode_source(b"\\xef\\xbb\\xbfCON")
    ('CON', 'utf-8')
    """
    if data.startswith(b"\xff\xfe") or data.startswith(b"\xfe\xff"):
        try:
            return data.decode("utf-16"), "utf-16"
        except UnicodeDecodeError as exc:
            raise ParseError(msg.BAD_ENCODING.format(detail=exc.reason), path=path) from None
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1"


def read_source(path: str) -> SourceText:
    """Read and decode a source file.

    Raises:
        ParseError: if the file cannot be read.
    """
    if os.path.exists(path) and not os.path.isfile(path) and not os.path.isdir(path):
        # a device or a FIFO: /dev/zero would never end, a FIFO would wait for a writer
        raise ParseError(msg.CANNOT_READ.format(reason="not a regular file"), path=path)
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError as exc:
        raise ParseError(msg.CANNOT_READ.format(reason=exc.strerror or exc), path=path) from None
    text, encoding = decode_source(data, path)
    return SourceText(os.fspath(path), text, encoding, digest=(len(data), zlib.crc32(data)))
