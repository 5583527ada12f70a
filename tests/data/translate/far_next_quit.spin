'' next and quit far from the loop's end or test: the compiler gives their
'' jump two offset bytes, which cost 16 cycles more than one.
VAR
  long a, b, c, d
PUB main | i
  repeat i from 0 to a + 3              ' bounds in variables: a jump to the step code
    if i == 2
      quit
    if i == 1
      next
    a := b + c * d + i
    b := a + c * d + i
    c := b + a * d + i
    d := a + c * b + i
    a := b + c * d + i
    b := a + c * d + i
    c := b + a * d + i
    d := a + c * b + i
  repeat 3                              ' repeat n: quit is a JNZ, here inside a case
    case i
      2: i++
         next
      3: quit
    a := b + c * d + i
    b := a + c * d + i
    c := b + a * d + i
    d := a + c * b + i
    a := b + c * d + i
    b := a + c * d + i
    c := b + a * d + i
    d := a + c * b + i
  dira[0..3]~~
  outa[0..3] := i
