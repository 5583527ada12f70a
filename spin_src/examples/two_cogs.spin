{{ two_cogs.spin: two cogs, two LEDs, one shared counter guarded by a lock.

   The main cog blinks P16 at 2 Hz; a second cog, started with cognew, blinks
   P17 at 5 Hz.  Both add to `toggles` under lock `guard`, so neither loses
   the other's updates.  After 3 seconds the main cog stops the other cog.

     spinemu run spin_src/examples/two_cogs.spin --trace two.vcd
}}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

VAR
  long stack[24]
  long toggles
  byte guard, helper

PUB main | t, n
  guard := locknew
  helper := cognew(blink(17, clkfreq / 10), @stack) + 1
  dira[16] := 1
  t := cnt
  repeat n from 1 to 12
    !outa[16]
    count
    waitcnt(t += clkfreq / 4)
  if helper
    cogstop(helper - 1)
  lockret(guard)

PRI blink(pin, half) | t
  dira[pin] := 1
  t := cnt
  repeat
    !outa[pin]
    count
    waitcnt(t += half)

PRI count
  repeat while lockset(guard)                   ' wait for the lock
  toggles++
  lockclr(guard)
