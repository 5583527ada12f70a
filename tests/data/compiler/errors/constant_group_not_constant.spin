' round( starts a constant expression that takes the rest of the expression
PUB main | x
  x := round(1.5) + x
