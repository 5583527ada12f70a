' Regression: in code, round( trunc( float( start a constant expression that takes the rest of
' the expression; '-' before constant()/round()/obj#K negates at run time
' (found by the program generator)
OBJ
  c : "constant_groups_child"
VAR
  long x, y[4]
PUB main
  x := round(1.5) + 2
  x := x * round(1.5) + 2
  x := x + round(1.5) * 2 + 1
  x := (y[1] + trunc(2.5) << 1) + 1
  x := y[round(1.5) + 1]
  x := float(3) * 2.0 > 1.0
  x := round(1.5) == 2
  x := -round(1.5) * 2
  x := -constant(2) + 1
  x := -float(2)
  x := -c#K
  x := - 5
  x := -"A"
  x := lookup(x: round(1.5)..5, 7)
