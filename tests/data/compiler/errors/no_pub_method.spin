PRI main
  outa[0]~~
