{{ knight_rider.spin: one lit LED sweeps back and forth over P16..P23.

   Shows pin ranges (outa[23..16] writes eight pins at once), the rotate
   operators and a lookup table of speeds.

     spinemu run spin_src/examples/knight_rider.spin --trace knight.log
     spinemu trace show knight.log --pins 16..23
}}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

PUB main | pattern, pass, t
  dira[23..16] := %1111_1111
  pattern := %0000_0001
  t := cnt
  repeat pass from 0 to 5
    repeat 7                                    ' up: P16 -> P23
      outa[23..16] := pattern
      pattern <-= 1
      waitcnt(t += clkfreq / lookupz(pass // 3 : 40, 60, 100))
    repeat 7                                    ' and back down
      outa[23..16] := pattern
      pattern ->= 1
      waitcnt(t += clkfreq / lookupz(pass // 3 : 40, 60, 100))
  outa[23..16] := 0
