'' cognew/coginit of a Spin method: the arguments, then the stack, then coginit's cog id.
VAR
  long r[20], x, stack[64], c
PUB main | i
  x := 1
  r[0] := cognew(worker(x, x++), @stack[x * 10])
  waitcnt(cnt + 20000)
  cogstop(r[0])
  x := 2
  c := 0
  coginit(x++, worker(x, x++), @stack[x * 10])
  waitcnt(cnt + 20000)
  cogstop(3)
  r[3] := x
  r[4] := c
PRI worker(a, b)
  r[1 + c++] := a * 10 + b
  repeat
