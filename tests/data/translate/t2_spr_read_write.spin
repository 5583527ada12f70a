'' A statement that reads a register through spr[], computes, then writes one:
'' the pins change when the write runs, at the end of the statement.
VAR
  long r
PUB main | a, b, i
  dira[7..0] := $FF
  a := 1000
  b := 7
  spr[4] := spr[4] | (a / b / b / b) & 1 | 2          ' outa: read, divide, write
  spr[4] := spr[4] ^ (a * b * b // 3 + 4)
  r := cnt
  repeat i from 0 to 2
    spr[4] := spr[4] ^ (|< i)
  r := cnt - r
