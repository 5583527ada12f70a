"""Spin lexer: tokens, comments and sections of a Spin 1 source file.

Spin (Propeller Manual v1.2, chapter 2) is read line by line:

* A source is a list of *sections*, each opened by a block designator
  (``CON VAR OBJ PUB PRI DAT``) in the first column; text before the first
  designator belongs to an implicit ``CON``.
* Comments: ``'`` and ``''`` to the end of the line, ``{ }`` (nesting) and
  ``{{ }}`` (ending at the first ``}}``).  Brace comments may span lines;
  they count as white space, so a line broken by one continues after it.
* Numbers: ``123`` ``$7F`` ``%1010`` ``%%0123`` with ``_`` separators, and
  floats ``1.5`` ``1e6``.  ``$`` alone is the current address in DAT.
* Keywords are case-insensitive: the lexer looks words up in lower case but
  never changes the text, so diagnostics show the user's spelling.

In DAT sections the lexer also tells labels, conditions (``if_c``),
instructions (``mov``) and effects (``wz``) apart by their place on the line,
and ``[`` is the repeat-count bracket ``DLSQB`` (DAT data is never indexed).

The output is a :class:`LexedFile`: sections made of :class:`Line` objects
(tokens without line ends plus the line's indentation column, tabs expanded
to multiples of 8 as OpenSpin does), comments by line, and diagnostics.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..diagnostics import Diagnostic
from .. import messages as msg
from ..diagnostics import split_lines

__all__ = ["Token", "Line", "Section", "Comment", "LexedFile", "tokenize", "KEYWORDS",
           "PASM_MNEMONICS", "PASM_CONDITIONS", "DESIGNATORS"]

TAB_WIDTH = 8


class Token:
    """One token: its kind (``type``), its text and where it starts (1-based)."""

    __slots__ = ("type", "value", "line", "col")

    def __init__(self, type: str, value: str, line: int, col: int):
        self.type = type
        self.value = value
        self.line = line
        self.col = col

    def __repr__(self) -> str:
        return f"Token({self.type!r}, {self.value!r}, {self.line}, {self.col})"


@dataclass
class Line:
    """The tokens of one logical line and its indentation (columns, 0-based)."""

    tokens: list
    indent: int

    @property
    def line(self) -> int:
        return self.tokens[0].line


@dataclass
class Section:
    """A block opened by a designator (``kind`` upper case) and its lines."""

    kind: str
    line: int
    lines: list = field(default_factory=list)


@dataclass(frozen=True)
class Comment:
    """A comment: ``kind`` is ``'`` ``''`` ``{`` or ``{{``; ``text`` excludes the delimiters."""

    kind: str
    text: str
    line: int
    col: int
    end_line: int


@dataclass
class LexedFile:
    """LexedFil: see the module docstring."""

    sections: list
    comments: dict  # line -> [Comment]
    errors: list    # [Diagnostic]


DESIGNATORS = {"con", "var", "obj", "pub", "pri", "dat", "dev"}
#: words OpenSpin reserves without giving them a meaning in Spin 1 code
_RESERVED = ("archive", "enc", "ones", "precompile")

_BLOCK_WORDS = ("if ifnot elseif elseifnot else case other repeat from to step while until "
                "next quit return abort result")
_BUILTINS = ("bytemove wordmove longmove bytefill wordfill longfill strsize strcomp string constant "
             "float round trunc cognew coginit cogstop cogid locknew lockret lockset lockclr waitcnt "
             "waitpeq waitpne waitvid clkset reboot chipver clkfreq clkmode")
_REGISTERS = "par cnt ina inb outa outb dira dirb ctra ctrb frqa frqb phsa phsb vcfg vscl"
_KCONSTS = ("true false posx negx pi rcfast rcslow xinput xtal1 xtal2 xtal3 pll1x pll2x pll4x "
            "pll8x pll16x")

#: P1 instruction mnemonics (Propeller Manual v1.2, chapter 3).
PASM_MNEMONICS = frozenset(
    "abs absneg add addabs adds addsx addx and andn call clkset cmp cmps cmpsub cmpsx cmpx "
    "cogid coginit cogstop djnz hubop jmp jmpret lockclr locknew lockret lockset max maxs min "
    "mins mov movd movi movs mul muls muxc muxnc muxnz muxz neg negc negnc negnz negz nop or "
    "rcl rcr rdbyte rdlong rdword ret rev rol ror sar shl shr sub subabs subs subsx subx sumc "
    "sumnc sumnz sumz test testn tjnz tjz waitcnt waitpeq waitpne waitvid wrbyte wrlong wrword "
    "xor".split())
