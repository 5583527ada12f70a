VAR
  long mov
PUB main
