'' boot_count.spin: counts its boots in a VAR that it saves into the boot EEPROM at the VAR's own hub
'' address: the boot loader copies the whole EEPROM into hub RAM, so the next boot starts with the count.

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  SCL = 28
  SDA = 29

VAR
  long boots

PUB main | i, a
  boots++
  outa[SCL] := 1
  dira[SCL] := 1
  a := @boots
  start
  write($A0)
  write(a >> 8)
  write(a & $FF)
  repeat i from 0 to 3
    write(byte[a][i])
  stop
  waitcnt(cnt + clkfreq / 100)                          ' the write cycle

PRI start
  dira[SDA] := 0
  outa[SCL] := 1
  dira[SDA] := 1
  outa[SCL] := 0

PRI stop
  dira[SDA] := 1
  outa[SCL] := 1
  dira[SDA] := 0

PRI write(b) | i
  repeat i from 7 to 0
    dira[SDA] := (b >> i & 1) ^ 1
    outa[SCL] := 1
    outa[SCL] := 0
  dira[SDA] := 0
  outa[SCL] := 1
  outa[SCL] := 0
