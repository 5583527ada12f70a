'' Counter A in DUTY differential mode: carry on pin 3, its inverse on pin 4, 25 % duty.
PUB main
  dira[3..4] := %11
  frqa := $4000_0000
  ctra := %00111 << 26 | 4 << 9 | 3
  waitcnt(cnt + 2_000)
