'' Code the compiler hints about (spinemu.compiler.hints); the image must not change.
PUB main | z, i
  z := 5
  if z<-1                                 ' rotate-left, not z < -1
    outa[0]~~
  if z >= 3                               ' assigns z := z > 3
    outa[1]~~
  repeat while i <= 10                    ' assigns i := i < 10
    i++
  z<-=1                                   ' a rotate-left assignment, meant
  z >= 3                                  ' an assignment on its own, meant
  z := z <- 1                             ' spaced: a rotate, meant
  outa[2] := (i >= 2) + 1
  if z => 3 and i =< 2                    ' the comparisons
    outa[3]~~
