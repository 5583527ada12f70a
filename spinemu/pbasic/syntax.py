"""PBASIC 2.5 source -> :class:`.nodes.Program` (flat statements with positions).

Loads ``grammars/pbasic.lark`` once (LALR, contextual lexer, Lark's grammar
cache), runs the directive scan and conditional compilation of
:mod:`.preprocess`, parses, and turns Lark's tree into :mod:`.nodes`.  Parse
errors become :class:`~spinemu.diagnostics.ParseError` with ``file:line:col``
and messages in PBASIC words (never Lark terminal names).
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Optional

from lark import Lark, Token, Transformer, Tree, v_args
from lark.exceptions import (UnexpectedCharacters, UnexpectedEOF, UnexpectedInput,
                             VisitError)

from ..diagnostics import ParseError, source_line_at
from . import messages as M
from . import nodes as N
from .preprocess import conditional_compile, scan_directives
from .words import OTHER_STAMP_COMMANDS, RESERVED

__all__ = ["parse_source", "parse_file", "parse_condition", "grammar_path", "get_parser",
           "read_source"]

_CMP_NORMAL = {"=<": "<=", "=>": ">=", "><": "<>"}
#: Operators allowed after CON and in DATA.
_CONST_OPS = {"+", "-", "*", "/", "<<", ">>", "&", "|", "^"}


def grammar_path() -> Path:
    """``grammars/pbasic.lark`` in the repository, or inside the installed package."""
    here = Path(__file__).resolve().parent
    for cand in (here.parent / "grammars" / "pbasic.lark",
                 here.parent.parent / "grammars" / "pbasic.lark"):
        if cand.exists():
            return cand
    raise FileNotFoundError("grammars/pbasic.lark not found")


@lru_cache(maxsize=1)
def get_parser() -> Lark:
    """The LALR parser (built once per process; Lark caches the analysed grammar on disk)."""
    return Lark(grammar_path().read_text(), parser="lalr", lexer="contextual",
                start=["start", "cond"], propagate_positions=True, maybe_placeholders=True,
                cache=True)


def read_source(path: str) -> str:
    """A source file as text: UTF-16 or UTF-8 with a byte-order mark, UTF-8 if it decodes,
    otherwise Windows-1252 (the Stamp editor's).

    Raises:
        ParseError: the file cannot be read.
    """
    try:
        if Path(path).exists() and not Path(path).is_file() and not Path(path).is_dir():
            raise OSError(0, "not a regular file")      # a device such as /dev/zero would never end
        data = Path(path).read_bytes()
    except OSError as e:
        raise ParseError(M.CANNOT_READ.format(e.strerror or e), path=str(path)) from None
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):      # UTF-16 with a byte-order mark (a Windows editor)
        return data.decode("utf-16", errors="replace")
    if data.startswith(b"\xef\xbb\xbf"):                  # UTF-8 with a byte-order mark (Notepad)
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def parse_file(path: str) -> N.Program:
    return parse_source(read_source(path), str(path))


def parse_source(text: str, path: str = "<input>") -> N.Program:
    """Parse a whole PBASIC file.

    Raises:
        ParseError: missing/unsupported directives, conditional-compilation
            errors, or a syntax error.
    """
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    if not text.endswith("\n"):
        text += "\n"
    directives = scan_directives(text, path)
    body = conditional_compile(text, path, directives, _pp_evaluate(path))
    tree = _parse(body, "start", path, text)
    prog = N.Program(path=path, source=text, stamp=directives.stamp or "BS2",
                     language=directives.language)
    prog.items = _transform(_Builder(text, path), tree)
    return prog


def parse_condition(text: str, path: str = "<input>", line: int = 1, column: int = 1,
                    source: Optional[str] = None):
    """Parse one PBASIC condition (used by ``#IF``); errors point at ``line:column`` on."""
    body = text.strip()
    lead = len(text) - len(text.lstrip())
    try:
        tree = get_parser().parse(body, start="cond")
    except UnexpectedInput as e:
        src = source_line_at(source, line) if source else None
        col = column + lead + max(0, (getattr(e, "column", 1) or 1) - 1)
        raise ParseError(M.PP_BAD_EXPR, path=path, line=line, column=col,
                         source_line=src) from None
    return _transform(_Builder(body, path), tree)


def _transform(builder, tree):
    try:
        return builder.transform(tree)
    except VisitError as e:          # errors raised while building nodes
        if isinstance(e.orig_exc, ParseError):
            raise e.orig_exc from None
        raise


def _pp_evaluate(path: str):
    def evaluate(expr_text: str, line: int, column: int, symbols: dict, source: str) -> int:
        from .exprs import eval_const   # late import: exprs needs nodes only
        node = parse_condition(expr_text, path, line, column, source)
        return eval_const(node, lambda name: symbols.get(name.upper(), 0), path=path)
    return evaluate


# ---------------------------------------------------------------- errors

_TERMINAL_WORDS = {
    "_NL": "end of line", "COLON": "':'", "_COMMA": "','", "LPAR": "'('", "RPAR": "')'",
    "LSQB": "'['", "RSQB": "']'", "EQUAL": "'='", "DOT": "'.'", "QMARK": "'?'",
    "BACKSLASH": "'\\'", "AT": "'@'", "NAME": "a name", "STRING": "a string",
    "BINOP": "a binary operator", "MINUS": "'-'", "UNOP": "a unary operator",
    "CMPOP": "a comparison operator", "LOGOP": "AND, OR or XOR", "FORMATTER": "a formatter",
"VARTYPE": "Bit, Nib, Byte or Word",
    "LOOPTEST": "WHILE or UNTIL", "WORD": "'Word'",
}
_OPERAND = {"NAME", "DECNUM", "HEXNUM", "BINNUM", "STRING", "LPAR", "UNOP", "MINUS"}
_WORD_AT_END = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*$")
_BAD_FORMATTER = re.compile(r"(?i)^(I?S?HEX|I?S?BIN|S?DEC)[0-9]+$")
_OPERATOR_WORDS = {w for w, what in RESERVED.items()
                   if "operator" in what or "formatter" in what}


def _describe_expected(expected: set) -> str:
    parts = []
    names = set(expected)
    if "_NL" in names:
        # LALR merges states, so the other candidates are often noise: say
        # what the BS2 tokenizer says.
        return "':' or end of line"
    if {"HIGH", "GOSUB", "DEBUG"} <= names:
        return "a label, variable, or instruction"
    if names & {"NAME", "DECNUM"} and names & {"UNOP", "LPAR", "MINUS"}:
        parts.append("a constant, variable, unary operator, or '('")
        names -= _OPERAND
    elif names & {"DECNUM", "HEXNUM", "BINNUM"}:
        parts.append("a constant")
        names -= {"DECNUM", "HEXNUM", "BINNUM", "STRING", "NAME"}
    if {"_NL", "COLON"} & names:
        parts.append("':' or end of line")
        names -= {"_NL", "COLON"}
    for n in sorted(names):
        word = _TERMINAL_WORDS.get(n)
        if word is None:
            word = f"'{n}'" if n.isalpha() else None
        if word and word not in parts:
            parts.append(word)
    if not parts:
        return "something else"
    if len(parts) > 5:
        parts = parts[:5]
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " or " + parts[-1]


def _found(tok: Token) -> str:
    if tok.type == "_NL" or tok.type == "$END":
        return "end of line"
    return "'" + str(tok.value).split("\n")[0].rstrip(",") + "'"


def _statement_start_word(line_text: str, col: int) -> Optional[tuple[str, int]]:
    """The first word of the statement containing column ``col`` (1-based)."""
    segment_start = 0
    in_str = False
    for i, ch in enumerate(line_text[:col - 1]):
        if ch == '"':
            in_str = not in_str
        elif ch == ":" and not in_str:
            segment_start = i + 1
        elif ch == "'" and not in_str:
            break
    m = re.match(r"\s*([A-Za-z_][A-Za-z0-9_]*)", line_text[segment_start:])
    if not m:
        return None
    return m.group(1), segment_start + m.start(1) + 1


#: Deepest parse tree built into nodes (the node builder and the compiler recurse per level);
#: an expression this deep is far past what the BS2's 8-entry expression stack evaluates.
MAX_TREE_DEPTH = 100


def _parse(text: str, start: str, path: str, original: str) -> Tree:
    try:
        tree = get_parser().parse(text, start=start)
    except UnexpectedInput as e:
        raise _syntax_error(e, text, path, original) from None
    _check_depth(tree, path, original)
    return tree


def _check_depth(tree: Tree, path: str, original: str) -> None:
    """Refuse a tree deeper than :data:`MAX_TREE_DEPTH` (walked without recursion)."""
    stack = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        if depth > MAX_TREE_DEPTH:
            meta = node.meta
            line = getattr(meta, "line", None)
            raise ParseError(M.EXPRESSION_TOO_COMPLEX, path=path, line=line, column=getattr(meta, "column", None),
                             source_line=source_line_at(original, line) if line else None)
        stack.extend((child, depth + 1) for child in node.children if isinstance(child, Tree))


def _syntax_error(e: UnexpectedInput, text: str, path: str, original: str) -> ParseError:
    line = getattr(e, "line", 1) or 1
    col = getattr(e, "column", 1) or 1
    src = source_line_at(original, line) or source_line_at(text, line) or ""
    length = 1

    def err(msg: str, c: int = col, n: int = length) -> ParseError:
        return ParseError(msg, path=path, line=line, column=c, source_line=src, length=n)

    if isinstance(e, UnexpectedCharacters):
        ch = text[e.pos_in_stream] if e.pos_in_stream < len(text) else "?"
        return err(M.UNEXPECTED_CHAR.format(ch))
    tok = getattr(e, "token", None)
    expected = set(getattr(e, "expected", None) or getattr(e, "accepts", None) or ())
    if isinstance(e, UnexpectedEOF) or tok is None:
        return err(M.UNEXPECTED.format(_describe_expected(expected), "end of file"))
    if tok.type not in ("_NL", "$END"):
        length = max(1, len(str(tok.value).split("\n")[0].rstrip(",")))
    # Commands of other Stamps ('I2CIN 1, ...').
    first = _statement_start_word(src, col)
    if first and first[0].upper() in OTHER_STAMP_COMMANDS:
        word, c = first
        return err(M.OTHER_STAMP_COMMAND.format(word.upper(), OTHER_STAMP_COMMANDS[word.upper()]),
                   c, len(word))
    # A declaration of a reserved word: 'Loop VAR Byte'.
    if tok.type in ("VAR", "CON", "PIN", "DATA") and first and first[0].upper() in RESERVED:
        return err(M.RESERVED_NAME.format(first[0]), first[1], len(first[0]))
    # A comparison or AND/OR/NOT outside a condition: x = a > b.
    if tok.type in ("CMPOP", "EQUAL", "LOGOP", "NOT") and tok.type not in expected:
        return err(M.COMPARE_OUTSIDE_CONDITION.format(str(tok.value).upper()))
    before = _WORD_AT_END.search(src[:col - 1])
    if tok.type == "IF" or (before and before.group(1).upper() == "IF"
                            and first and first[1] < before.start(1) + 1):
        c = col if tok.type == "IF" else before.start(1) + 1
        return err(M.NESTED_INLINE_IF, c, 2)
    if tok.type == "ELSE" and first and first[0].upper() == "IF":
        return err(M.ELSE_AFTER_LABEL)
    # A name alone on its line: a label without its colon.
    if tok.type in ("_NL", "COLON", "$END") and first and first[0].upper() not in RESERVED \
            and src[first[1] - 1:col - 1].strip() == first[0]:
        return err(M.LABEL_MISSING_COLON, first[1], len(first[0]))
    m = _WORD_AT_END.search(src[:col - 1])
    # DEC6, BIN17: a formatter with too many digits is just an unknown name.
    if m and _BAD_FORMATTER.match(m.group(1)):
        word = m.group(1)
        return err(M.UNDEFINED.format(word) + " (DEC/SDEC take 1-5 digits, HEX 1-4, BIN 1-16)",
                   m.start(1) + 1, len(word))
    # An operator word where a value was wanted ('x = ATN 4'): blame the word.
    if m and m.group(1).upper() in _OPERATOR_WORDS:
        word = m.group(1)
        return err(M.RESERVED_AS_VALUE.format(word.upper(), RESERVED[word.upper()]),
                   m.start(1) + 1, len(word))
    return err(M.UNEXPECTED.format(_describe_expected(expected), _found(tok)))


# ---------------------------------------------------------------- tree -> nodes

def _tpos(tok: Token) -> N.Pos:
    text = str(tok.value).split("\n")[0]
    return N.Pos(tok.line, tok.column, max(1, len(text)))


def _mpos(meta) -> N.Pos:
    if getattr(meta, "empty", False):
        return N.Pos(1, 1)
    length = meta.end_column - meta.column if meta.end_line == meta.line else 1
    return N.Pos(meta.line, meta.column, max(1, length))


def _number(tok: Token) -> int:
    """A literal's value; a decimal of more than 40 digits reads as ``2**160`` (too big either
    way: Python refuses to convert decimal text longer than 4,300 digits)."""
    s = str(tok.value)
    if s.startswith("$"):
        return int(s[1:], 16)
    if s.startswith("%"):
        return int(s[1:], 2)
    if len(s.lstrip("0")) > 40:
        return 1 << 160
    return int(s)


def leftmost_pos(e) -> N.Pos:
    """Position of the first character of an expression."""
    while isinstance(e, (N.Binary, N.Compare, N.Logic)):
        e = e.left
    return e.pos


@v_args(meta=True)
class _Builder(Transformer):
    """Lark tree -> list of nodes.Stmt / nodes.Label (and expressions)."""

    def __init__(self, source: str, path: str = "<input>"):
        super().__init__(visit_tokens=False)
        self._lines = source.split("\n")
        self._path = path

    def _line(self, n: int) -> Optional[str]:
        return self._lines[n - 1] if 1 <= n <= len(self._lines) else None

    def _text(self, pos: N.Pos) -> str:
        if 1 <= pos.line <= len(self._lines):
            return self._lines[pos.line - 1][pos.column - 1: pos.column - 1 + pos.length]
        return ""

    # ---- program structure
    def start(self, meta, children):
        return [c for c in children if c is not None]

    def label(self, meta, children):
        tok = children[0]
        return N.Label(str(tok), _tpos(tok))

    def __default__(self, data, children, meta):
        pos = _mpos(meta)
        return N.Stmt(str(data), pos, tuple(children), self._text(pos))

    def then_part(self, meta, children):
        return list(children)

    goto_part = then_part
    else_part = then_part

    # ---- expressions
    def number(self, meta, children):
        tok = children[0]
        return N.Num(_number(tok), str(tok), _tpos(tok))

    def string(self, meta, children):
        tok = children[0]
        return N.Str(str(tok)[1:-1], _tpos(tok))

    def ref(self, meta, children):
        names = [c for c in children if isinstance(c, Token)]
        index = children[-1] if children and not isinstance(children[-1], Token) else None
        first = names[0]
        mods = tuple((str(t), _tpos(t)) for t in names[1:])
        return N.Ref(str(first), _tpos(first), mods, index)

    def binop(self, meta, children):
        left, op, right = children
        return N.Binary(str(op).upper(), left, right, _tpos(op))

    def unop(self, meta, children):
        op, operand = children
        return N.Unary(str(op).upper(), operand, _tpos(op))

    def compare(self, meta, children):
        left, op, right = children
        o = str(op)
        return N.Compare(_CMP_NORMAL.get(o, o), left, right, _tpos(op))

    def logic(self, meta, children):
        left, op, right = children
        return N.Logic(str(op).upper(), left, right, _tpos(op))

    def not_(self, meta, children):
        pos = _mpos(meta)
        return N.Not(children[0], N.Pos(pos.line, pos.column, 3))

    # ---- constant expressions (CON, DATA): the same nodes, left to right
    def kexpr(self, meta, children):
        acc = children[0]
        for i in range(1, len(children), 2):
            op = children[i]
            if str(op).upper() not in _CONST_OPS:
                raise ParseError(M.UNEXPECTED.format("':' or end of line", f"'{op}'"),
                                 path=self._path, line=op.line, column=op.column,
                                 source_line=self._line(op.line), length=len(str(op)))
            acc = N.Binary(str(op).upper(), acc, children[i + 1], _tpos(op))
        return acc

    def kterm(self, meta, children):
        minus, atom = children
        if minus is None:
            return atom
        return N.Unary("-", atom, _tpos(minus))

    def kname(self, meta, children):
        tok = children[0]
        return N.Ref(str(tok), _tpos(tok))

    # ---- pieces of statements that are not statements
    def _piece(kind):
        def build(self, meta, children):
            pos = _mpos(meta)
            return N.Stmt(kind, pos, tuple(children), self._text(pos))
        return build

    for _k in ("data_at", "data_value", "data_reserve", "case_eq", "case_cmp", "case_range",
               "read_item", "write_item", "xout_item", "shout_item", "shin_item",
               "out_value", "out_fmt", "out_fmt_show", "out_show", "out_asc_show", "out_str",
               "out_rep", "in_byte", "in_fmt", "in_str", "in_waitstr", "in_wait", "in_skip"):
        locals()[_k] = _piece(_k)
    del _k, _piece
