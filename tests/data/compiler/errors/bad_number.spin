PUB main | x
  x := %102
