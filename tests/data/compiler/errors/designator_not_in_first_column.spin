PUB main
  outa[0]~~
 PRI other
