' Probe: every operator, assignment forms as statements and as values, precedence
VAR
  long a, b, c
  byte bv
  word wv

PUB main | x, y, z
  x := a + b - c * a / b // c
  x := a ** b
  x := a #> b <# c
  x := a << 1 >> 2 ~> 3 <- 4 -> 5 >< 6
  x := a & b | c ^ a
  x := a == b or a <> b and a < b
  x := a > b or a =< b or a => b
  x := not a
  x := -a
  x := !a
  x := ^^a
  x := ||a
  x := |<a
  x := >|a
  x := +a
  x := -a * b + c
  x := a + b << 2
  x := (a + b) << 2
  x := a | b & c
  x := not a == b
  x := a + b #> c
  x := ++a
  x := --a
  x := a++
  x := a--
  x := a~
  x := a~~
  x := ~a
  x := ~~a
  x := ?a
  x := a?
  ++a
  --a
  a++
  a--
  a~
  a~~
  ~a
  ~~a
  ?a
  a?
  bv++
  wv--
  ++bv
  -a
  !a
  ||a
  ^^a
  |<a
  >|a
  not a
  a += 1
  a -= 2
  a *= 3
  a **= 4
  a /= 5
  a //= 6
  a #>= 7
  a <#= 8
  a <<= 9
  a >>= 10
  a ~>= 11
  a <-= 12
  a ->= 13
  a ><= 14
  a &= 15
  a |= 16
  a ^= 17
  a and= 18
  a or= 19
  a === 20
  a <>= 21
  a <= 22
  a >= 23
  a =<= 24
  a =>= 25
  a + = 26
  x := a += 1
  x := a and= b
  x := y := z := 3
  x := 1 + y := 3 + 4
  x := not y := 3 and 4
  if (y := a) > 0
    z := 1
  waitcnt(y += 100)
  x := a++ * 2
