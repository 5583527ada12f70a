'' an RCTIME-style measurement of pulses on P12 with POS detectors.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  PIN = 12
VAR
  long width, width2
PUB main
  frqa := 1
  ctra := %01000 << 26 | PIN            ' POS detector
  repeat until ina[PIN]                 ' wait for the pulse
  phsa := 0
  repeat while ina[PIN]
  width := phsa                         ' clocks it was high after PHSA := 0
  frqb := 1
  ctrb := %01000 << 26 | PIN
  waitpeq(|< PIN, |< PIN, 0)            ' the second pulse, measured whole
  waitpne(|< PIN, |< PIN, 0)
  width2 := phsb
