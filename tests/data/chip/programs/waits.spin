VAR
  long n, t
PUB main | i
  repeat i from 0 to 40
    t := cnt
    waitcnt(t + 3000 + i * 4)
  repeat i from 0 to 40
    t := 700 - i * 4
    waitcnt(cnt + t)
  dira[5] := 1
  outa[5] := 1
  waitpeq(|< 5, |< 5, 0)
  waitpne(0, |< 5, 0)
  n := cnt[5]
  n := cnt[7..0]
  n := ina[3]
  n := ina[7..0]
  n := ina
  n := spr[1]
