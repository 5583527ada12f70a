'' serial_lcd.spin: text to a Parallax serial LCD on P15 at 9600 baud (a bit-banged transmitter).

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  LCD_PIN = 15

PUB main
  outa[LCD_PIN]~~
  dira[LCD_PIN]~~
  waitcnt(cnt + clkfreq / 100)
  tx(22)                                                ' display on, no cursor
  tx(12)                                                ' clear
  waitcnt(cnt + clkfreq / 200)                          ' the LCD needs 5 ms after a clear
  str(string("Hello, LCD"))
  tx(148)                                               ' line 1, column 0
  str(string("2nd line"))
  tx(17)                                                ' backlight on

PRI str(s)
  repeat strsize(s)
    tx(byte[s++])

PRI tx(b) | t, bits
  bits := (b | $100) << 1
  t := cnt
  repeat 10
    outa[LCD_PIN] := bits & 1
    bits >>= 1
    waitcnt(t += clkfreq / 9600)
