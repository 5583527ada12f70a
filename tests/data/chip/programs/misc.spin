VAR
  long n, m, stack[40]
PUB main | i, l
  l := locknew
  n := lockset(l)
  n := lockset(l)
  n := lockclr(l)
  lockset(l)
  lockclr(l)
  lockret(l)
  locknew
  n := cogid
  clkset(clkmode, clkfreq)
  n := cognew(child0, @stack)
  cogstop(n)
  n := cognew(child1(1), @stack)
  cogstop(n)
  n := cognew(child2(1, 2), @stack)
  cogstop(n)
  n := cognew(child4(1, 2, 3, 4), @stack)
  cogstop(n)
  n := cognew(child6(1, 2, 3, 4, 5, 6), @stack)
  cogstop(n)
  cognew(child0, @stack)
  coginit(7, child1(5), @stack)
  cogstop(7)
  cogstop(1)
  n := \deep(3)
  n := \deep(1)
  n := \deep(0)
  \deep(2)
  n := lvl1
  lvl1
  n := retv(5)
  retv(5)
  n := strsize(string("hello"))
PRI child0
  repeat
PRI child1(a)
  repeat
PRI child2(a, b)
  repeat
PRI child4(a, b, c, d)
  repeat
PRI child6(a, b, c, d, e, f)
  repeat
PRI deep(k)
  if k == 0
    abort 9
  if k == 1
    abort
  result := deep(k - 2) + 1
PRI lvl1
  result := 3
  return
PRI retv(x)
  return x + 1
