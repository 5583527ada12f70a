'' An object array named without an index means its element 0, as in
'' OBJ v[4] : "x" ... v.start: calls, constants and each element's own VAR.
OBJ
  kid[3] : "semantics_child"
VAR
  long r1, r2, r3, r4
PUB main
  r1 := kid.twice(5)                    ' element 0: 5 * 2 + 1
  r2 := kid.twice(5)                    ' element 0 again: + 2
  r3 := kid[1].twice(kid#FACTOR)        ' element 1 has its own count: 3 * 2 + 1
  r4 := kid[0].twice(0)                 ' element 0's third call
  dira[0..3]~~
  outa[0..3] := r1 + r2 + r3 + r4
