PUB main | q[9000], z
  z := 1
