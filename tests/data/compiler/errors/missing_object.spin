OBJ
  s : "no_such_object"
PUB main
