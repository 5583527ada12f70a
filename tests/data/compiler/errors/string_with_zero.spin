PUB main | x
  x := string("a", 0)
