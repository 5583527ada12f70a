'' POS, POSEDGE, NEG and NEGEDGE detectors on stimulus pins P3 and P4.
'' (spinemu counter tests: tests/chip/test_counter_programs.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long pos, negs, posedge, negedge
PUB main
  frqa := 1
  frqb := 1
  ctra := %01000 << 26 | 3          ' POS detector, APIN = P3
  ctrb := %01010 << 26 | 3          ' POSEDGE detector
  waitcnt(cnt + 400_000)
  pos := phsa
  posedge := phsb
  ctra := %01100 << 26 | 4          ' NEG detector, APIN = P4 (high but for the pulses)
  ctrb := %01110 << 26 | 3          ' NEGEDGE detector
  phsa := 0
  phsb := 0
  waitcnt(cnt + 400_000)
  negs := phsa
  negedge := phsb
