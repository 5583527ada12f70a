'' The same blink with "+ cnt" on both waits.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

PUB main
  dira[16]~~
  waitcnt(clkfreq / 10 + cnt)                           ' 100 ms
  outa[16]~~
  waitcnt(clkfreq / 100 + cnt)                          ' 10 ms
  outa[16]~
