'' PLL internal with a VCO below 64 MHz.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  frqa := $0400_0000                    ' VCO = 16 * 80 MHz * 2**26 / 2**32 = 20 MHz: below the lock range
  ctra := %00001 << 26 | 3 << 23       ' PLL internal (video), VCO / 16
  waitcnt(cnt + 10_000)
