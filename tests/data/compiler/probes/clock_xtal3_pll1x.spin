' Probe: clock header for _clkmode = xtal3 + pll1x, _clkfreq = 20_000_000
CON
  _clkmode = xtal3 + pll1x
  _clkfreq = 20_000_000

PUB main
  outa[0]~~
