'' Spin evaluates operands left to right: a value read before a later operand's side effect
'' (x := ..., x++, ~x, ~~x, ?x, x += ..., a method call) keeps what it read.
VAR
  long r[40], n, x, y, arr[4]
  byte b
  word w
PUB main | i, j, k
  x := 5
  r[0] := x + (x := 7)
  i := 3
  r[1] := i + (i := 10)
  r[2] := i + i++
  r[3] := i++ + i
  r[4] := x + x++
  r[5] := x + ++x
  r[6] := ++x + (x := 100)
  j := 1
  r[7] := j * 10 + (j += 4)
  r[8] := (j := 2) + (j := 3)
  x := 9
  r[9] := x - x~
  x := 9
  r[10] := x - x~~
  b := 200
  r[11] := b + ~b
  w := 40000
  r[12] := w + ~~w
  x := 1234
  r[13] := x + ?x
  r[14] := x + x?
  i := 0
  arr[i] := i++
  arr[i++] := i
  r[15] := arr[0]
  r[16] := arr[1]
  r[17] := arr[2]
  i := 1
  arr[i] += i++
  r[18] := arr[1]
  r[19] := f(i, i++, i)
  r[20] := y + g
  r[21] := g + y
  x := 3
  r[22] := x and (x := 0)
  x := 3
  r[23] := x or (x := 0)
  k := 5
  r[24] := k < (k := 1)
  k := 5
  r[25] := k #> (k := 10)
  r[26] := k / (k := 2)
  i := 0
  r[27] := lookup(i++ : i, i, 7)
  r[28] := x += g
  r[29] := arr[g & 3] += g
PRI f(a, bb, c)
  return a * 100 + bb * 10 + c
PRI g
  y += 3
  x += 1
  return y
