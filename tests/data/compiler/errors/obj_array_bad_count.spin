OBJ
  c[x] : "child_ok"
PUB main
