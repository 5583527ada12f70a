"""Parsing a Spin source into a :class:`~spinemu.frontend.ast.SpinFile`.

Each section is parsed on its own: every CON, VAR, OBJ and DAT line, and
every method.  A syntax error is reported, and parsing goes on with the next
line or method, so one run reports several errors without cascades.
"""
from __future__ import annotations


from ..diagnostics import Diagnostic, ParseError
from .. import messages as msg
from .ast import SpinFile
from .builder import AstBuilder
from .lalr import Parser, ParseFailure, load_tables
from .layout import layout
from .limits import MAX_BLOCK_DEPTH, MAX_EXPRESSION_DEPTH, block_nesting_errors, expression_depth_error
from .lexer import TAB_WIDTH, Token, tokenize, KEYWORDS, _OPERATORS
from .preprocess import preprocess
from .source import SourceText, read_source

__all__ = ["parse_source", "parse_file", "parse_text"]

_tables = None
_OP_SPELLING = {}
for _spelling, _type in _OPERATORS.items():
    if _type != "OPASSIGN":
        _OP_SPELLING.setdefault(_type, _spelling)
_KEYWORD_SPELLING = {t: w for w, t in KEYWORDS.items() if t == w.upper()}
_START = {"CON": "con_line", "VAR": "var_line", "OBJ": "obj_line", "DAT": "dat_line"}
#: tokens that open a block (limits.py); a method with fewer than ten cannot nest ten deep
_BLOCK_TOKENS = frozenset({"IF", "IFNOT", "REPEAT", "CASE", "LOOKUP"})


def _get_tables():
    global _tables
    if _tables is None:
        _tables = load_tables()
    return _tables


def describe_token(tok) -> str:
    """How a found token is named in a message."""
    t = tok.type
    if t in msg.FOUND_WORDS:
        return msg.FOUND_WORDS[t]
    if t == "STRING":
        return f'string "{tok.value}"'
    return f"'{tok.value}'"


def describe_expected(expected) -> str:
    """A short "expected ..." phrase for a set of token kinds."""
    exp = set(expected)
    words = []
    for group, phrase in msg.EXPECTED_GROUPS:
        if len(exp & group) >= 3:
            words.append(phrase)
            exp -= group
    if len(exp) > 6 and words:
        exp = {e for e in exp if e in ("_NL", "COMMA", "RPAR", "RSQB", "COLON")}
    for t in sorted(exp):
        if t in msg.TOKEN_WORDS:
            words.append(msg.TOKEN_WORDS[t])
        elif t in _OP_SPELLING:
            words.append(f"'{_OP_SPELLING[t]}'")
        elif t in _KEYWORD_SPELLING:
            words.append(f"'{_KEYWORD_SPELLING[t]}'")
        else:
            words.append(t.lower())
    words = list(dict.fromkeys(words))
    if len(words) > 6:
        words = words[:6] + ["..."]
    if not words:
        return ""
    if len(words) == 1:
        return words[0]
    return ", ".join(words[:-1]) + " or " + words[-1]


def _open_brackets(tokens: list, tok) -> set:
    """Which of ')' and ']' could close something open on ``tok``'s line before it."""
    stack = []
    for t in tokens:
        if t is tok:
            break
        if t.line != tok.line:
            stack.clear()
            continue
        if t.type == "LPAR":
            stack.append("RPAR")
        elif t.type in ("LSQB", "DLSQB"):
            stack.append("RSQB")
        elif t.type in ("RPAR", "RSQB") and stack:
            stack.pop()
    return set(stack)


def _failure(exc: ParseFailure, source: SourceText, start: str, tokens: list) -> Diagnostic:
    tok = exc.token
    if tok.type == "EQUAL" and start == "method":
        text = msg.SINGLE_EQUAL
    else:
        expected = set(exc.expected)
        # LALR merges look-aheads: do not offer a ')' or ']' that closes nothing
        expected -= {"RPAR", "RSQB"} - _open_brackets(tokens, tok)
        exp = describe_expected(expected or exc.expected)
        tail = msg.EXPECTED_TAIL.format(what=exp) if exp else ""
        text = msg.UNEXPECTED.format(found=describe_token(tok), expected=tail)
    length = max(1, len(tok.value)) if isinstance(tok, Token) else 1
    return Diagnostic(text, source.path, tok.line, tok.col, source.line(tok.line), "error", length)


