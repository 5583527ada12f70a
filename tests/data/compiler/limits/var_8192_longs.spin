VAR
  long v[8192]
  word w
PUB main
  w := 1
  v[1] := 2
