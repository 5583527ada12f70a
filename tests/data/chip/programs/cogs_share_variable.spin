'' Two cogs talk through a variable: cog 0 busy-waits on it (a loop the
'' fast-forward parks), cog 1 counts it down every 2 ms and toggles pin 0.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long flag, rounds, worker_cog, stack[32]
PUB main
  flag := 5
  worker_cog := cognew(worker, @stack)
  repeat while flag
  repeat rounds from 1 to 3
    flag := 3
    repeat until flag == 0
  dira[1] := 1
  outa[1] := 1
  cogstop(worker_cog)
PRI worker | t
  dira[0] := 1
  t := cnt
  repeat
    waitcnt(t += 160_000)
    !outa[0]
    if flag
      flag--
