"""Random DAT sections: data lines of every size with size overrides, repetition, strings, alignment, labels.

Every label is recorded with what code may do with it: read it (``lbl``,
``lbl[i]``, ``byte[@lbl][i]``), write it (only labels whose line has one
size and a known item count, so a write never lands in code), use it as a
string (``strsize(@lbl)``) or as a table of object offsets (``@@tab[i]``).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .gen_const import ConstGen, float_literal, int_literal, int_value
from .rand import Rand

SIZES = {"byte": 1, "word": 2, "long": 4}


@dataclass
class DatLabel:
    """A DAT label and what code may do with it."""

    name: str
    size: int                  # the size of its line (1, 2, 4)
    count: int | None = None   # items of that size it surely owns (for writes); None: read only
    string: bool = False       # a zero-terminated string starts here
    table: list = field(default_factory=list)   # labels whose @offsets this word/long table holds


class DatGen:
    """Writes the DAT lines of one object."""

    def __init__(self, rng: Rand, consts: ConstGen, names, add_file=None):
        self.rng = rng
        self.consts = consts
        self.names = names
        self.add_file = add_file        # add_file(text) -> file name, for ``file "name"`` lines
        self.labels: list[DatLabel] = []
        self.lines: list[str] = []

    def section(self, n_lines: int) -> list[str]:
        rng = self.rng
        self.lines.append(rng.case("DAT"))
        for _ in range(n_lines):
            kind = rng.weighted({"data": 8, "array": 3, "string": 2, "table": 2 if self.labels else 0,
                                 "align": 1, "bare_label": 1, "pasm": 1,
                                 "file": 0.3 if self.add_file else 0})
            getattr(self, "_" + kind)()
        return self.lines

    def _label(self) -> str:
        return self.names.new("d")

    def _line(self, label: str | None, size_word: str, items: list[str]) -> None:
        pad = " " * self.rng.between(1, 12)
        self.lines.append(f"{label or ''}{pad}{self.rng.case(size_word)} {', '.join(items)}".rstrip())

    def _value(self, size: int) -> str:
        rng = self.rng
        kind = rng.weighted({"literal": 5, "const": 3, "float": 2 if size == 4 else 0,
                             "offset": 1 if self.labels and size >= 2 else 0})
        if kind == "literal":
            return int_literal(rng, int_value(rng)) if rng.chance(0.85) else "-" + int_literal(rng, rng.between(1, 300))
        if kind == "const":
            return self.consts.int_expr(rng.between(0, 2))
        if kind == "float":
            return float_literal(rng) if rng.chance(0.6) else self.consts.float_expr(1)
        return "@" + rng.case(rng.pick(self.labels).name)

    def _count(self) -> str:
        rng = self.rng
        return int_literal(rng, rng.pick([0, 1, 2, 3, 5, 8])) if rng.chance(0.8) else "1 + 1"

    def _data(self) -> None:
        """A line of mixed items: values, repetitions, size overrides, strings.

        An override holds for the rest of the line and may not be smaller than the line's size.
        """
        rng = self.rng
        size_word = rng.pick(list(SIZES))
        size = SIZES[size_word]
        items = []
        for _ in range(rng.between(1, 6)):
            kind = rng.weighted({"value": 6, "override": 3, "repeat": 2, "string": 1})
            if kind == "override":
                over = rng.pick([w for w, s in SIZES.items() if s >= SIZES[size_word]])
                size = SIZES[over]
                items.append(f"{rng.case(over)} {self._value(size)}")
            elif kind == "repeat":
                items.append(f"{self._value(size)}[{self._count()}]")
            elif kind == "string":
                items.append(self._string_text())
            else:
                items.append(self._value(size))
        label = self._label() if rng.chance(0.7) else None
        if label:
            self.labels.append(DatLabel(label, SIZES[size_word]))
        self._line(label, size_word, items)

    def _array(self) -> None:
        """A writable array: one size, known count (``long 0[4]`` or a list of values)."""
        rng = self.rng
        size_word = rng.pick(list(SIZES))
        size = SIZES[size_word]
        if rng.chance(0.5):
            count = rng.between(1, 6)
            items = [f"{self._value(size)}[{count}]"]
        else:
            count = rng.between(1, 6)
            items = [self._value(size) for _ in range(count)]
        label = self._label()
        self.labels.append(DatLabel(label, size, count))
        self._line(label, size_word, items)

    def _string_text(self) -> str:
        rng = self.rng
        letters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 !#$%&()*+-./:;<=>?[]^_{|}~"
        return '"' + "".join(rng.pick(letters) for _ in range(rng.between(1, 8))) + '"'

    def _string(self) -> None:
        label = self._label()
        self.labels.append(DatLabel(label, 1, string=True))
        items = [self._string_text()]
        if self.rng.chance(0.3):
            items.append(f"{self.rng.between(32, 126)}")
        items.append("0")
        self._line(label, "byte", items)

    def _table(self) -> None:
        rng = self.rng
        targets = [rng.pick(self.labels) for _ in range(rng.between(1, 4))]
        size_word = rng.pick(["word", "long"])
        label = self._label()
        self.labels.append(DatLabel(label, SIZES[size_word], None, table=targets))
        self._line(label, size_word, ["@" + rng.case(t.name) for t in targets])

    def _align(self) -> None:
        self.lines.append(" " * self.rng.between(1, 12) + self.rng.case(self.rng.pick(list(SIZES))))

    def _pasm(self) -> None:
        """An ``org`` block of PASM that no cog runs: every mnemonic, condition, effect and operand form."""
        from spinemu.pasm import CONDITIONS, INSTRUCTIONS, REGISTERS
        rng = self.rng
        lines = self.lines
        base = self._label()
        origin = rng.pick([0, 0, 16, 100])
        lines.append(f"{base}{' ' * rng.between(1, 6)}{rng.case('org')} {origin}" if rng.chance(0.8)
                     else f"{base}{' ' * rng.between(1, 6)}{rng.case('org')}")
        names = [base] + [self._label() for _ in range(rng.between(2, 6))]
        # local labels belong to the plain label before them: they come right after the org
        # line and only lines of that scope (the other local lines) name them
        locals_ = [f":l{i}" for i in range(rng.between(0, 2))]
        mnemonics = sorted(INSTRUCTIONS)
        scope: list = []
        returns: list = []
        operand = lambda: rng.pick([rng.case(rng.pick(names)), rng.case(rng.pick(list(REGISTERS))),
                                    str(rng.between(0, 15)), "$"] + scope)
        for name in locals_ + names[1:]:
            scope = locals_ if name.startswith(":") else []
            mnem = rng.pick(mnemonics)
            while mnem == "call" and scope:         # its x_ret line would end the local scope
                mnem = rng.pick(mnemonics)
            ins = INSTRUCTIONS[mnem]
            form = ins.operands
            if form == "call":          # call #x needs x_ret: point it at a label that has one
                target = rng.pick(names)
                if target not in returns:
                    returns.append(target)
                    lines.append(f"{target}_ret{' ' * rng.between(1, 4)}{rng.case('ret')}")
                text = f"{rng.case('call')} #{target}"
            else:
                src = operand()
                src = f"#{src}" if rng.chance(0.5) or form == "s" and rng.chance(0.5) else src
                text = {"ds": f"{mnem} {operand()}, {src}", "d": f"{mnem} {operand()}", "s": f"{mnem} {src}",
                        "": mnem}[form]
                text = rng.case(text.split(" ", 1)[0]) + text[len(text.split(" ", 1)[0]):]
                if ins.kind != "nop" and rng.chance(0.4):
                    effects = ["wz", "wc"] + (["wr", "nr"] if ins.allows_wr_nr else [])
                    text += " " + ", ".join(rng.case(e) for e in effects[:rng.between(1, len(effects))])
            cond = rng.case(rng.pick(list(CONDITIONS))) + " " if ins.kind != "nop" and rng.chance(0.3) else ""
            lines.append(f"{name}{' ' * rng.between(1, 6)}{cond}{text}")
        for _ in range(rng.between(0, 2)):
            lines.append(f"{self._label()}{' ' * rng.between(1, 6)}{rng.case('res')} {rng.between(0, 4)}")
        if rng.chance(0.5):
            lines.append(f"{' ' * rng.between(1, 6)}{rng.case('fit')}{' ' + str(0x1F0) if rng.chance(0.5) else ''}")
        # code may read these labels' longs (read only: they are instructions)
        for name in names:
            self.labels.append(DatLabel(name, 4))

    def _file(self) -> None:
        """``label file "name"``: the bytes of a generated data file."""
        rng = self.rng
        text = "".join(rng.pick("abcdefghij0123456789 ,.;") for _ in range(rng.between(1, 40)))
        name = self.add_file(text)
        label = self._label()
        self.labels.append(DatLabel(label, 1))
        self.lines.append(f"{label}{' ' * rng.between(1, 6)}{rng.case('file')} \"{name}\"")

    def _bare_label(self) -> None:
        label = self._label()
        self.lines.append(label)
        # alone on a line it has the previous directive's size: read only, size unknown here
        self.labels.append(DatLabel(label, 1))
