'' AN001's RC decay measurement on P2: charge, PHSA~, release, read.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  PIN = 2
VAR
  long decay
PUB main
  ctra := %01000 << 26 | PIN      ' POS detector (AN001's RC decay measurement)
  frqa := 1
  outa[PIN] := 1                  ' charge
  dira[PIN] := 1
  waitcnt(cnt + 10_000)
  phsa~
  dira[PIN]~                      ' release: the capacitor holds the pin high for a while
  waitcnt(cnt + 100_000)
  decay := phsa
