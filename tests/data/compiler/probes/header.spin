' Probe: the first method has parameters and locals (dcurr), clock from _clkfreq
CON
  _clkmode = xtal2 + pll8x
  _clkfreq = 96_000_000

VAR
  long v[3]

PUB start(a, b) | c, d[4]
  c := a + b
  d[2] := c