#: P1 instruction conditions.
PASM_CONDITIONS = frozenset(
    "if_always if_never if_e if_ne if_a if_b if_ae if_be if_c if_nc if_z if_nz if_c_eq_z "
    "if_c_ne_z if_c_and_z if_c_and_nz if_nc_and_z if_nc_and_nz if_c_or_z if_c_or_nz if_nc_or_z "
    "if_nc_or_nz if_z_eq_c if_z_ne_c if_z_and_c if_z_and_nc if_nz_and_c if_nz_and_nc if_z_or_c "
    "if_z_or_nc if_nz_or_c if_nz_or_nc".split())
_EFFECTS = frozenset("wz wc wr nr".split())
_DIRECTIVES = {"org": "ORG", "res": "RES", "fit": "FIT", "file": "FILE"}


def _keywords() -> dict:
    kw: dict[str, str] = {}
    for w in PASM_MNEMONICS:
        kw[w] = "PASM_OP"
    for w in PASM_CONDITIONS:
        kw[w] = "COND"
    for w in _EFFECTS:
        kw[w] = "EFFECT"
    kw.update(_DIRECTIVES)
    for w in _BLOCK_WORDS.split():
        kw[w] = w.upper()
    for w in ("byte", "word", "long"):
        kw[w] = "SIZE"
    for w in _BUILTINS.split():
        kw[w] = "BUILTIN"
    for w in ("lookup", "lookupz", "lookdown", "lookdownz"):
        kw[w] = "LOOKUP"
    for w in _REGISTERS.split():
        kw[w] = "REG"
    kw["spr"] = "SPR"
    for w in _KCONSTS.split():
        kw[w] = "KCONST"
    kw.update({"and": "AND", "or": "OR", "not": "NOT"})
    for w in DESIGNATORS:
        kw[w] = "SECTION"
    for w in _RESERVED:
        kw[w] = "RESERVED"
    return kw


#: lower-case word -> token type, for Spin code (PASM words are reserved there too)
KEYWORDS: dict[str, str] = _keywords()

_OPERATORS = {
    # assignment forms of the binary operators (value keeps the spelling)
    "**=": "OPASSIGN", "//=": "OPASSIGN", "#>=": "OPASSIGN", "<#=": "OPASSIGN", "~>=": "OPASSIGN",
    "<<=": "OPASSIGN", ">>=": "OPASSIGN", "<-=": "OPASSIGN", "->=": "OPASSIGN", "><=": "OPASSIGN",
    "===": "OPASSIGN", "<>=": "OPASSIGN", "=<=": "OPASSIGN", "=>=": "OPASSIGN",
    "+=": "OPASSIGN", "-=": "OPASSIGN", "*=": "OPASSIGN", "/=": "OPASSIGN", "&=": "OPASSIGN",
    "|=": "OPASSIGN", "^=": "OPASSIGN", "<=": "OPASSIGN", ">=": "OPASSIGN",
    ":=": "ASSIGN",
    "**": "STARSTAR", "//": "SLASHSLASH", "#>": "LIMMIN", "<#": "LIMMAX", "~>": "SAR",
    "<<": "SHL", ">>": "SHR", "<-": "ROL", "->": "ROR", "><": "REV", "==": "EQEQ", "<>": "NE",
    "=<": "LE", "=>": "GE", "^^": "SQRT", "||": "ABS", "|<": "DECODE", ">|": "ENCODE",
    "~~": "TILDE2", "++": "INC", "--": "DEC", "@@": "ATAT", "..": "DOTDOT",
    "+": "PLUS", "-": "MINUS", "*": "STAR", "/": "SLASH", "&": "AMP", "|": "BAR", "^": "CARET",
    "<": "LT", ">": "GT", "!": "BANG", "~": "TILDE", "?": "QUESTION", "@": "AT", ":": "COLON",
    ",": "COMMA", "(": "LPAR", ")": "RPAR", "[": "LSQB", "]": "RSQB", ".": "DOT", "#": "HASH",
    "\\": "BACKSLASH", "=": "EQUAL",
}
_OP_PATTERN = "|".join(re.escape(op) for op in sorted(_OPERATORS, key=len, reverse=True))

_TOKEN_RE = re.compile(r"""
 (?P<nl>\r\n|\r|\n)
|(?P<ws>[ \t\f\x00]+)
|(?P<com>'[^\r\n]*)
|(?P<lbrace>\{)
|(?P<rbrace>\}+)
|(?P<float>\d[\d_]*\.\d[\d_]*(?:[eE][+-]?\d+)?|\d[\d_]*[eE][+-]?\d+)
|(?P<dec>\d[\d_]*)
|(?P<hex>\$[0-9A-Fa-f][0-9A-Fa-f_]*)
|(?P<here>\$)
|(?P<quat>%%[0-3][0-3_]*)
|(?P<bin>%[01][01_]*)
|(?P<name>[A-Za-z_][A-Za-z_0-9]*)
|(?P<str>"[^"\r\n]*")
|(?P<badstr>"[^"\r\n]*)
|(?P<op>""" + _OP_PATTERN + r""")
""", re.X)

