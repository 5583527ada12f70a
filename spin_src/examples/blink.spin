{{ blink.spin: the "hello world" of the Propeller.

   Blinks the LED on P16 (the Propeller Demo Board's first LED) twice a
   second, for ever.  Run it and watch the pin:

     spinemu run spin_src/examples/blink.spin --seconds 2
     spinemu run spin_src/examples/blink.spin --seconds 2 --trace blink.vcd
}}
CON
  _clkmode = xtal1 + pll16x                     ' 5 MHz crystal x 16 = 80 MHz
  _xinfreq = 5_000_000

  LED = 16

PUB main | t
  dira[LED] := 1                                ' make P16 an output
  t := cnt
  repeat
    !outa[LED]                                  ' toggle it
    waitcnt(t += clkfreq / 4)                   ' every 1/4 s: a 2 Hz blink
