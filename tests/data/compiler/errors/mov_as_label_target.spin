PUB main | x
  x := @nosuch