_SPACED_EQUAL = re.compile(r"[ \t]+=(?![=<>])")
_NUMBER_KINDS = {"dec": "NUMBER", "hex": "NUMBER", "quat": "NUMBER", "bin": "NUMBER", "float": "FLOAT"}
_NEWLINE_RE = re.compile(r"\r\n|\r|\n")
_BRACE_RE = re.compile(r"[{}]")


class _Lexer:
    def __init__(self, text: str, path: str, eof=None):
        self.text = text
        lines = split_lines(text)
        self.eof = eof or (len(lines) + 1, 1)
        self.path = path
        self.sections: list[Section] = [Section("CON", 1)]
        self.comments: dict[int, list] = {}
        self.errors: list[Diagnostic] = []
        self.line = 1
        self.line_start = 0
        self.tokens: list[Token] = []   # the logical line being built
        self.line_indent = 0
        self.dat_state = 0              # DAT: 0 line start, 1 after label, 2 after condition, 3 operands
        self._lines = None              # the text's lines, split once on the first error

    # -- helpers
    def error(self, message: str, line: int, col: int, length: int = 1) -> None:
        src = self._source_line(line)
        self.errors.append(Diagnostic(message, self.path, line, col, src, "error", length))

    def _source_line(self, line: int):
        if self._lines is None:
            self._lines = split_lines(self.text)
        lines = self._lines
        return lines[line - 1] if 1 <= line <= len(lines) else None

    def _indent_of(self, pos: int) -> int:
        prefix = self.text[self.line_start:pos]
        col = 0
        for ch in prefix:
            col = (col // TAB_WIDTH + 1) * TAB_WIDTH if ch == "\t" else col + 1
        return col

    def _end_line(self) -> None:
        if self.tokens:
            self.sections[-1].lines.append(Line(self.tokens, self.line_indent))
            self.tokens = []
        self.dat_state = 0

    def _unterminated(self, message: str) -> None:
        """An unclosed comment is reported at the end of the file (as OpenSpin does)."""
        line, col = self.eof
        self.error(message, line, col)

    def _add_comment(self, kind: str, body: str, line: int, col: int, end_line: int) -> None:
        self.comments.setdefault(line, []).append(Comment(kind, body, line, col, end_line))

    def _emit(self, type_: str, value: str, pos: int) -> None:
        if not self.tokens:
            self.line_indent = self._indent_of(pos)
        self.tokens.append(Token(type_, value, self.line, pos - self.line_start + 1))

    # -- comments spanning lines
    def _brace_comment(self, pos: int) -> int:
        """Skip a ``{`` or ``{{`` comment starting at ``pos``; return the position after it."""
        text = self.text
        line, col = self.line, pos - self.line_start + 1
        if text.startswith("{{", pos):
            end = text.find("}}", pos + 2)
            if end < 0:
                self._unterminated(msg.UNTERMINATED_DOC.format(line=line))
                end = len(text) - 2
            stop, kind, body = end + 2, "{{", text[pos + 2:end]
        else:
            depth, i = 0, len(text) - 1
            for m in _BRACE_RE.finditer(text, pos):
                depth += 1 if m.group() == "{" else -1
                if depth == 0:
                    i = m.start()
                    break
            else:
                self._unterminated(msg.UNTERMINATED_BRACE.format(line=line))
            stop, kind, body = i + 1, "{", text[pos + 1:i]
        # keep line bookkeeping right across the comment's line breaks
        for m in _NEWLINE_RE.finditer(text, pos, stop):
            self.line += 1
            self.line_start = m.end()
        self._add_comment(kind, body, line, col, self.line)
        return stop

    # -- words
    def _word(self, word: str, pos: int) -> int:
        """Emit a word token (or open a section); return the position after it."""
        end = pos + len(word)
        low = word.lower()
        kind = KEYWORDS.get(low, "NAME")
        section = self.sections[-1].kind
        if kind == "SECTION":
            col = pos - self.line_start + 1
            if col == 1 or not self.tokens:
                if col != 1:
                    self.error(msg.DESIGNATOR_NOT_FIRST.format(word=word), self.line, col, len(word))
                self._end_line()
                self.sections.append(Section(word.upper(), self.line))
                if word.upper() in ("PUB", "PRI"):
                    self._emit(word.upper(), word, pos)
                return end
        if section == "DAT":
            kind = self._dat_word(low, kind)
        elif kind in ("AND", "OR") and self.text.startswith("=", end) \
                and not self.text.startswith(("==", "=<", "=>"), end):
            self._emit("OPASSIGN", word + "=", pos)
            return end + 1
        self._emit(kind, word, pos)
        return end

    def _dat_word(self, low: str, kind: str) -> str:
        """Classify a word of a DAT line by its place: label, condition, instruction, operand."""
        state = self.dat_state
        if state < 3:
            if low in PASM_CONDITIONS and state < 2:
                self.dat_state = 2
                return "COND"
            if low in PASM_MNEMONICS:
                self.dat_state = 3
                return "PASM_OP"
            if kind == "SIZE" or low in _DIRECTIVES:
                self.dat_state = 3
                return kind
            self.dat_state = 1 if state == 0 else 3
            return kind
        if low in _EFFECTS:
            return "EFFECT"
        if kind in ("PASM_OP", "COND") and low in KEYWORDS and KEYWORDS[low] not in ("PASM_OP", "COND"):
            return KEYWORDS[low]
        return kind

    # -- main loop
    def run(self) -> LexedFile:
        text = self.text
        pos, n = 0, len(text)
        match = _TOKEN_RE.match
        while pos < n:
            m = match(text, pos)
            if m is None:
                ch = text[pos]
                shown = f"'{ch}'" if ch.isprintable() else f"U+{ord(ch):04X}"    # NUL, ^Z: say which
                self.error(msg.BAD_CHARACTER.format(ch=shown), self.line, pos - self.line_start + 1)
                pos += 1
                continue
            kind = m.lastgroup
            value = m.group()
            end = m.end()
            if kind == "nl":
                self._end_line()
                self.line += 1
                self.line_start = end
            elif kind == "ws":
                pass
            elif kind == "com":
                double = value.startswith("''")
                self._add_comment("''" if double else "'", value[2 if double else 1:],
                                  self.line, pos - self.line_start + 1, self.line)
            elif kind == "lbrace":
                end = self._brace_comment(pos)
            elif kind == "rbrace":
                self.error(msg.STRAY_CLOSE_BRACE, self.line, pos - self.line_start + 1)
            elif kind == "name":
                end = self._word(value, pos)
            elif kind == "str":
                self._emit("STRING", value[1:-1], pos)
                self._operand()
            elif kind == "badstr":
                self.error(msg.UNTERMINATED_STRING, self.line, pos - self.line_start + 1)
            elif kind == "op":
                end = self._op(value, pos)
            elif kind == "here":
                self._emit("HERE", value, pos)
                self._operand()
            else:  # numbers
                self._emit(_NUMBER_KINDS[kind], value, pos)
                self._operand()
            pos = end
        self._end_line()
        return LexedFile(self.sections, self.comments, self.errors)

    def _operand(self) -> None:
        if self.dat_state < 3:
            self.dat_state = 3

    def _op(self, value: str, pos: int) -> int:
        type_ = _OPERATORS[value]
        end = pos + len(value)
        if value + "=" in _OPERATORS and _OPERATORS[value + "="] == "OPASSIGN":
            # OpenSpin reads "x + = 1" as "x += 1"
            m = _SPACED_EQUAL.match(self.text, end)
            if m:
                self._emit("OPASSIGN", value + "=", pos)
                return m.end()
        if self.sections[-1].kind == "DAT":
            if type_ == "COLON":
                m = _TOKEN_RE.match(self.text, end)
                if m is not None and m.lastgroup == "name":
                    self._emit("LOCALNAME", ":" + m.group(), pos)
                    if self.dat_state == 0:
                        self.dat_state = 1
                    return m.end()
            elif type_ == "LSQB":
                type_ = "DLSQB"
            self._operand()
        self._emit(type_, value, pos)
        return end


def tokenize(text: str, path: str = "<input>", eof=None) -> LexedFile:
    """Split ``text`` into sections of token lines; collect comments and lexical errors.

    >>> lexed = tokenize("CON\\n  X = $10 ' sixteen\\nPUB main\\n  x := X\\n")
    >>> [s.kind for s in lexed.sections]
    ['CON', 'CON', 'PUB']
    >>> [(t.type, t.value) for t in lexed.sections[1].lines[0].tokens]
    [('NAME', 'X'), ('EQUAL', '='), ('NUMBER', '$10')]
    >>> lexed.comments[2][0].text
    ' sixteen'
    """
    return _Lexer(text, path, eof).run()
