'' Locals Spin does not initialise, in a method a cog starts in: they hold
'' what cognew left on the new cog's stack (the interpreter's start words).
VAR
  long seen[4], stack[20]
PUB main
  cognew(worker(5), @stack)
  waitcnt(cnt + 20_000)
PRI worker(n) | a, b, c, d
  seen[0] := a
  seen[1] := b
  seen[2] := c
  repeat n
    d += 1
  seen[3] := d
