'' Conformance probe: two cogs update the same hub variables without a lock.
'' Each update reads the variable in one hub window and writes it back in a
'' later one; an update by the other cog in between is lost on the chip.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long counts[3], racy, racy2, stack[20], done
  word w
PUB main | k, x
  cognew(incr, @stack)
  repeat k from 1 to 1000
    racy++
    x := x * 3 + k
    racy2 += 3
    w += 1
  repeat until done
  counts[0] := racy
  counts[1] := racy2
  counts[2] := w
PRI incr | k, y
  repeat k from 1 to 1000
    racy += 1
    y := y ^ k
    racy2 -= 1
    w++
  done := 1
