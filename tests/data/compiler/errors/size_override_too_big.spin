VAR
  byte b
PUB main | x
  x := b.word
