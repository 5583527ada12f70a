'' The same worker with a stack large enough for ten nested calls.
VAR
  long stack[80]
  long total

PUB main
  cognew(worker, @stack)
  waitcnt(cnt + 200_000)

PRI worker
  total := sum(10)

PRI sum(n)
  if n > 0
    return n + sum(n - 1)
