' Probe: clock header for no settings
CON
  X = 0

PUB main
  outa[0]~~
