'' led_duty.spin: an LED on P16 lit 25 % of each 10 ms for 20 periods, then on for 10 ms; a counter in NCO
'' mode blinks P17 at 1 kHz meanwhile (half the time lit), and stops at the end.

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

PUB main | t, period
  dira[16]~~
  dira[17]~~
  ctra := %00100 << 26 | 17                             ' NCO single-ended on P17
  frqa := 53_687                                        ' 2^32 * 1 kHz / 80 MHz
  period := clkfreq / 100
  t := cnt
  repeat 20
    outa[16]~~
    waitcnt(t + period / 4)
    outa[16]~
    waitcnt(t += period)
  outa[16]~~
  ctra := 0
  waitcnt(t + period)
