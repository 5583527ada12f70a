PUB main | i
  repeat i from string("a") to 5
