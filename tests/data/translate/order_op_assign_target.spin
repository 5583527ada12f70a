'' OP= whose value writes the target: Spin computes the value first and reads the target after
'' it, so the target's read sees the write (Python's  T op= V  and  T = T op V  read T first).
VAR
  long g, r[6]
PUB main
  g := -5
  g =>= lookupz(7: 1, 2, (long[@g] := 0))    ' the write is in a lookup item reached last: 0 => 0
  r[0] := g
  g := 5
  g += (long[@g] := 7)                        ' 7 + 7
  r[1] := g
  g := 5
  g *= lookup(3: 1, 2, (g := 3))              ' 3 * 3
  r[2] := g
  g := 5
  g -= setg(100)                              ' 100 - 1
  r[3] := g
  r[4] := 9
  r[4] #>= (r[4] := 2) + 1                    ' 2 #> 3
PRI setg(v)
  g := v
  return 1
