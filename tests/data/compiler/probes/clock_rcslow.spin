' Probe: clock header for _clkmode = rcslow
CON
  _clkmode = rcslow

PUB main
  outa[0]~~
