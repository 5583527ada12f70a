OBJ
  c : "child_ok"
PUB main
  c.nosuch
