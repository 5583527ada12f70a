'' POS detector with feedback (APIN P8, BPIN P9): CNT and PHSA read in pairs.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long c1, p1, c2, p2, c3, p3, c4, p4
PUB main
  dira[9] := 1
  frqa := 1
  ctra := %01001 << 26 | 9 << 9 | 8     ' POS detector with feedback: APIN = P8, BPIN = P9
  c1 := cnt
  p1 := phsa
  waitcnt(cnt + 100_000)
  c2 := cnt
  p2 := phsa
  waitcnt(cnt + 300_000)
  c3 := cnt
  p3 := phsa
  waitcnt(cnt + 100_000)
  c4 := cnt
  p4 := phsa
