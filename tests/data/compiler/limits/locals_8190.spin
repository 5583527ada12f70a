PUB main | q[8190], z
  z := 1
