'' WAITPEQ/WAITPNE on input P2 (the twin of wait_nco: a stimulus makes the edges); P3 follows each edge.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[3] := 1
  repeat 10
    waitpeq(|< 2, |< 2, 0)
    outa[3] := 1
    waitpne(|< 2, |< 2, 0)
    outa[3] := 0
