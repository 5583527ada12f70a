' Probe: long offsets (VAR, locals, DAT past 127 bytes), long jumps, register ranges both ways
VAR
  long first, pad[40], far
  word wfar
  byte bfar

PUB main | a, locs[40], lfar
  far := 1
  wfar := 2
  bfar := 3
  lfar := 4
  locs[39] := 5
  far := tab[100]
  far := @tab2
  outa[0..3]~~
  outa[3..0]~
  dira[first..far] := lfar
  result~~
  spr[2] += 3
  if first
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
  repeat while first
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
    far := $12345678
  case far
    1: first := 1
    other: first := 2

DAT
tab   byte 0[200]
tab2  long 1, 2
