CON
  count = 3
VAR
  long count
PUB main
