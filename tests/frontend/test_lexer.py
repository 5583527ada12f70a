"""The lexer: comments, numbers, case-insensitive keywords, sections, DAT word classes."""
from spinemu.frontend.lexer import tokenize
from spinemu.frontend.preprocess import preprocess
from spinemu.frontend.source import SourceText, decode_source, utf16_char_byte


def kinds(text, section=1, line=0):
    lexed = tokenize(text)
    return [(t.type, t.value) for t in lexed.sections[section].lines[line].tokens]


def test_keywords_are_case_insensitive_but_keep_the_users_spelling():
    assert kinds("PUB Main\n  RePeat WHILE x\n", 1, 1) == [("REPEAT", "RePeat"), ("WHILE", "WHILE"), ("NAME", "x")]


def test_numbers_in_every_base_with_underscores():
    toks = kinds("CON\n  A = $1F_FF + %10_01 + %%3_2 + 1_000 + 1.5e3 + 2.0\n")
    assert [v for t, v in toks if t in ("NUMBER", "FLOAT")] == ["$1F_FF", "%10_01", "%%3_2", "1_000", "1.5e3", "2.0"]


def test_ranges_are_not_read_as_floats():
    assert kinds("PUB m\n  outa[7..0]~~\n", 1, 1)[2:5] == [("NUMBER", "7"), ("DOTDOT", ".."), ("NUMBER", "0")]


def test_comments_of_every_kind_are_kept_by_line():
    text = "' one\n'' two\n{ three { nested } }\n{{ four\n  lines }}\nPUB m ' five\n"
    lexed = tokenize(text)
    got = {line: [(c.kind, c.text) for c in cs] for line, cs in lexed.comments.items()}
    assert got == {1: [("'", " one")], 2: [("''", " two")], 3: [("{", " three { nested } ")],
                   4: [("{{", " four\n  lines ")], 6: [("'", " five")]}
    assert lexed.comments[4][0].end_line == 5


def test_a_brace_comment_inside_a_line_is_white_space_even_across_lines():
    toks = kinds("PUB m\n  x := 1 { a\n  b } + 2\n", 1, 1)
    assert [v for _t, v in toks] == ["x", ":=", "1", "+", "2"]


def test_doc_comment_ends_at_the_first_double_brace():
    lexed = tokenize("{{ a { b }} c }}\nPUB m\n")
    assert any("'}'" in d.message for d in lexed.errors)


def test_unclosed_comment_is_reported_at_the_end_of_the_file():
    lexed = tokenize("PUB m\n{ open\n\n", eof=(4, 1))
    assert [(d.line, d.column) for d in lexed.errors] == [(4, 1)]
    assert "opened on line 2" in lexed.errors[0].message


def test_sections_need_the_first_column():
    lexed = tokenize("PUB a\n  x := 1\n PRI b\n")
    assert [s.kind for s in lexed.sections] == ["CON", "PUB", "PRI"]
    assert "first column" in lexed.errors[0].message


def test_assignment_operators_even_with_a_space_before_the_equals():
    lines = tokenize("PUB m\n  x += 1\n  x + = 2\n  x AND= 3\n  x === 4\n  x <= 5\n").sections[1].lines
    assert [ln.tokens[1].value for ln in lines[1:]] == ["+=", "+=", "AND=", "===", "<="]


def test_comparison_operators_are_not_assignments():
    toks = kinds("PUB m\n  x := a =< b or a => c or a == d or a <> e\n", 1, 1)
    assert [t for t, _ in toks if t in ("LE", "GE", "EQEQ", "NE")] == ["LE", "GE", "EQEQ", "NE"]


def test_dat_words_are_labels_conditions_instructions_and_effects_by_position():
    lexed = tokenize("DAT\nloop  if_nz  and  x, #1  wz, wc\n:inner mov a, b\n byte 1, 2\n")
    lines = lexed.sections[1].lines
    assert [t.type for t in lines[0].tokens] == ["NAME", "COND", "PASM_OP", "NAME", "COMMA", "HASH",
                                                 "NUMBER", "EFFECT", "COMMA", "EFFECT"]
    assert [(t.type, t.value) for t in lines[1].tokens[:2]] == [("LOCALNAME", ":inner"), ("PASM_OP", "mov")]
    assert lines[2].tokens[0].type == "SIZE"


def test_dat_brackets_are_repeat_counts():
    assert [t.type for t in tokenize("DAT\n long 0[4]\n").sections[1].lines[0].tokens] == \
        ["SIZE", "NUMBER", "DLSQB", "NUMBER", "RSQB"]


def test_indentation_expands_tabs_to_multiples_of_eight():
    lines = tokenize("PUB m\n\tx := 1\n  \ty := 2\n   z := 3\n").sections[1].lines
    assert [ln.indent for ln in lines[1:]] == [8, 8, 3]


def test_unterminated_string_and_stray_characters_are_errors():
    lexed = tokenize('PUB m\n  x := "abc\n  y := 1 ` 2\n')
    assert [d.line for d in lexed.errors] == [2, 3]


def test_openspins_unused_reserved_words_are_not_names():
    assert kinds("VAR\n  long enc\n")[1][0] == "RESERVED"


def test_utf16_sources_are_decoded_and_map_characters_like_openspin():
    text, enc = decode_source("PUB m\n".encode("utf-16"))
    assert (text, enc) == ("PUB m\n", "utf-16")
    src = SourceText("x.spin", 'DAT byte "é←€\uf016"', enc)
    assert src.string_bytes("é←€\uf016") == bytes([0xE9, 0x02, 0xA4, 0x16])
    assert utf16_char_byte("\u4e2d") == 0xFF


def test_non_utf8_bytes_are_read_as_latin1():
    assert decode_source(b"' caf\xe9\nPUB m\n") == ("' caf\xe9\nPUB m\n", "latin-1")


def test_source_text_always_ends_with_a_newline_and_knows_its_end():
    src = SourceText("x.spin", "PUB m\n  x := 1")
    assert src.text.endswith("\n") and src.end_position() == (2, 9)
    assert SourceText("y.spin", "PUB m\n").end_position() == (2, 1)


def test_preprocessor_conditionals_keep_line_numbers():
    text, errors = preprocess("#define A\n#ifdef A\nkeep\n#else\ndrop\n#endif\n#ifndef A\ndrop\n#endif\n")
    assert text.splitlines() == ["", "", "keep", "", "", "", "", "", ""] and not errors
