{{ Asks for a number on P30, reads it from P31 (digits, then CR), prints twice
   that; then does it again.  9600 baud, bit-banged in Spin (bitbang_serial.spin).
   Send it numbers from a file, or type them (Enter sends CR):
     printf '21\r' > number.txt
     spinemu run spin_src/examples/serial_echo.spin --baud 9600 --console-in number.txt --console-in-at 0.05
     spinemu run spin_src/examples/serial_echo.spin --baud 9600 --console }}
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
