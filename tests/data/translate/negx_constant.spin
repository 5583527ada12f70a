'' The negation of a constant that is NEGX (-NEGX is NEGX again in 32 bits), whether the
'' constant is written NEGX or $8000_0000, used where the long's sign matters.
CON
  K1 = NEGX
  K2 = $8000_0000
VAR
  long r[6]
PUB main
  r[0] := 0 #> -K1
  r[1] := -K2 < 0
  r[2] := (-K1) / 3
  r[3] := -K2 <# 5
  r[4] := (-K1 // 7) + (-NEGX > 0)
  r[5] := -$8000_0000 => 0
  dira := r[2] & 15
