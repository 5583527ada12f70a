PUB main | x
  x := 1
{ this comment
  never ends
