' Regression: NOT stands wherever a term may; its operand takes what follows up to comparisons
' (found by the program generator)
CON
  K1 = 2 * NOT 0 + 1
  K2 = NOT 1 == 0
  K3 = 4 + NOT 0 AND 1
VAR
  long x, y, z
PUB main
  x := x + NOT y
  x := x + NOT y + z
  x := x + NOT y == z
  x := x == NOT y + z
  x := x * NOT y + z
  x := x AND NOT y OR z
  x := x + NOT y AND z
  x := NOT NOT y == z
DAT
folded      long K1, K2, K3, 2 * NOT 0 + 1
folded_end
