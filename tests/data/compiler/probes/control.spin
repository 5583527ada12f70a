' Probe: if/case/repeat forms, next/quit, return/abort
VAR
  long a, b, i

PUB main | x
  if a
    x := 1
  ifnot a
    x := 2
  if a
    x := 3
  else
    x := 4
  if a
    x := 5
  elseif b
    x := 6
  elseifnot a
    x := 7
  else
    x := 8
  if a
    if b
      x := 9
  else
    x := 10
  case a
    1: x := 1
    2..3, 5: x := 2
       x := 3
    7:
      x := 4
    other: x := 5
  case b
    1: x := 1
    "a".."z": x := 2
  case a
    1:
      case b
        2: x := 3
  repeat
    if a
      quit
    next
  repeat 5
    x++
  repeat a
    if b
      next
    if x
      quit
    x := 2
  repeat i from 1 to 10
    x += i
  repeat i from 10 to 0 step 2
    if x
      next
    quit
  repeat i from a to b step -1
    x--
  repeat while a
    next
    quit
  repeat until b
    next
  repeat
    next
    quit
  while a
  repeat
    x := 1
  until b
  repeat
    case a
      1: quit
      2: next
  repeat 3
    case a
      1: quit
      2: next
  repeat
    case a
      1:
        case b
          3: quit
  repeat while a < 10
  repeat until (a := b) == 3
  x := check(1)
  x := \check(2)
  \check(3)
  return x

PRI check(v)
  if v == 1
    return
  if v == 2
    return v
  if v == 3
    abort
  abort v

PRI empty
