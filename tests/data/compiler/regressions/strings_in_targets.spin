' Regression: when an assignment target (or an object-array index) holds a string, the
' strings of the value (arguments) keep their addresses but are written over in the pool
' (found by the program generator)
OBJ
  c[2] : "constant_groups_child"
VAR
  long x, t[8]
PUB main
  t[strsize(string("a"))] := strsize(string("x9z"))
  x := strsize(string("zz"))
  x := (t[strsize(string("a"))] += strsize(string("x9z")))
  t[strsize(string("a"))] := strsize(string("x9z")) + (t[strsize(string("bb"))] := strsize(string("ccc")))
  byte[@t][((t[(strsize(string("z9"))) & 7] AND= strsize(string("91")))) & 7] := -(strsize(string("1cbcz")))
  c[strsize(string("q")) & 1].g(strsize(string("arg1")), string("arg2"))
  x := strsize(string("end"))
