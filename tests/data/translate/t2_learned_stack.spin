'' Calls right after a cog start: the bytecode engine runs them in its
'' busy-loop learner (a tracking copy of the interpreter), whose stack use
'' counts as the cog's stack too.
VAR
  long r, stack[16]
PUB main
  cognew(sleeper, @stack)
  r := deep(1, 2, 3, 4, 5, 6)
  repeat
PRI sleeper
  waitcnt(cnt + 100_000)
  r += 1000
PRI deep(a, b, c, d, e, f)
  return deeper(a, b, c, d, e, f) + 1
PRI deeper(a, b, c, d, e, f)
  return a + b + c + d + e + f
