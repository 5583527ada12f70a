CON
  A = 10
  B = A / 0
PUB main
