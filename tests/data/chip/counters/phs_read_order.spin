'' POS detector reading P7 while a second cog toggles it: 40 PHSA reads.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long reads[40]
PUB main | i
  cognew(toggler, @stack)
  waitcnt(cnt + 20_000)
  frqa := 1
  ctra := %01000 << 26 | 7
  phsa := 0
  repeat i from 0 to 39
    reads[i] := phsa
PRI toggler
  dira[7] := 1
  repeat
    outa[7] := 1
    outa[7] := 0
    outa[7] := 1
    outa[7] := 0
    outa[7] := 1
    outa[7] := 1
    outa[7] := 0
DAT
stack long 0[32]
