{{ Prints two lines on P30 at 19200 baud with a serial port written in Spin
   (bitbang_serial.spin).  Watch it on spinemu's serial console:
     spinemu run spin_src/examples/serial_hello.spin --baud 19200 }}
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
