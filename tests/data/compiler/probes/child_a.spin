CON
  COUNT = 4

VAR
  long v

PUB start(x)
  v := x

PUB value
  return v
