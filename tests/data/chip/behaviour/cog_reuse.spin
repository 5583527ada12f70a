'' A cog drives pin 5 high, is stopped, and is restarted on code that never
'' touches DIRA/OUTA: on the chip pin 5 then floats, on spinsim it stays driven.
VAR
  long stack[32]
PUB main
  coginit(1, driver, @stack)
  waitcnt(cnt + 100_000)
  cogstop(1)
  coginit(1, idle, @stack)
  waitcnt(cnt + 100_000)
  cogstop(1)
PRI driver
  dira[5]~~
  outa[5]~~
  repeat
PRI idle
  repeat
