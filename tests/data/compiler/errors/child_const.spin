CON
  K = 5
PUB f
  return 1
