'' Evaluation order around assignment targets: object index after the arguments, byte and
'' word targets, memory and register targets with side effects in their index, chains of +=.
OBJ
  kid[3] : "order_targets_child"
VAR
  long r[60], n, x, y, arr[8]
  byte bb[8]
  word ww[4]
PUB main | i, j, p
  i := 1
  r[0] := kid[i].put(i++)
  r[1] := kid[0].get + kid[1].get * 10 + kid[2].get * 100
  i := 0
  r[2] := kid[i++].put(i)
  r[3] := kid[0].get + kid[1].get * 10 + kid[2].get * 100
  x := 1
  r[4] := kid[x // 5].put(bump)
  r[5] := kid[1].get + kid[2].get * 10
  i := 2
  bb[i] := 250
  r[6] := bb[i]~ + bb[i]
  bb[i] := 250
  r[7] := bb[i++]~ + i
  i := 2
  bb[2] := 7
  r[8] := (bb[i] += 300) + bb[i]
  ww[1] := 65000
  j := 1
  r[9] := ~~ww[j] + ww[j]
  p := @arr
  long[p][1] := 5
  r[10] := long[p][1] + (long[p][1] := 9)
  i := 1
  r[11] := long[p][i++] + long[p][i]
  r[12] := long[p += 4][0] + long[p][0]
  dira[7..0] := $FF
  i := 1
  outa[i + 3..i] := 5
  r[13] := outa[7..0] + (outa[3..0] := 9) + outa[7..0]
  i := 0
  r[14] := outa[i++ + 3..i]
  r[15] := lookup(x++ : x, 2, 3)
  r[16] := lookdown(x : 5, x, 7)
  x := 2
  r[17] := x * (x := 3) * x
  r[18] := (y := 4) + (x -= y) + x
  r[19] := x++ + x++ + x++
  r[20] := -x + !x + (x := 0)
  x := 7
  r[21] := x == x++
  x := 7
  r[22] := x <> (x := 8) and x
  r[23] := ||x #> bumpx <# x
  arr[2] := 3
  i := 2
  arr[i] += arr[i] += i++
  r[24] := arr[2]
  r[25] := arr[3]
  r[26] := ?arr[0] == arr[0]
  arr[1] := -5
  r[27] := arr[1]? <> arr[1]
  r[28] := (x := 9) ^ (x := 10) | x
  r[29] := x->1 + x<-(x := 2) + x ~> 1 + x >> 1 + x << 1
  r[30] := (x := 100) / bumpx // x
  r[31] := x ** (x := 1000) + x
  r[32] := (x := -7) >< 8 + ^^x + |<x + >|x
  r[33] := kid[(constant(TRUE * $CBF2) >> 1) // 3].put(bump)
PRI bump
  x += 10
  return x
PRI bumpx
  x := x * 3 + 1
  return x - 2
