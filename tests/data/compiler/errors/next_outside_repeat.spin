PUB main
  next
