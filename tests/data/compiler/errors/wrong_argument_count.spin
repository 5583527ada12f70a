PUB main
  f(1, 2)
PRI f(a)
  return a
