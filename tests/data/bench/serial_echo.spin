{{ Asks for a number on P30, reads it from P31 (digits, then CR), prints twice
   that; then does it again.  9600 baud, bit-banged in Spin. }}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

OBJ
  ser : "bitbang_serial"

PUB main | n, turn
  ser.start(31, 30, 9600)
  repeat turn from 1 to 2
    ser.str(string("Number? "))
    n := ser.getdec
    ser.str(string("Twice "))
    ser.dec(n)
    ser.str(string(" is "))
    ser.dec(n * 2)
    ser.tx(13)
