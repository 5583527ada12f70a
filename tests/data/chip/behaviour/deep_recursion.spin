'' Recurses until the stack runs past the end of hub RAM.
PUB main
  dive(0)
PRI dive(n) | pad[100]
  dive(n + 1)
