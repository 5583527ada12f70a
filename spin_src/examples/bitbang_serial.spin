{{ A bit-banged asynchronous serial port in Spin (8N1, true mode: idle high).
   Written for spinemu's serial console tests.  Each bit is timed by WAITCNT,
   so it keeps the baud rate exactly; Spin is fast enough for 19200 baud. }}

VAR
  long rx_pin, tx_pin, bit_ticks

PUB start(rxpin, txpin, baud)
  rx_pin := rxpin
  tx_pin := txpin
  bit_ticks := clkfreq / baud
  outa[tx_pin] := 1             ' idle high first, then drive: no glitch on the line
  dira[tx_pin] := 1

PUB tx(c) | t
  c := (c | $100) << 1          ' start bit 0, data LSB first, stop bit 1
  t := cnt
  repeat 10
    waitcnt(t += bit_ticks)
    outa[tx_pin] := c
    c >>= 1

PUB rx : c | t
  waitpeq(0, |< rx_pin, 0)      ' the start bit's leading edge
  t := cnt + bit_ticks >> 1     ' then sample in the middle of each bit
  repeat 8
    waitcnt(t += bit_ticks)
    c := (c >> 1) | (ina[rx_pin] << 7)
  ' no wait for the stop bit: its time is what the caller has to handle the
  ' byte before the next start bit (Spin needs it at 9600 baud)

PUB str(addr)
  repeat strsize(addr)
    tx(byte[addr++])

PUB dec(value) | div, printing
  if value < 0
    tx("-")
    -value
  div := 1_000_000_000
  printing := false
  repeat 10
    if value => div or printing or div == 1
      tx("0" + value / div)
      value //= div
      printing := true
    div /= 10

PUB getdec : value | c, negative
  negative := false             ' locals are not cleared
  repeat
    c := rx
    if c == "-"
      negative := true
    elseif c => "0" and c =< "9"
      value := value * 10 + c - "0"
    elseif c == 13
      quit
  if negative
    -value
