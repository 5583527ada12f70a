' Probe: variable access forms
VAR
  long lv, larr[10], lbig
  word wv, warr[3]
  byte bv, barr[5]
  long pad[30], far

PUB main(p1, p2) : r | l1, l2[4], l3
  lv := 1
  lbig := 2
  larr[0] := 3
  larr[2] := 4
  larr[lv] := 5
  wv := 6
  warr[1] := 7
  bv := 8
  barr[lv] := 9
  far := 10
  l3 := 11
  l2[1] := 12
  p2 := 13
  r := 14
  result := 15
  result[1] := 16
  lv.byte[1] := 17
  lv.word[lv] := 18
  lv.byte := 19
  lv.long := 20
  l1.word[1] := 21
  result.byte[1] := 22
  dat1.byte[2] := 23
  byte[lv] := 24
  word[lv][2] := 25
  long[lv][lbig] := 26
  lv := @larr
  lv := @larr[2]
  lv := @l2
  lv := @warr[lv]
  lv := @@lv
  lv := dat1
  lv := @dat1
  lv := dat1[2]
  lv := dat2
  lv := @dat3
  lv := word[@dat1][1]
  lv := spr[3]
  spr[4] := lv
  spr[lv]++
  lv := dira
  dira := lv
  outa[3] := 1
  outa[lv]~~
  outa[7..4] := %1010
  dira[0..3]~~
  lv := ina[5]
  lv := ina[2..0]
  !outa[1]
  outa[3..0]++
  outa++
  ctra := 1
  frqa := 2
  phsa := 3
  vcfg := 4
  vscl := 5
  lv := cnt + par
  lv := inb | outb | dirb | ctrb | frqb | phsb

DAT
dat1    long    1, 2, 3
dat2    word    4
dat3    byte    5
