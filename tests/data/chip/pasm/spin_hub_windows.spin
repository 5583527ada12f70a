'' Probe: six Spin cogs (ids 1-6, cog 1 used twice) each adding to its own hub
'' variable and toggling a pin, so that the hub windows of cogs 2-7 show in the
'' pin trace (spinsim: cogs 0-1 at t mod 16 = 8, 2-3 at 12, 4-5 at 0, 6-7 at 4),
'' as does a stopped cog started again (spinsim keeps its DIRA and OUTA).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long counts[8], stacks[200]
PUB main | i
  repeat i from 1 to 6
    cognew(toggle(i), @stacks[i * 30])
  waitcnt(cnt + 300_000)
PUB toggle(pin) | k
  dira[pin] := 1
  repeat k from 1 to 40
    counts[pin] += k
    !outa[pin]
