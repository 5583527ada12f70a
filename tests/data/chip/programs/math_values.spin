VAR
  long r[200]
  long n
PUB main | i, x, y
  repeat i from 0 to 9
    x := lookupz(i: 0, 1, -1, 5, -5, $7FFFFFFF, $80000000, 33, 32, 100)
    y := lookupz(i: 3, -3, 0, 31, 32, 33, -1, 64, 1, 7)
    r[n++] := x / y
    r[n++] := x // y
    r[n++] := x >> y
    r[n++] := x << y
    r[n++] := x ~> y
    r[n++] := x -> y
    r[n++] := x <- y
    r[n++] := x >< y
    r[n++] := x ** y
    r[n++] := ^^x
    r[n++] := >|x
    r[n++] := |<x
    r[n++] := ||x
    r[n++] := x #> y
    r[n++] := x <# y
    r[n++] := x * y
