' Regression: a next/quit whose jump lands exactly 63 bytes past its long form, inside an
' if/case branch: OpenSpin compiles the if/case again until its size settles; the next/quit
' (sized against the loop's previous compile) is short while the branch jumps before it are
' long, long once they shrank, and when that is one byte the if/case stops with the jump to
' the branch written from the compile before: one byte past the branch's first instruction.
' (Found by the program generator.)  The case's end address push is the byte here, so that
' method comes first (the address must be below 256 to shrink).
PUB in_case | a, b
  repeat while a
    case a
      9:
        if b
          quit
        return
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 123456
        b := 100
      other:
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 123456
        a := 100
  a := 1
PUB in_else | a, b
  repeat b
    if a
      a := 123456
      a := 1000
    else
      if b
        next
      return
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 1000
      b := 100
  a := 1
PUB in_elseif | a, b
  repeat b
    ifnot a
    elseif a
      if b
        a := 100
      if b
        next
      return
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 123456
      b := 1000
      b := 100
  a := 1
