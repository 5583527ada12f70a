"""The Spin front end: source reading, lexer, indentation post-lexer, LALR parser, AST.

One front end for two back ends (the compiler and the Spin->Python translator):

* :func:`parse_file` / :func:`parse_source` give one file's :class:`~spinemu.frontend.ast.SpinFile`;
* :func:`load_program` loads a whole object tree (OBJ files resolved, CON folded).

>>> from spinemu.frontend import parse_source
>>> f = parse_source("CON\\n  X = 1\\nPUB main\\n  result := X\\n")
>>> [c.name for c in f.cons], [m.name for m in f.methods]
(['X'], ['main'])
"""
from .objects import ObjectUnit, load_program
from .parser import parse_file, parse_source, parse_text
from .source import Pos, SourceText, read_source

__all__ = ["parse_file", "parse_source", "parse_text", "load_program", "ObjectUnit", "SourceText", "Pos",
           "read_source"]
