CON
  _clkmode = xtal1 + xtal2
  _xinfreq = 5_000_000
PUB main
