PUB main | x
  case x
    other: x := 1
    2: x := 2
