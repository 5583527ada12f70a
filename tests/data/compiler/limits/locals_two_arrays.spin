PUB main | q[4000], r[5000], z
  z := 1
