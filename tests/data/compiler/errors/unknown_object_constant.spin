OBJ
  c : "child_ok"
CON
  A = c#NOPE
PUB main
