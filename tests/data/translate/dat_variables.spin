'' DAT longs are variables in methods, not constants (their offset in the
'' object is a constant only in DAT and CON expressions): loop bounds, a
'' repeat count, a case value and an address taken with @ read them at run time;
'' inside constant() a label is its offset in the object, as the compiler has it.
VAR
  long sum, count, hit, r1, r2
PUB main | i
  repeat i from first to last step 2    ' 5, 7, 9
    sum += i
  repeat times                          ' 3 passes
    count++
  case 9
    first: hit := 1
    last: hit := 2                      ' last is 9
  r1 := long[@last - 4]                 ' first
  r2 := constant(@last + 1) - constant(first)   ' offsets: 25 - 20
  first := 0
  last := 1
  repeat i from first to last           ' 0, 1: quit leaves in the first pass
    quit
  dira[0..7]~~
  outa[0..7] := sum + count + hit + r1 + r2 + i
DAT
pad     long 0, 0, 0
first   long 5
last    long 9
times   long 3
