PUB main | x
  x := 1
  x := y + 1
