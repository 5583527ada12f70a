"""The Spin compiler: a program's AST to a Propeller 1 image, byte-identical with OpenSpin.

>>> from spinemu.compiler import compile_source
>>> prog = compile_source("PUB main\\n  dira[16]~~\\n")
>>> prog.binary.hex()[:8]
'001bb700'
"""
from .program import CompiledProgram, InstanceLayout, LineTable, compile_file, compile_source

__all__ = ["compile_file", "compile_source", "CompiledProgram", "LineTable", "InstanceLayout"]
