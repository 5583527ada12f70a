'' next in loops whose test or step Python's continue would skip: repeat ... while/until, repeat x from with variable bounds.
VAR
  long r[40], n, top

PUB main | i, k
  k := 0
  repeat
    k++
    if k & 1
      next
    r[n++] := k
  while k < 9
  k := 0
  repeat
    k += 3
    case k
      6, 12: next
    r[n++] := k
  until k > 14
  top := 7
  repeat i from 1 to top
    if i == 3
      next
    r[n++] := i * 10
  r[n++] := i
