OBJ
  c : "child_nopub"
PUB main
