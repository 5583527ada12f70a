'' Lookup items paid one by one whose value reads a register and then calls a method: the
'' call is paid before the method runs (the method changes pins), the rest once it returns.
VAR
  long n, r[4]
PUB main
  r[0] := lookdown(7: 1, probe(outa))
  r[1] := lookup(2: 5, probe(ina) + 1, 9)
  r[2] := lookupz(1: 3, probe(cnt & 0) | 4, 4)
  r[3] := lookdownz(2: outa[3], probe(dira) * 2, 2)
  dira[n]~~
PRI probe(v) : x
  dira[n++]~~
  x := n
