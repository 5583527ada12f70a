'' lookdown positions past $7FFF_FFFF (a range of more than 2^31 values) are negative longs,
'' as the ROM's 32-bit arithmetic leaves them, also when compared or limited afterwards.
VAR
  long w, r[6]
PUB main
  r[0] := lookdown(w: $80000000..7)
  r[1] := lookdownz(w: $80000000..7) #> 1
  r[2] := lookdown(w: 6, $80000000..7, -207) =< 1
  r[3] := lookdownz(w: 1, 2, $80000000..$7FFFFFFF) < 0
  r[4] := lookdown(w: w++, $80000000..7, w--) // 1000
  r[5] := w
  dira := r[4] & 7
