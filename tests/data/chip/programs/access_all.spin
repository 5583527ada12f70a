VAR
  long lv[40]
  long big[40]
  word wv[8]
  byte bv[8]
  long n
PUB main | a, b, c, d, e, f, g, h, arr[40]
  result := 5
  n := result
  n := @result
  n := result := 7
  result += 3
  n := result++
  a := 5
  n := a
  n := @a
  n := a := 7
  a += 3
  n := a++
  b := 5
  n := b
  n := @b
  n := b := 7
  b += 3
  n := b++
  c := 5
  n := c
  n := @c
  n := c := 7
  c += 3
  n := c++
  d := 5
  n := d
  n := @d
  n := d := 7
  d += 3
  n := d++
  e := 5
  n := e
  n := @e
  n := e := 7
  e += 3
  n := e++
  f := 5
  n := f
  n := @f
  n := f := 7
  f += 3
  n := f++
  g := 5
  n := g
  n := @g
  n := g := 7
  g += 3
  n := g++
  lv[0] := 5
  n := lv[0]
  n := @lv[0]
  n := lv[0] := 7
  lv[0] += 3
  n := lv[0]++
  lv[1] := 5
  n := lv[1]
  n := @lv[1]
  n := lv[1] := 7
  lv[1] += 3
  n := lv[1]++
  lv[2] := 5
  n := lv[2]
  n := @lv[2]
  n := lv[2] := 7
  lv[2] += 3
  n := lv[2]++
  lv[3] := 5
  n := lv[3]
  n := @lv[3]
  n := lv[3] := 7
  lv[3] += 3
  n := lv[3]++
  lv[4] := 5
  n := lv[4]
  n := @lv[4]
  n := lv[4] := 7
  lv[4] += 3
  n := lv[4]++
  lv[5] := 5
  n := lv[5]
  n := @lv[5]
  n := lv[5] := 7
  lv[5] += 3
  n := lv[5]++
  lv[6] := 5
  n := lv[6]
  n := @lv[6]
  n := lv[6] := 7
  lv[6] += 3
  n := lv[6]++
  lv[7] := 5
  n := lv[7]
  n := @lv[7]
  n := lv[7] := 7
  lv[7] += 3
  n := lv[7]++
  bv := 9
  n := bv
  n := @bv
  n := bv := 11
  bv += 2
  bv++
  bv[2] := 9
  n := bv[2]
  n := @bv[2]
  n := bv[2] := 11
  bv[2] += 2
  bv[2]++
  byte[@bv] := 4
  n := byte[@bv]
  n := @byte[@bv]
  n := byte[@bv] := 12
  byte[@bv] -= 1
  byte[@bv]--
  byte[@bv][1] := 4
  n := byte[@bv][1]
  n := @byte[@bv][1]
  n := byte[@bv][1] := 12
  byte[@bv][1] -= 1
  byte[@bv][1]--
  wv := 9
  n := wv
  n := @wv
  n := wv := 11
  wv += 2
  wv++
  wv[2] := 9
  n := wv[2]
  n := @wv[2]
  n := wv[2] := 11
  wv[2] += 2
  wv[2]++
  word[@wv] := 4
  n := word[@wv]
  n := @word[@wv]
  n := word[@wv] := 12
  word[@wv] -= 1
  word[@wv]--
  word[@wv][1] := 4
  n := word[@wv][1]
  n := @word[@wv][1]
  n := word[@wv][1] := 12
  word[@wv][1] -= 1
  word[@wv][1]--
  big := 9
  n := big
  n := @big
  n := big := 11
  big += 2
  big++
  big[2] := 9
  n := big[2]
  n := @big[2]
  n := big[2] := 11
  big[2] += 2
  big[2]++
  long[@big] := 4
  n := long[@big]
  n := @long[@big]
  n := long[@big] := 12
  long[@big] -= 1
  long[@big]--
  long[@big][1] := 4
  n := long[@big][1]
  n := @long[@big][1]
  n := long[@big][1] := 12
  long[@big][1] -= 1
  long[@big][1]--
  db := 3
  n := db
  n := @db
  n := db := 13
  db *= 2
  db~
  n := byte[@db]
  dw := 3
  n := dw
  n := @dw
  n := dw := 13
  dw *= 2
  dw~
  n := word[@dw]
  dl := 3
  n := dl
  n := @dl
  n := dl := 13
  dl *= 2
  dl~
  n := long[@dl]
  db[1] := 3
  n := db[1]
  n := @db[1]
  n := db[1] := 13
  db[1] *= 2
  db[1]~
  n := byte[@db][1]
  dw[1] := 3
  n := dw[1]
  n := @dw[1]
  n := dw[1] := 13
  dw[1] *= 2
  dw[1]~
  n := word[@dw][1]
  dl[1] := 3
  n := dl[1]
  n := @dl[1]
  n := dl[1] := 13
  dl[1] *= 2
  dl[1]~
  n := long[@dl][1]
  arr[0] := 6
  n := arr[0]
  n := @arr[0]
  n := arr[0] := 8
  arr[0] |= 1
  arr[0]~~
  arr[1] := 6
  n := arr[1]
  n := @arr[1]
  n := arr[1] := 8
  arr[1] |= 1
  arr[1]~~
  arr[30] := 6
  n := arr[30]
  n := @arr[30]
  n := arr[30] := 8
  arr[30] |= 1
  arr[30]~~
DAT
db byte 1, 2, 3, 4
dw word 1, 2, 3
dl long 5, 6, 7
