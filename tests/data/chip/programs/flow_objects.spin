OBJ
  one : "sub_obj"
  many[3] : "sub_obj"
VAR
  long v0, v1, v2, v3, v4, v5, v6, v7
  long pad[40]
  long far_l
  word far_w
  byte far_b
PUB main | a, b, c, d, e, f, g, big[40], farloc
  far_l := 1
  v0 := 5
  v0 := v0
  v0 := @v0
  v0 := v0 := 7
  v0 += 3
  v1 := 5
  v0 := v1
  v0 := @v1
  v0 := v1 := 7
  v1 += 3
  v2 := 5
  v0 := v2
  v0 := @v2
  v0 := v2 := 7
  v2 += 3
  v3 := 5
  v0 := v3
  v0 := @v3
  v0 := v3 := 7
  v3 += 3
  v4 := 5
  v0 := v4
  v0 := @v4
  v0 := v4 := 7
  v4 += 3
  v5 := 5
  v0 := v5
  v0 := @v5
  v0 := v5 := 7
  v5 += 3
  v6 := 5
  v0 := v6
  v0 := @v6
  v0 := v6 := 7
  v6 += 3
  v7 := 5
  v0 := v7
  v0 := @v7
  v0 := v7 := 7
  v7 += 3
  far_l := 1
  v1 := far_l
  v1 := @far_l
  v1 := far_l := 2
  far_l += 1
  far_l++
  far_l[0] := 1
  v1 := far_l[0]
  v1 := @far_l[0]
  v1 := far_l[0] := 2
  far_l[0] += 1
  far_l[0]++
  far_w := 1
  v1 := far_w
  v1 := @far_w
  v1 := far_w := 2
  far_w += 1
  far_w++
  far_w[0] := 1
  v1 := far_w[0]
  v1 := @far_w[0]
  v1 := far_w[0] := 2
  far_w[0] += 1
  far_w[0]++
  far_b := 1
  v1 := far_b
  v1 := @far_b
  v1 := far_b := 2
  far_b += 1
  far_b++
  far_b[0] := 1
  v1 := far_b[0]
  v1 := @far_b[0]
  v1 := far_b[0] := 2
  far_b[0] += 1
  far_b[0]++
  farloc := 1
  v1 := farloc
  v1 := @farloc
  v1 := farloc := 3
  farloc -= 1
  fdl := 1
  v1 := fdl
  v1 := @fdl
  v1 := fdl := 3
  fdl -= 1
  fdl~
  fdw := 1
  v1 := fdw
  v1 := @fdw
  v1 := fdw := 3
  fdw -= 1
  fdw~
  fdb := 1
  v1 := fdb
  v1 := @fdb
  v1 := fdb := 3
  fdb -= 1
  fdb~
  byte[@big] := 1
  word[@big] := 1
  v1 := word[@big] := 2
  long[@big] ^= 3
  word[@big] ^= 3
  v1 := @byte[@big]
  v1 := @word[@big]
  byte[@big]++
  farloc[1] := 1
  v1 := farloc[1]
  v1 := @farloc[1]
  v1 := farloc[1] := 3
  farloc[1] -= 1
  fdl[1] := 1
  v1 := fdl[1]
  v1 := @fdl[1]
  v1 := fdl[1] := 3
  fdl[1] -= 1
  fdl[1]~
  fdw[1] := 1
  v1 := fdw[1]
  v1 := @fdw[1]
  v1 := fdw[1] := 3
  fdw[1] -= 1
  fdw[1]~
  fdb[1] := 1
  v1 := fdb[1]
  v1 := @fdb[1]
  v1 := fdb[1] := 3
  fdb[1] -= 1
  fdb[1]~
  byte[@big][1] := 1
  word[@big][1] := 1
  v1 := word[@big][1] := 2
  long[@big][1] ^= 3
  word[@big][1] ^= 3
  v1 := @byte[@big][1]
  v1 := @word[@big][1]
  byte[@big][1]++
  repeat 3
    v2++
  repeat v3
    v2++
  v3 := 0
  repeat v3
    v2++
  repeat while v2 < 10
    v2++
  repeat until v2 > 12
    v2++
  repeat
    v2++
  while v2 < 15
  repeat
    v2++
  until v2 > 17
  if v2 > 1
    v1 := 1
  elseif v2 > 0
    v1 := 2
  else
    v1 := 3
  ifnot v2
    v1 := 5
  repeat a from 1 to 3
    repeat b from 3 to 1
      v4++
      if v4 > 100
        quit
      next
  repeat 2
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  repeat c from 0 to 2
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  repeat c from 0 to 4 step 2
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  v2 := 0
  repeat while v2 < 2
    v2++
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  if v2 == 99
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  else
    v1 := 1
  case v2
    0: v1 := 0
    1: v1 := 1
    2: v1 := 2
    3: v1 := 3
    4: v1 := 4
    5: v1 := 5
    6: v1 := 6
    7: v1 := 7
    8: v1 := 8
    9: v1 := 9
    10: v1 := 10
    11: v1 := 11
    12: v1 := 12
    13: v1 := 13
    14: v1 := 14
    15: v1 := 15
    16: v1 := 16
    17: v1 := 17
    18: v1 := 18
    19: v1 := 19
    30..40: v1 := 9
    other: v1 := 0
  case v1
    0..5: v1 := 0
    10..15: v1 := 1
    20..25: v1 := 2
    30..35: v1 := 3
    40..45: v1 := 4
    50..55: v1 := 5
    60..65: v1 := 6
    70..75: v1 := 7
    80..85: v1 := 8
    90..95: v1 := 9
    100..105: v1 := 10
    110..115: v1 := 11
  repeat d from 0 to 2
    repeat outa from 0 to 2
      v2++
    repeat dira from 0 to 6 step 3
      v2++
  repeat outa from 0 to 2
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  repeat dira from 0 to 6 step 3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  repeat d from 0 to 6 step 3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
    v5 := v6 + v7 * v4 - v3
  dira := 0
  outa := 0
  v1 := one.get(3)
  one.get(4)
  repeat e from 0 to 2
    v1 := many[e].get(e)
    many[e].get(e)
  v1 := one#K
  pad[0] := 1
  repeat 3
    repeat 2
      v2++
      quit
    v2++
  repeat 3
    v2++
    if v2 > 0
      quit
  case v2
    1..3:
      repeat 2
        if v2
          quit
DAT
padding long 0[40]
fdl long 7
fdw word 7
fdb byte 7
