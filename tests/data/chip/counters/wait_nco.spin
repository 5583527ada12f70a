'' WAITPEQ/WAITPNE on an NCO output (P2, ~1 kHz); P3 follows each edge.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[2] := 1
  dira[3] := 1
  frqa := 53_687                        ' 2**32 * 1_000 / 80_000_000
  ctra := %00100 << 26 | 2
  repeat 10
    waitpeq(|< 2, |< 2, 0)
    outa[3] := 1
    waitpne(|< 2, |< 2, 0)
    outa[3] := 0
