'' waitcnt for a count that has already passed: "+ cnt" is missing, so the
'' cog waits for CNT to come round to 800_000 again: 53.7 s at 80 MHz.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

PUB main
  dira[16]~~
  waitcnt(clkfreq / 10 + cnt)                           ' 100 ms: fine
  outa[16]~~
  waitcnt(clkfreq / 100)                                ' 10 ms meant, "+ cnt" forgotten
  outa[16]~
