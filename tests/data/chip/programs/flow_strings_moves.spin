VAR
  long r[200]
  long n
  byte buf[32]
PUB main | i, x
  repeat i from 1 to 5 step 2
    r[n++] := i
  r[n++] := i
  repeat i from 5 to 1 step 2
    r[n++] := i
  r[n++] := i
  repeat i from 5 to 1 step -2
    r[n++] := i
  r[n++] := i
  repeat i from 1 to 5 step -2
    r[n++] := i
  r[n++] := i
  repeat i from -2 to 2
    r[n++] := i
  r[n++] := i
  repeat i from 3 to 3
    r[n++] := i
  r[n++] := i
  repeat i from 0 to 6 step 4
    r[n++] := i
  r[n++] := i
  repeat i from 0 to 9
    r[n++] := lookup(i: 10, 20, 30..33, 7..5)
    r[n++] := lookupz(i: 10, 20, 30..33, 7..5)
    r[n++] := lookdown(i: 1, 2, 8..5, 9)
    r[n++] := lookdownz(i: 1, 2, 8..5, 9)
  repeat i from 0 to 9
    case i
      1: r[n++] := 100
      4..2: r[n++] := 200
      7, 9: r[n++] := 300
      other: r[n++] := 400
  repeat i from -1 to 1
    x := lookup(i: 5, 6)
    r[n++] := x
  bytefill(@buf, 1, 10)
  buf[3] := 0
  r[n++] := strsize(@buf)
  r[n++] := strcomp(@buf, @buf)
  r[n++] := strcomp(@buf, @buf + 1)
  repeat i from 0 to 9
    buf[i] := i + 1
  bytemove(@buf + 2, @buf, 6)
  r[n++] := long[@buf][0]
  r[n++] := long[@buf][1]
  r[n++] := long[@buf][2]
  repeat i from 0 to 9
    buf[i] := i + 1
  bytemove(@buf, @buf + 2, 6)
  r[n++] := long[@buf][0]
  r[n++] := long[@buf][1]
  r[n++] := long[@buf][2]
  repeat i from 0 to 9
    buf[i] := i + 1
  wordmove(@buf + 1, @buf + 4, 2)
  r[n++] := long[@buf][0]
  r[n++] := long[@buf][1]
  r[n++] := long[@buf][2]
  longfill(@buf + 1, $11223344, 2)
  r[n++] := long[@buf][0]
  r[n++] := long[@buf][1]
  r[n++] := long[@buf][2]
  wordfill(@buf + 1, $5566, 3)
  r[n++] := long[@buf][0]
  r[n++] := long[@buf][1]
  r[n++] := long[@buf][2]
  bytefill(@buf, 0, 0)
  r[n++] := \thrower(1)
  r[n++] := \thrower(0)
  r[n++] := outer
  r[n++] := \outer
  r[n++] := word[@buf][0]
  r[n++] := long[@buf + 1]
  r[n++] := word[@buf + 1]
  i := $12345678
  r[n++] := byte[@i][1]
  r[n++] := word[@i][1]
  r[n++] := i.byte[2]
  r[n++] := i.word[1]
  r[n++] := @r
  r[n++] := @@0
  r[n++] := n
PUB thrower(f)
  if f
    abort 77
  return 88
PUB outer
  result := 5
  thrower(1)
  return 6
