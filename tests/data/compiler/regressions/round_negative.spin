' Regression: round() is x + 0.5 toward zero (negative values round up), trunc() toward zero
' (found by the program generator)
CON
  R1 = round(-680.0)
  R2 = round(-1000.383)
  R3 = round(-0.6)
PUB main | x
  x := round(-3.443)
  x := trunc(-3.443)
DAT
folded      long R1, R2, R3, round(-2.5), round(2.5), round(-1.5), trunc(-1.5), round(-0.4)
folded_end
