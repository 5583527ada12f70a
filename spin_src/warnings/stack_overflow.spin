'' A cog's stack grows past the array given to cognew: sum(10) recurses ten
'' calls deep and needs more than the 8 longs of "stack"; the calls overwrite
'' whatever follows it in hub RAM (here "total").
VAR
  long stack[8]
  long total

PUB main
  cognew(worker, @stack)
  waitcnt(cnt + 200_000)

PRI worker
  total := sum(10)

PRI sum(n)
  if n > 0
    return n + sum(n - 1)
