' Probe: clock header for _clkmode = xtal2 + pll8x, _xinfreq = 10_000_000
CON
  _clkmode = xtal2 + pll8x
  _xinfreq = 10_000_000

PUB main
  outa[0]~~
