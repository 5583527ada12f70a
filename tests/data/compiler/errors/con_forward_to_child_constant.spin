' the first CON pass does not see a child's constants, so B is not known when A needs it
OBJ
  c : "child_const"
CON
  A = B
  B = c#K
PUB main
