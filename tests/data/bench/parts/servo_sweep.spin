'' servo_sweep.spin: servo pulses on P17 every 20 ms: 25 at 1.0 ms, one of 3.0 ms (out of range),
'' 25 at 2.0 ms, then 25 at 1.5 ms.

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

PUB main | t
  dira[17]~~
  t := cnt
  pulses(1000, 25, @t)
  pulses(3000, 1, @t)
  pulses(2000, 25, @t)
  pulses(1500, 25, @t)

PRI pulses(us, n, tp)
  repeat n
    outa[17]~~
    waitcnt(long[tp] + us * (clkfreq / 1_000_000))
    outa[17]~
    waitcnt(long[tp] += clkfreq / 50)
