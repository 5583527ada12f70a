'' AND/OR chains whose last operand has a side effect or a cost (a CNT read, a call, a division):
'' Spin evaluates every operand and gives TRUE (-1) or FALSE (0), so the Python engine joins them
'' with & and |, and an inner `a and b` of two non-boolean values must count as true or false,
'' not as the value of b.
VAR
  long r[12], a, b, calls
PUB main | t
  a := 6
  b := 2                                      ' 6 & 2 = 2 and 6 & 1 = 0: bit tests would go wrong
  t := cnt
  r[0] := a and b and cnt - t > 0
  r[1] := a and 1 and tick(3)
  r[2] := (a or 0) and b // 1 == 0
  r[3] := 0 or a and tick(1)
  r[4] := a and b or tick(0)
  if a and b and cnt - t > 100
    r[5] := 1
  if a and 1 and tick(1)
    r[6] := 1
  repeat while a and b and tick(a-- - 3)
    r[7]++
  r[8] := calls
  r[9] := a
PRI tick(n)
  calls++
  return n
