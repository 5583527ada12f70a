PUB main
DAT
  byte 1.5
