'' WAITPNE on input P1, then P2 high (the twin of wait_feedback).
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  waitpne(|< 1, |< 1, 0)
  dira[2] := 1
  outa[2] := 1
