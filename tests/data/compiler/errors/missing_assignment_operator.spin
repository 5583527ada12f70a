PUB main | x
  x = 5
