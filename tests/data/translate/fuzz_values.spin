'' Values the random program generators found computed differently by the Python engine:
'' comparisons used as numbers (TRUE is -1), a shift count of an expression, AND/OR on an
'' unwrapped value, several lookups on one line, an empty case, strings in conditions and in
'' the value of an assignment whose target holds a string, lookups and case values with side
'' effects (reached or not), x OR= f(y).
VAR
  long r[40], a, b, calls
  word w[8]
PUB main | i, k
  a := 3
  b := 5
  r[0] := (a < b) ** 1
  r[1] := (a < b) << 4
  r[2] := -(a < b) + !(a == b) + ||(a > b)
  r[3] := byte[@r][(a < b) & 3]
  r[4] := 1 << ($8000_0000 ^ b)
  r[5] := (1 << 32 + a) OR tick(1)
  r[6] := lookup(a : 5, 6, 7) + lookdown(b : 1, 5, 9) + lookupz(lookdownz(a : 1, 2, 3) : 10, 20, 30)
  if strsize(string("hello"))
    r[7] := strcomp(string("ab"), string("ab"))
  r[8] := (w[strsize(string("x"))] := strsize(string("abcdef")))
  r[9] := w[1]
  i := 2
  r[10] := lookup(i : tick(1), tick(2), tick(3))
  r[11] := lookdown(b : 1, (k := 5), tick(10))
  r[12] := lookupz(i : 7, a / 3, 9, b // 0)
  r[13] := lookdownz(b : 1..3, tick(4)..tick(6))
  r[14] := k
  case b
    1, tick(20): r[15] := 1
    (k := 5): r[15] := 2
    tick(30): r[15] := 3
  i := 0
  r[16] := i OR= tick(40)
  r[17] := i AND= a / 2
  r[18] := lookup(a : 1, lookupz(b : 9, -7..0, 5), tick(50))
  outa[7..0] := 15
  r[19] := ++outa[3..0] + --outa[7..4] << 8
  r[20] := lookup(2 : 4, 1..5) - where       ' a frame's address after a lookup on the stack
  r[38] := calls
  r[39] := k
PRI where | l[2]
  return @l
PRI tick(v)
  calls++
  return v
