' Probe: clock header for _clkmode = xinput + pll4x, _xinfreq = 6_000_000
CON
  _clkmode = xinput + pll4x
  _xinfreq = 6_000_000

PUB main
  outa[0]~~
