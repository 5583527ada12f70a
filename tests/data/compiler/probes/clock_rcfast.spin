' Probe: clock header for _clkmode = rcfast
CON
  _clkmode = rcfast

PUB main
  outa[0]~~
