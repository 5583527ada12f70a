'' A small object for the harness tests: results, aborts, strings, a hang, variables, a second cog.
VAR
  long total, history[4], flag, done, stack[24]
  word level
  byte code

DAT
greeting      byte      "hello", 0
table         long      10, 20, 30

PUB plus(a, b)
  total := a + b
  history[0] := a
  return total

PUB negate(x)
  return -x

PUB check(x)
  if x < 0
    abort x
  return x * 2

PUB deep(x)
  return inner(x)

PRI inner(x)
  if x == 0
    abort 99
  return x

PUB length(s)
  return strsize(s)

PUB hang | n
  repeat
    n++

PUB delay(cycles)
  waitcnt(cnt + cycles)

PUB watcher
  cognew(watch, @stack)

PRI watch
  repeat until flag
  done := flag + 1

PUB setPin(p)
  dira[p]~~
  outa[p]~~
