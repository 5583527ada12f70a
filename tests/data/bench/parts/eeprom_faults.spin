'' eeprom_faults.spin: two mistakes an I2C master can make with the boot EEPROM: a page write of 70 bytes
'' from $7F30 (it wraps inside its 64-byte page), and a START sent after 4 bits of a byte.

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  SCL = 28
  SDA = 29

PUB main | i
  outa[SCL] := 1
  dira[SCL] := 1
  start
  write($A0)
  write($7F)
  write($30)
  repeat i from 0 to 69
    write(i)
  stop
  waitcnt(cnt + clkfreq / 100)                          ' the write cycle
  start
  repeat i from 7 to 4                                  ' half a control byte...
    dira[SDA] := ($A0 >> i & 1) ^ 1
    outa[SCL] := 1
    outa[SCL] := 0
  start                                                 ' ... and a START in the middle of it
  write($A0)
  stop

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
