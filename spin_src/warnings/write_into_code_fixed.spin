'' The loop stays inside buf.
DAT
buf     byte    0[8]

PUB main | i
  repeat i from 0 to 7
    buf[i] := "x"
