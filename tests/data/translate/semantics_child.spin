CON
  FACTOR = 3

VAR
  long calls

PUB twice(x)
  calls++
  return x * 2 + calls
