'' Conformance probe: CHIPVER reads the chip's version from the ROM's last byte
'' ($FFFF): 1 on the P8X32A.  Drivers such as VGA64 and PS2_HID refuse to start
'' on any other value.  The version goes to a VAR and onto P0.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long version, last_byte
PUB main
  version := chipver
  last_byte := byte[$FFFF]
  dira[0] := 1
  outa[0] := chipver
  waitcnt(cnt + 2_000)
