'' cognew with no free cog: main starts eight blinkers, but cog 0 (running
'' main) is one of the eight, so the eighth cognew returns -1.
VAR
  long stacks[8 * 16]

PUB main | i
  repeat i from 0 to 7
    cognew(blink(16 + i), @stacks[i * 16])
  waitcnt(cnt + 100_000)

PRI blink(pin)
  dira[pin]~~
  repeat
    !outa[pin]
    waitcnt(cnt + 40_000)
