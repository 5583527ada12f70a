{{ Prints two lines on P30 at 19200 baud with a bit-banged Spin serial port. }}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

OBJ
  ser : "bitbang_serial"

PUB main | i
  ser.start(31, 30, 19200)
  ser.str(string("Hello from Spin!", 13))
  repeat i from 1 to 3
    ser.dec(i * 7)
    ser.tx(" ")
  ser.tx(13)
  waitcnt(cnt + clkfreq / 100)  ' let the last stop bit out before the cog stops
