CON
  A = 1.5 + 2
PUB main
