'' Spin's AND and OR evaluate both operands (no short cut): calls, x++ and
'' lock built-ins on the right run even when the left decides the result.
VAR
  long calls, n, r1, r2, r3, r4, r5
PUB main | lock
  r1 := no and yes                      ' yes is called
  r2 := yes or no                       ' no is called
  if no and n++                         ' n++ runs
    r3 := 1
  lock := locknew
  r4 := 0 and lockset(lock)             ' the lock is set anyway
  r5 := lockclr(lock)                   ' TRUE: it was set
  repeat while no and yes               ' both called once
PRI yes
  calls++
  return TRUE
PRI no
  calls += 100
  return FALSE
