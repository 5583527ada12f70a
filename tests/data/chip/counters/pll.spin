'' PLL differential at 625 kHz on P5/P6 and PLL single-ended at 80 MHz on P4.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[5] := 1
  dira[6] := 1
  frqa := $1000_0000                        ' VCO = 16 * 80 MHz * 2**28 / 2**32 = 80 MHz
  ctra := %00011 << 26 | 0 << 23 | 6 << 9 | 5  ' PLL differential, VCO / 128: 625 kHz on P5, inverted on P6
  frqb := $1000_0000
  ctrb := %00010 << 26 | 7 << 23 | 4         ' PLL single-ended, VCO / 1: 80 MHz on P4
  dira[4] := 1
  waitcnt(cnt + 100_000)
