"""OpenSpin's preprocessor conditionals: ``#define``, ``#ifdef`` and friends.

OpenSpin (1.00.81, enabled by default) reads lines that start with ``#``
followed by a directive word.  spinemu supports what library code uses:
``#define NAME``, ``#undef NAME``, ``#ifdef``/``#ifndef NAME``,
``#elseifdef``/``#elseifndef NAME``, ``#else`` and ``#endif``.  Directive
lines and the lines of inactive branches become empty lines, so line
numbers do not move.  (Defined names are not substituted into the text.)
"""
from __future__ import annotations

import re

__all__ = ["preprocess"]

_DIRECTIVE = re.compile(r"#(define|undef|ifdef|ifndef|elseifdef|elseifndef|else|endif)\b[ \t]*(\w*)",
                        re.IGNORECASE)
_LINE = re.compile(r"[^\r\n]*(\r\n|\r|\n|$)")


def preprocess(text: str, defines=()) -> tuple[str, list]:
    """Apply the conditionals; returns ``(text, [(line, message)])``.

    >>> preprocess("#define A\\n#ifdef A\\nyes\\n#else\\nno\\n#endif\\n")[0]
    '\\n\\nyes\\n\\n\\n\\n'
    """
    if "#" not in text:
        return text, []
    defined = {d.lower() for d in defines}
    stack: list = []            # [(active, taken)] per open #if
    out: list[str] = []
    errors: list = []
    active = True
    for number, m in enumerate(_LINE.finditer(text), 1):
        line, ending = m.group(0)[:len(m.group(0)) - len(m.group(1))], m.group(1)
        if not m.group(0):
            break
        d = _DIRECTIVE.match(line)
        if d is None:
            out.append(line + ending if active else ending)
            continue
        word, name = d.group(1).lower(), d.group(2).lower()
        if word in ("define", "undef") and active:
            (defined.add if word == "define" else defined.discard)(name)
        elif word in ("ifdef", "ifndef"):
            cond = (name in defined) == (word == "ifdef")
            stack.append((active, cond))
            active = active and cond
        elif word in ("elseifdef", "elseifndef", "else"):
            if not stack:
                errors.append((number, f"#{word} without #ifdef"))
            else:
                outer, taken = stack[-1]
                cond = True if word == "else" else (name in defined) == (word == "elseifdef")
                active = outer and not taken and cond
                stack[-1] = (outer, taken or cond)
        elif word == "endif":
            if not stack:
                errors.append((number, "#endif without #ifdef"))
            else:
                active = stack.pop()[0]
        out.append(ending)
    return "".join(out), errors
