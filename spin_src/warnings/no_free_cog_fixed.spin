'' Seven blinkers in new cogs; main blinks the eighth pin itself.
VAR
  long stacks[7 * 16]

PUB main | i
  repeat i from 0 to 6
    cognew(blink(16 + i), @stacks[i * 16])
  blink(23)

PRI blink(pin)
  dira[pin]~~
  repeat
    !outa[pin]
    waitcnt(cnt + 40_000)
