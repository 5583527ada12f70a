PUB main | x
  x := y
  x := y + 1
  z := 3
