' Regression: a "next" in "repeat ... until" that jumps exactly 63 bytes is short in OpenSpin
' (elsewhere a 63-byte forward jump is long); found by the program generator
VAR
  long x, y
PUB main
  repeat
    next
    x := 5
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := y
    x := y
    x := y
    x := y
    x := y
    x := y
    x := y
    x := y
  until x
  repeat
    if x
      next
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
    x := lookupz(y: 3)
  while x
