'' WAITPNE on a feedback output (P1 = !P0 one clock later), then P2 high.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[1] := 1
  frqa := 1
  ctra := %01001 << 26 | 1 << 9 | 0      ' feedback: BPIN = P1 = !P0 one clock later
  waitpne(|< 1, |< 1, 0)                ' P1 drops when P0 rises
  dira[2] := 1
  outa[2] := 1
