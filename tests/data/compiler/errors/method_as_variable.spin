PUB main
  main := 3
