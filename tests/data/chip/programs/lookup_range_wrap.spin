' lookup with ranges whose ends are far apart: the ROM counts |hi - lo| + 1 items in 32 bits
' (so $8000_0000..$7FFF_FFFF holds none) and matches when index - base < count, unsigned
VAR
  long out[12]
PUB main | i
  out[0] := lookup($8000_0000: $8000_0000..2, 777)
  out[1] := lookup($8000_0003: $8000_0000..2, 777)
  out[2] := lookup($8000_0000: 2..$8000_0000, 777)
  out[3] := lookup($8000_0001: $7FFF_FFFF..-5, 777)
  out[4] := lookup(1: $8000_0000..$7FFF_FFFF, 777)
  out[5] := lookup(2: $8000_0000..$7FFF_FFFF, 777)
  out[6] := lookup(1: $7FFF_FFFF..$8000_0000, 777)
  out[7] := lookupz(0: 0..$FFFF_FFFF, 5)
  out[8] := lookdown(1: $8000_0000..$7FFF_FFFF, 777)
  out[9] := lookdown(777: 5, $8000_0000..2, 777)
  i := -1
  out[10] := lookup(i: 1..3, 9)
  out[11] := lookup(3: 1..3, 9)
