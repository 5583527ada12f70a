'' LOGIC A & !B: A = P5 from a stimulus, B = P6 driven by a second cog.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long count
PUB main
  cognew(driver, @stack)
  frqa := 3
  ctra := %10010 << 26 | 6 << 9 | 5     ' LOGIC A & !B: APIN = P5, BPIN = P6
  waitcnt(cnt + 600_000)
  count := phsa
PRI driver
  dira[6] := 1
  waitcnt(cnt + 200_000)
  outa[6] := 1
  waitcnt(cnt + 50_000)
  outa[6] := 0
  waitcnt(cnt + 200_000)
DAT
stack long 0[32]
