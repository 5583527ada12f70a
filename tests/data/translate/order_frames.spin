'' Evaluation order with locals in a hub frame (their address is taken), RESULT, and side
'' effects in if, repeat (count, while, until, from) and case selectors, and aborts.
VAR
  long r[60], n, x, y, arr[8], stack[40], flag
PUB main | i, j, buf[4]
  i := 2
  buf[i] := 5
  r[0] := buf[i] + (buf[i] := 7) + buf[i]
  r[1] := buf[i++] + buf[i]
  r[2] := (result := 3) + result++ + result
  r[3] := i + setlocal(@i) + i
  r[4] := buf[1] + setlocal(@buf[1]) + buf[1]
  i := 1
  buf[i] += setlocal(@buf[i])
  r[5] := buf[1]
  i := 1
  r[6] := buf.byte[i++] + buf.byte[i]
  x := 0
  if (x := x + 1) == 1 and x++ == 1
    r[7] := x
  repeat j from x to x + 2
    r[8] += j
  x := 0
  repeat while x++ < 3 and (y := x) < 5
    r[9] += x * 10 + y
  x := 0
  repeat
    r[10] += x
  until x++ == 4
  x := 3
  repeat x++
    r[11] += x
  r[12] := \tr(1) + tr(0) + x
  x := 0
  r[13] := \tr(x++) + x
  x := 5
  case x++
    5: r[14] := x
    6: r[14] := 100
  case x += 1
    7: r[15] := x
    other: r[15] := -1
  case bumpx
    1..10: r[16] := x
    other: r[16] := x * 1000
PRI setlocal(p)
  long[p] := long[p] * 10 + 1
  return long[p]
PRI tr(v)
  x += 100
  if v
    abort x
  return x + 1
PRI bumpx
  x := x * 3 + 1
  return x - 2