def _longest_line(tokens) -> int:
    """Most tokens on one line of ``tokens`` (an expression is never deeper than its token count)."""
    longest = count = 0
    line = None
    for tok in tokens:
        if tok.line != line:
            line, count = tok.line, 0
        count += 1
        longest = max(longest, count)
    return longest


def parse_text(source: SourceText, defines=()) -> tuple[SpinFile, list]:
    """Parse ``source``; returns the file and the list of error diagnostics (maybe empty).

    ``defines`` are names taken as ``#define``d before the first line (OpenSpin's ``-D``).
    """
    text, pp_errors = preprocess(source.text, defines)
    lexed = tokenize(text, source.path, source.eof)
    errors: list[Diagnostic] = list(lexed.errors)
    for line, text_ in pp_errors:
        errors.append(Diagnostic(text_, source.path, line, 1, source.line(line)))
    if not source.text.strip():
        errors.append(Diagnostic(msg.EMPTY_FILE, source.path))
    spin = SpinFile(source.path, source, comments=lexed.comments)
    builder = AstBuilder(source.path)
    parser = Parser(_get_tables(), builder)

    def indent_at(tok) -> int:
        text = source.line(tok.line) or ""
        col = 0
        for ch in text[:tok.col - 1]:
            col = (col // TAB_WIDTH + 1) * TAB_WIDTH if ch == "\t" else col + 1
        return col

    def run(tokens, start):
        builder.in_code = start == "method"
        try:
            node = parser.parse(tokens, start)
        except ParseFailure as exc:
            errors.append(_failure(exc, source, start, tokens))
            return None
        opening = sum(1 for t in tokens if t.type in _BLOCK_TOKENS) if start == "method" else 0
        problems = block_nesting_errors(node) if opening > MAX_BLOCK_DEPTH else []
        if _longest_line(tokens) > MAX_EXPRESSION_DEPTH:
            deep = expression_depth_error(node)
            problems += [deep] if deep else []
        for text_, where in problems:
            errors.append(Diagnostic(text_, source.path, where.pos.line, where.pos.col,
                                     source.line(where.pos.line)))
        return node if not problems else None

    for section in lexed.sections:
        spin.sections.append((section.kind, section.line))
        kind = section.kind
        if kind == "DEV":
            for line in section.lines:
                tok = line.tokens[0]
                errors.append(Diagnostic(msg.DEV_SECTION, source.path, tok.line, tok.col, source.line(tok.line)))
            continue
        if kind in ("PUB", "PRI"):
            layout_errors: list = []
            tokens = layout(section.lines, layout_errors, indent_at)
            for text, tok in layout_errors:
                errors.append(Diagnostic(text, source.path, tok.line, tok.col, source.line(tok.line),
                                         "error", len(tok.value)))
            method = run(tokens, "method") if not layout_errors else None
            if method is not None:
                method.end_line = section.lines[-1].line
                spin.methods.append(method)
            continue
        start = _START[kind]
        for line in section.lines:
            last = line.tokens[-1]
            tokens = line.tokens + [Token("_NL", "", last.line, last.col + len(last.value))]
            node = run(tokens, start)
            if node is None:
                continue
            if kind == "CON":
                spin.cons.extend(node)
            elif kind == "VAR":
                spin.vars.extend(node)
            elif kind == "OBJ":
                spin.objs.append(node)
            else:
                spin.dat.append(node)
    # a line with a lexical error gets no syntax error on top of it
    bad_lines = {d.line for d in lexed.errors}
    lexical = {id(d) for d in lexed.errors}            # by identity: thousands of errors must not go quadratic
    errors = [d for d in errors if id(d) in lexical or d.line not in bad_lines]
    errors.sort(key=lambda d: (d.line or 0, d.column or 0))
    return spin, errors


def parse_source(text: str, path: str = "<input>", encoding: str = "utf-8") -> SpinFile:
    """Parse Spin source text.

    Raises:
        ParseError: with every syntax error found.

    >>> f = parse_source("PUB main\\n  outa[0]~~\\n", "blink.spin")
    >>> f.methods[0].name, type(f.methods[0].body[0]).__name__
    ('main', 'ExprStmt')
    """
    spin, errors = parse_text(SourceText(path, text, encoding))
    if errors:
        raise ParseError(diagnostics=errors)
    return spin


def parse_file(path: str) -> SpinFile:
    """Read and parse a Spin source file.

    Raises:
        ParseError: if the file cannot be read or has syntax errors.
    """
    spin, errors = parse_text(read_source(path))
    if errors:
        raise ParseError(diagnostics=errors)
    return spin
