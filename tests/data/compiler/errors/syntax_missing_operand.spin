PUB main | x
  x := 3 +
