'' DUTY DAC ramp on P6 (FRQA written in a loop), DUTY differential on P7/P8 and a feedback
'' counter (APIN P9 = P6, BPIN P10) in cog 1, which switches P7/P8's DIRA on and off.
'' (spinemu counter tests: tests/chip/test_listen_counters.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long stack[20]
PUB main | level
  cognew(second, @stack)
  dira[6] := 1
  dira[9] := 1
  ctra := %00110 << 26 | 6              ' DUTY single-ended on P6
  repeat level from 0 to 40
    frqa := level << 26
    outa[9] := level & 1                ' P9 follows the ramp's low bit
    waitcnt(cnt + 3_000)
PRI second
  frqa := $2000_0000
  ctra := %00111 << 26 | 8 << 9 | 7     ' DUTY differential: P7 carry, P8 not carry
  frqb := 1
  ctrb := %01001 << 26 | 10 << 9 | 9    ' POS detector with feedback: APIN P9, BPIN P10
  dira[10] := 1
  repeat 4
    dira[7..8] := %11
    waitcnt(cnt + 20_000)
    dira[7..8] := %00
    waitcnt(cnt + 9_000)
