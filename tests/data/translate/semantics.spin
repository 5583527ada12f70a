'' Spin semantics for the cross-check: case, lookup, abort/trap, strings, loops, objects.
CON
  LIMIT = 20

VAR
  long r[64], n
  byte text[8]

OBJ
  child : "semantics_child"

PUB main | i, k
  repeat i from 0 to 11
    case i
      0: r[n++] := 100
      1, 2: r[n++] := 200 + i
      3..5: r[n++] := lookupz(i - 3: 7, 8, 9)
      other: r[n++] := lookdown(i: 6, 8, 10..12)
  r[n++] := \risky(1)
  r[n++] := \risky(0)
  r[n++] := strsize(string("hello"))
  r[n++] := strcomp(string("ab"), string("ab"))
  bytemove(@text, string("spin"), 5)
  r[n++] := text[2]
  k := 0
  repeat
    k += 3
  until k > LIMIT
  r[n++] := k
  repeat while k > 0
    k -= 7
    if k == 6
      next
    r[n++] := k
  r[n++] := child.twice(21)
  r[n++] := child#FACTOR * 2
  repeat i from 5 to 1 step 2
    r[n++] := i
  r[n++] := -17 / 5
  r[n++] := -17 // 5
  r[n++] := $8000_0000 >> 4
  r[n++] := $8000_0000 ~> 4
  r[n++] := 1 << 33
  r[n++] := |< 31
  r[n++] := >| $100
  r[n++] := ^^ 1000
  r[n++] := 12 #> 50 <# 40
  r[n++] := (3 > 2) and (1 == 1)
  dira[3..0] := %1111
  repeat i from 0 to 3
    outa[i] := 1
    waitcnt(cnt + 400)
  outa[3..0] := 0

PRI risky(ok)
  if not ok
    abort 77
  return 5
