{{ Serial out of a counter: CTRA in NCO mode with FRQA = 0 drives P30 with PHSA[31],
   so writing PHSA sets the line (OUTA[30] stays 0).  Prints a line at 9600 baud while
   CTRB, a 1 kHz NCO on P4, runs all along and cog 1 switches P4's DIRA on and off. }}
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  TX = 30
  BIT = 80_000_000 / 9600

VAR
  long stack[20]

PUB main | t, bits, c, p
  cognew(blinker, @stack)
  ctra := %00100 << 26 | TX
  frqa := 0
  phsa := $8000_0000                    ' idle high
  dira[TX] := 1
  p := @text
  t := cnt + 2_000
  repeat while c := byte[p++]
    bits := (c | $100) << 1             ' start bit, 8 data bits, stop bit
    repeat 10
      waitcnt(t += BIT)
      phsa := bits << 31
      bits >>= 1
  waitcnt(t += BIT)

PRI blinker
  frqb := 53_687                        ' 2**32 * 1_000 / 80_000_000: 1 kHz
  ctrb := %00100 << 26 | 4
  repeat 6
    dira[4] := 1
    waitcnt(cnt + 700_000)
    dira[4] := 0
    waitcnt(cnt + 300_000)

DAT
text    byte "Sent by a counter!", 13, 0
