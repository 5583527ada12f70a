'' NOT of a parenthesised AND/OR applies to the whole group:
'' not (a and b) is not ((not a) and b).
VAR
  long r1, r2, r3, r4
PUB main | a, b
  a := 1
  b := 0
  r1 := not (a and b)                   ' TRUE
  r2 := not ((a < 2) and (b > 5))       ' TRUE
  if not ((a == 1) or (b == 1))         ' taken only if both differ
    r3 := 1
  else
    r3 := 2
  r4 := not (b or not a)                ' TRUE
