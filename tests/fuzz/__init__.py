"""Random Spin programs for differential testing (see docs/fuzzing.md).

``generate(seed)`` returns a :class:`Program` (``files``: name -> Spin text,
``results``: where the program leaves its results); ``python -m tests.fuzz
--seed N`` prints the program of seed N and the first disagreement found.
"""
from .generator import Program, Results, generate

__all__ = ["generate", "Program", "Results"]
