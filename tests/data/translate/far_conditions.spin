'' Conditions whose code lies far from the start of their statement (an elseif after a long
'' branch, a case value after the others, a loop's test after its body): a lookup's end
'' address there is pushed in one or two bytes as it lies below or past $100.
VAR
  long a, hits, r[4]
PUB main
  a := 3
  if a == 1
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
  elseif lookup(a : 0, 1, 2)
    r[0] := 1
  case lookdown(a : 5, 3)
    9:
      hits := a * $12345678 + $7654321 - a * $1234567
    lookup(a : 7, 8, 2):
      r[1] := 2
  repeat
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    hits := a * $12345678 + $7654321 - a * $1234567
    a++
  while lookdown(a : 4, 5, 6)
  r[2] := a
