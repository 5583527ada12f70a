'' lcd_busy.spin: an HD44780 LCD in 8-bit mode (RS P0, R/W P1, E P2, D0..D7 on P8..P15) driven by
'' reading its busy flag before every write; then the first line is read back from the display's RAM.
'' VAR: busy_polls (busy-flag reads), readback[0..4] (characters read back).

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  RS = 0
  RW = 1
  E = 2
  DB0 = 8

VAR
  long busy_polls
  byte readback[8]

PUB main | i
  dira[RS]~~
  dira[RW]~~
  dira[E]~~
  waitcnt(cnt + clkfreq / 50)                           ' 20 ms after power-up
  command($38)                                          ' 8 bits, 2 lines
  command($0C)                                          ' display on
  command($06)                                          ' move right
  command($01)                                          ' clear: 1.52 ms busy
  text(string("HELLO"))
  command($C0)
  text(string("WORLD"))
  command($80)
  repeat i from 0 to 4
    readback[i] := read_data

PRI wait_ready | b
  dira[DB0 + 7..DB0]~
  outa[RS]~
  outa[RW]~~
  repeat
    outa[E]~~
    b := ina[DB0 + 7]
    outa[E]~
    busy_polls++
  while b
  outa[RW]~

PRI command(c)
  wait_ready
  outa[RS]~
  put(c)

PRI text(s)
  repeat strsize(s)
    wait_ready
    outa[RS]~~
    put(byte[s++])

PRI put(v)
  outa[DB0 + 7..DB0] := v
  dira[DB0 + 7..DB0]~~
  outa[E]~~
  outa[E]~
  dira[DB0 + 7..DB0]~

PRI read_data : v
  wait_ready
  outa[RS]~~
  outa[RW]~~
  outa[E]~~
  v := ina[DB0 + 7..DB0]
  outa[E]~
  outa[RW]~
