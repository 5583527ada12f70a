'' Jumps near the short/long boundary (offsets of 63 and 64 bytes): each loop, if and case
'' body grows by two bytes at a time, so each jump is priced in both forms (tests/data/README.md).
VAR
  long r[16], hits
PUB main | a, i, k
  i := 0
  repeat
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    if ++i > 2
      quit
  repeat 2
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
  i := 0
  repeat while i < 2
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
  i := 0
  repeat
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
  until i > 1
  repeat i from 0 to 1
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
  repeat i from 0 to 2
    if i == 1
      hits := a * $12345678 + $7654321 - a * $1234567
      hits := a * $12345678 + $7654321 - a * $1234567
      a++
      a++
      a++
      a++
    elseif i == 2
      hits++
    else
      hits += 2
  repeat i from 0 to 3
    case i
      0:
        hits := a * $12345678 + $7654321 - a * $1234567
        hits := a * $12345678 + $7654321 - a * $1234567
        a++
        a++
        a++
        a++
      1, 2: hits++
      other: hits += 3
  r[0] := a
  i := 0
  repeat
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    if ++i > 2
      quit
  repeat 2
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
  i := 0
  repeat while i < 2
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
  i := 0
  repeat
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
  until i > 1
  repeat i from 0 to 1
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
  repeat i from 0 to 2
    if i == 1
      hits := a * $12345678 + $7654321 - a * $1234567
      hits := a * $12345678 + $7654321 - a * $1234567
      a++
      a++
      a++
      a++
      a++
    elseif i == 2
      hits++
    else
      hits += 2
  repeat i from 0 to 3
    case i
      0:
        hits := a * $12345678 + $7654321 - a * $1234567
        hits := a * $12345678 + $7654321 - a * $1234567
        a++
        a++
        a++
        a++
        a++
      1, 2: hits++
      other: hits += 3
  r[1] := a
  i := 0
  repeat
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    a++
    if ++i > 2
      quit
  repeat 2
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    a++
  i := 0
  repeat while i < 2
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    a++
  i := 0
  repeat
    i++
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    a++
  until i > 1
  repeat i from 0 to 1
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
    a++
    a++
    a++
    a++
    a++
  repeat i from 0 to 2
    if i == 1
      hits := a * $12345678 + $7654321 - a * $1234567
      hits := a * $12345678 + $7654321 - a * $1234567
      a++
      a++
      a++
      a++
      a++
      a++
    elseif i == 2
      hits++
    else
      hits += 2
  repeat i from 0 to 3
    case i
      0:
        hits := a * $12345678 + $7654321 - a * $1234567
        hits := a * $12345678 + $7654321 - a * $1234567
        a++
        a++
        a++
        a++
        a++
        a++
      1, 2: hits++
      other: hits += 3
  r[2] := a
