' Regression: CON lines are read in two passes; a constant may use one defined further down
' when that one is known after the first pass (found by the program generator)
CON
  B = C, A = B
  C = 1
  D = E + 1
  E = 2
PUB main
DAT
folded      long A, B, C, D, E
folded_end
