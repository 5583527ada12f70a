'' Number spellings Spin accepts and Python does not: runs of underscores,
'' underscores at the end, leading zeros in decimals.
CON
  MASK = %0111_1111_1000_0000__0000_0000_0000_0000
  HEX  = $FF__00_
  DEC  = 1__000_
  ZERO = 007
VAR
  long a, b, c, d, e, f
PUB main
  a := MASK
  b := HEX
  c := DEC
  d := ZERO
  e := %%3__2_1
  f := $8000_0000__ + 0__10
