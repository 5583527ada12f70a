"""The parser: every Spin construct to AST nodes with positions; indentation; syntax errors."""
import pytest

from spinemu.diagnostics import ParseError
from spinemu.frontend import ast, parse_source


def method_body(text):
    return parse_source("PUB main | x, y\n" + text).methods[0].body


def expr(text):
    return method_body(f"  x := {text}\n")[0].expr.value


def test_con_definitions_and_enumerations():
    f = parse_source("CON\n  A = 1, B = A + 2\n  #0, RED, GREEN[2], BLUE\n  _clkmode = xtal1 + pll16x\n")
    kinds = [type(c).__name__ for c in f.cons]
    assert kinds == ["ConDef", "ConDef", "ConEnumStart", "ConEnumName", "ConEnumName", "ConEnumName", "ConDef"]
    assert f.cons[4].name == "GREEN" and f.cons[4].skip.value == 2


def test_var_obj_and_method_declarations():
    f = parse_source('VAR\n  long a, b[4]\n  byte c\nOBJ\n  s : "serial"\n  t[2] : "timer"\n'
                     "PUB go(p, q) : r | l, buf[8]\nPRI helper\n")
    assert [(v.size, v.name, v.count is not None) for v in f.vars] == [(4, "a", False), (4, "b", True), (1, "c", False)]
    assert [(o.name, o.filename, o.count is not None) for o in f.objs] == [("s", "serial", False), ("t", "timer", True)]
    go, helper = f.methods
    assert (go.public, go.name, [p for p, _ in go.params], go.result) == (True, "go", ["p", "q"], "r")
    assert [(l.name, l.count is not None) for l in go.locals] == [("l", False), ("buf", True)]
    assert (helper.public, helper.params, helper.result) == (False, [], None)


def test_result_may_be_named_result():
    assert parse_source("PUB f : result\n").methods[0].result == "result"


def test_every_node_knows_its_file_line_and_column():
    f = parse_source("PUB main\n  outa[0]~~\n", "blink.spin")
    stmt = f.methods[0].body[0]
    assert (stmt.pos.path, stmt.pos.line, stmt.pos.col) == ("blink.spin", 2, 3)
    assert stmt.expr.target.bit.pos.col == 8


@pytest.mark.parametrize("text,shape", [
    ("a + b * c", ("+", "NameRef", "*")),
    ("a * b + c", ("+", "*", "NameRef")),
    ("a << 2 & b", ("&", "<<", "NameRef")),
    ("a | b & c", ("|", "NameRef", "&")),
    ("a == b AND c", ("AND", "==", "NameRef")),
    ("not a == b", ("NOT", "==")),
    ("a OR b AND c", ("OR", "NameRef", "AND")),
    ("a #> b + c", ("#>", "NameRef", "+")),
    ("-a * b", ("*", "-", "NameRef")),
])
def test_operator_precedence_follows_the_manual(text, shape):
    e = expr(text)
    assert e.op == shape[0]
    if isinstance(e, ast.Binary):
        for side, want in zip((e.left, e.right), shape[1:]):
            assert (side.op if hasattr(side, "op") else type(side).__name__) == want


def test_an_assignment_takes_the_rest_of_the_expression():
    e = expr("1 + y := 3 + 4")
    assert isinstance(e, ast.Binary) and isinstance(e.right, ast.Assign)
    assert e.right.value.op == "+"


def test_assignment_operators_keep_their_binary_operator():
    body = method_body("  x += 1\n  x AND= 1\n  x === 1\n  x <= 1\n  x := 1\n")
    assert [s.expr.op for s in body] == ["+", "AND", "==", "<", ":="]


def test_prefix_postfix_and_address_operators():
    body = method_body("  ++x\n  x--\n  x~~\n  ~~x\n  ?x\n  x := @y\n  x := @@y\n  !outa[0]\n")
    assert [type(s.expr).__name__ for s in body[:5]] == ["PreOp", "PostOp", "PostOp", "PreOp", "PreOp"]
    assert isinstance(body[5].expr.value, ast.AddrOf) and isinstance(body[6].expr.value, ast.ObjAddr)
    assert isinstance(body[7].expr, ast.Unary) and body[7].expr.op == "!"


def test_variable_forms():
    body = method_body("  x := y[2]\n  x := y.byte[1]\n  x := byte[y][3]\n  x := word[y]\n"
                       "  x := outa[3..0]\n  x := ina[2]\n  x := spr[4]\n  x := result[1]\n  x := result.word\n")
    kinds = [type(s.expr.value).__name__ for s in body]
    assert kinds == ["NameRef", "MemberRef", "MemRef", "MemRef", "RegRef", "RegRef", "SprRef", "ResultRef", "MemberRef"]
    assert body[4].expr.value.bit2 is not None and body[5].expr.value.bit2 is None


