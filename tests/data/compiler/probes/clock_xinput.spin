' Probe: clock header for _clkmode = xinput, _xinfreq = 10_000_000
CON
  _clkmode = xinput
  _xinfreq = 10_000_000

PUB main
  outa[0]~~
