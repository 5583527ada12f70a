'' Counter A in NCO single-ended mode toggles pin 2 at ~1 kHz for 10 ms, then the
'' cog reads PHS in LOGIC-always mode twice (the difference counts clocks).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long phs1, phs2
PUB main
  dira[2] := 1
  frqa := 53_687                                ' 2**32 * 1_000 / 80_000_000
  ctra := %00100 << 26 | 2
  waitcnt(cnt + 800_000)
  ctra := 0
  frqb := 1
  ctrb := %11111 << 26
  phs1 := phsb
  phs2 := phsb
