{{ Cog 1 prints a count on P0 at 19200 baud while cog 0 toggles P5 with its own
   timing: the console decodes one pin of a chip whose cogs interleave. }}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

OBJ
  ser : "bitbang_serial"

VAR
  long stack[40]

PUB main | i
  cognew(talker, @stack)
  dira[5] := 1
  repeat 300
    !outa[5]
    waitcnt(cnt + 3_000)

PRI talker | i
  ser.start(1, 0, 19200)
  repeat i from 1 to 12
    ser.dec(i)
    ser.tx(",")
  ser.tx(13)
