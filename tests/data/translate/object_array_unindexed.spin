'' An object array named without an index means its element 0, as in
'' OBJ v[4] : "x" ... v.start: calls, constants and each element's own VAR;
'' a single object indexed with 0 is itself.
OBJ
  kid[3] : "semantics_child"
  one : "semantics_child"
VAR
  long r1, r2, r3, r4, r5
PUB main
  r1 := kid.twice(5)                    ' element 0: 5 * 2 + 1
  r2 := kid.twice(5)                    ' element 0 again: + 2
  r3 := kid[1].twice(kid#FACTOR)        ' element 1 has its own count: 3 * 2 + 1
  r4 := kid[0].twice(0)                 ' element 0's third call
  r5 := one[0].twice(1) + one.twice(1)  ' 1 * 2 + 1, then 1 * 2 + 2
  dira[0..7]~~
  outa[0..7] := r1 + r2 + r3 + r4 + r5
