' Regression: a constant the second CON pass meets again with the value it already has is
' accepted (OpenSpin; a library object defines "cols = vga#cols" on two lines); found by the
' Windows-case library measurement
OBJ
  c : "constant_groups_child"
CON
  COLS = c#K
  ROWS = COLS * 2
  COLS = c#K
  X = Y
  X = Y
  Y = 3
PUB main
DAT
folded      long COLS, ROWS, X, Y
folded_end
