CON
  K = 42
VAR
  long x
PUB get(a)
  x += a
  return x
