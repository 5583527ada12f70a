'' Only one cog owns P5: main lets go of it before the other cog drives it.
VAR
  long stack[16]

PUB main
  dira[5]~~
  outa[5]~~                                             ' LED on
  dira[5]~                                              ' hand the pin over
  cognew(switch_off, @stack)
  waitcnt(cnt + 100_000)

PRI switch_off
  dira[5]~~                                             ' output, low: the LED goes off
  waitcnt(cnt + 50_000)
