PUB main | q[8191], z
  z := 1
