"""The Spin front end: source reading, lexer, indentation post-lexer, LALR parser, AST.

>>> from spinemu.frontend import parse_source
>>> f = parse_source("CON\\n  X = 1\\nPUB main\\n  result := X\\n")
>>> [c.name for c in f.cons], [m.name for m in f.methods]
(['X'], ['main'])
"""
from .parser import parse_file, parse_source, parse_text
from .source import SourceText, Pos, read_source

__all__ = ["parse_file", "parse_source", "parse_text", "SourceText", "Pos", "read_source"]
