PUB main | x
  if x
    quit
