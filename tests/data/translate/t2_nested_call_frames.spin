'' Calls inside another call's arguments run with that call's frame already
'' on the stack: their parameters (and @param) sit higher, each one by what
'' was pushed before it.
VAR
  long r1, r2, r3, r4, r5, r[4], i
PUB main
  r1 := plus(at(1), at(2))               ' at: 12 bytes up, then 16
  r2 := 5 + at(3)
  r3 := plus(7, at(4)) + at(5)
  r4 := plus(plus(at(6), 1), at(7))
  r5 := \plus(at(8), 0)
  r[i++] := plus(at(9), at(10)) + at(11)   ' the value is computed before i++
  r[i++] := plus(at(9), at(10)) + at(11)
  \plus(at(12), 1)                       ' a trapped call whose result is dropped
PRI at(x)
  return @x
PRI plus(a, b)
  return a + b
