' a size override may only make items larger than the line's size
PUB main
DAT
  long 1, byte 2
