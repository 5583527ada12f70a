' repeat n: DJNZ writes the count back only while it loops; the last pass leaves the
' count's stack long holding 1 (Parallax's ROM interpreter), which the hub RAM shows
VAR
  long out[4]
PUB main | a, b, i
  repeat 3
    a++
  out[0] := a
  repeat 200                    ' hot enough for compiled blocks
    repeat 2
      b++
    repeat (b & 3) + 1
      i += 3
      if i > 500
        quit
  out[1] := b
  out[2] := i
  out[3] := sum(5)
  repeat 2                      ' the last thing: its count's long stays in RAM
    a++
PRI sum(n) | k
  repeat n
    k += n
  return k
