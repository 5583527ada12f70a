PUB main | x
  x := string("abc)
