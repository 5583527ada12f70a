PUB f
  return 1
