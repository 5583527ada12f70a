'' The address of a parameter (@p) depends on what the caller's statement
'' and the statements around it keep on the stack: a `repeat n` count, a
'' `case` value and its end address.  Each probe records @p.
VAR
  long seen[10], k
PUB main | i
  probe(0)
  repeat 1
    if probe(8)                         ' a call at the start of a condition, inside a repeat count
      k := 0
  repeat 2
    probe(1)
  case k
    0: probe(2)
    other: probe(9)
  case probe(7)                         ' the end address is pushed before the value
    1: k := 0
  repeat 1
    case k
      0:
        repeat 1
          probe(3)
  repeat i from 0 to 0
    probe(4)
  k := 5 + probe(5)
  repeat while k < 7
    k++
    probe(6)
PRI probe(n)
  seen[n] := @n
  return 1
