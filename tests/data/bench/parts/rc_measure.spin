'' rc_measure.spin: an RC circuit on P5 measured three ways after charging it high for 1 ms:
'' a loop polling INA (loop_cycles), a counter in POS-detector mode (phs_cycles, AN001's RC decay)
'' and a second cog that waits in WAITPNE for the pin to fall while the first cog lets go of it
'' (wait_cycles: from the release the first cog recorded to the second cog's wake-up).

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  PIN = 5

VAR
  long loop_cycles, phs_cycles, wait_cycles, released, woke
  long stack[32]

PUB main | t
  ' 1: a polling loop
  charge
  t := cnt
  dira[PIN]~
  repeat while ina[PIN]
  loop_cycles := cnt - t
  ' 2: a POS detector counts the clocks the pin stays high
  charge
  ctra := %01000 << 26 | PIN
  frqa := 1
  phsa := 0
  dira[PIN]~
  repeat while ina[PIN]
  phs_cycles := phsa
  ctra := 0
  ' 3: another cog waits for the pin to fall
  charge
  cognew(waiter, @stack)
  waitcnt(cnt + 100_000)                                ' the waiter is waiting by then
  released := cnt
  dira[PIN]~
  repeat until woke
  wait_cycles := woke - released

PRI charge
  outa[PIN]~~
  dira[PIN]~~
  waitcnt(cnt + clkfreq / 1000)

PRI waiter
  waitpne(|< PIN, |< PIN, 0)
  woke := cnt