def test_calls_object_calls_constants_and_abort_traps():
    body = method_body("  f(1, 2)\n  s.tx(65)\n  t[1].go\n  x := s#BAUD\n  x := \\f(3)\n  \\s.stop\n  g\n")
    assert isinstance(body[0].expr, ast.Call) and len(body[0].expr.args) == 2
    assert (body[1].expr.obj, body[1].expr.method) == ("s", "tx")
    assert body[2].expr.index is not None and body[2].expr.args == []
    assert isinstance(body[3].expr.value, ast.ObjConst)
    assert isinstance(body[4].expr.value, ast.AbortTrap) and isinstance(body[5].expr, ast.AbortTrap)
    assert isinstance(body[6].expr, ast.NameRef)


def test_built_ins_and_lookups():
    body = method_body('  bytemove(@x, @y, 4)\n  x := string("hi", 13)\n  x := cogid\n'
                       '  x := lookupz(y: 1, 2..5, "a")\n  x := constant(3 * 4)\n  reboot\n')
    assert body[0].expr.name == "bytemove" and len(body[0].expr.args) == 3
    assert body[2].expr.value.args is None
    look = body[3].expr.value
    assert look.name == "lookupz" and isinstance(look.items[1], ast.Range)


def test_if_elseif_else_chain():
    (st,) = method_body("  if x\n    y := 1\n  elseifnot y\n    y := 2\n  elseif x\n    y := 3\n  else\n    y := 4\n")
    assert [b.negate for b in st.branches] == [False, True, False] and len(st.else_body) == 1


def test_case_with_values_ranges_other_and_inline_statements():
    (st,) = method_body("  case x\n    1, 3: y := 1\n          y := 2\n    4..6:\n      y := 3\n    other: y := 4\n")
    assert [len(i.body) for i in st.items] == [2, 1, 1]
    assert st.items[2].values is None and isinstance(st.items[1].values[0], ast.Range)


def test_an_inline_block_statement_after_a_case_value_owns_the_lines_below_it():
    (st,) = method_body("  case x\n    1: if y\n         x := 1\n       else\n         x := 2\n")
    inner = st.items[0].body[0]
    assert isinstance(inner, ast.If) and inner.else_body is not None


def test_every_repeat_form():
    body = method_body("  repeat\n    x++\n  repeat 5\n  repeat x from 1 to 9 step 2\n    y++\n"
                       "  repeat while x\n  repeat until y\n  repeat\n    x++\n  while y\n  repeat\n  until x\n")
    kinds = [(type(s).__name__, getattr(s, "until", None), getattr(s, "post", None)) for s in body]
    assert kinds == [("RepeatForever", None, None), ("RepeatCount", None, None), ("RepeatFrom", None, None),
                     ("RepeatWhile", False, False), ("RepeatWhile", True, False),
                     ("RepeatWhile", False, True), ("RepeatWhile", True, True)]
    assert body[2].step is not None


def test_blocks_are_made_by_indentation_and_lines_need_not_line_up():
    (st, after) = method_body("  if x\n      y := 1\n    y := 2\n  x := 3\n")
    assert len(st.branches[0].body) == 2 and isinstance(after, ast.ExprStmt)


def test_statements_may_start_in_column_one_of_a_method():
    assert len(parse_source("PUB m | x\nx := 1\nrepeat\n  x++\n").methods[0].body) == 2


def test_else_must_line_up_with_its_if():
    with pytest.raises(ParseError, match="'else' must line up with its 'if'"):
        parse_source("PUB m | x\n  if x\n    x := 1\n else\n    x := 2\n")


def test_return_abort_next_quit():
    body = method_body("  repeat\n    next\n    quit\n  return\n  return x\n  abort\n  abort 3\n")
    assert [type(s).__name__ for s in body[0].body] == ["Next", "Quit"]
    assert [type(s).__name__ for s in body[1:]] == ["Return", "Return", "Abort", "Abort"]
    assert body[1].value is None and body[2].value is not None


def test_dat_lines():
    f = parse_source("DAT\n  org 0\nstart if_c mov x, #1 wz, wc\n:l  jmp #:l\ntab byte 1, word 2, 3[4]\n"
                     "  res 2\n  fit\n  long\n")
    kinds = [type(d.body).__name__ for d in f.dat]
    assert kinds == ["Org", "Instruction", "Instruction", "Data", "Res", "Fit", "Data"]
    ins = f.dat[1].body
    assert (f.dat[1].label.name, ins.cond, ins.mnemonic, ins.effects) == ("start", "if_c", "mov", ["wz", "wc"])
    assert ins.operands[1].immediate and f.dat[2].label.local
    items = f.dat[3].body.items
    assert [(i.size, i.count is not None) for i in items] == [(None, False), (2, False), (None, True)]


def test_comments_are_kept_for_the_translator():
    f = parse_source("PUB main  ' starts here\n  x := 1 { inline }\n")
    assert f.comments_at(1)[0].text == " starts here" and f.comments_at(2)[0].kind == "{"


def test_syntax_errors_speak_the_users_language_and_several_are_reported():
    with pytest.raises(ParseError) as info:
        parse_source("CON\n  A = \nPUB m | x\n  x := (1 + 2\nPUB n\n  if\n")
    msgs = [(d.line, d.message) for d in info.value.diagnostics]
    assert [line for line, _ in msgs] == [2, 4, 6]
    assert msgs[0][1] == "unexpected end of line; expected an expression"
    assert "')'" in msgs[1][1]
