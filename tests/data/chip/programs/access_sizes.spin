VAR
  long v, pad[20]
  word w
  byte b
PUB main | a, n, big[40], far
  b := 1
  n := b
  n := @b
  n := b := 2
  b += 1
  b++
  w := 1
  n := w
  n := @w
  n := w := 2
  w += 1
  w++
  v.byte := 1
  n := v.byte
  n := @v.byte
  n := v.byte := 2
  v.byte += 1
  v.byte++
  v.byte[1] := 1
  n := v.byte[1]
  n := @v.byte[1]
  n := v.byte[1] := 2
  v.byte[1] += 1
  v.byte[1]++
  v.word := 1
  n := v.word
  n := @v.word
  n := v.word := 2
  v.word += 1
  v.word++
  v.word[1] := 1
  n := v.word[1]
  n := @v.word[1]
  n := v.word[1] := 2
  v.word[1] += 1
  v.word[1]++
  a.byte := 1
  n := a.byte
  n := @a.byte
  n := a.byte := 2
  a.byte += 1
  a.byte++
  a.byte[1] := 1
  n := a.byte[1]
  n := @a.byte[1]
  n := a.byte[1] := 2
  a.byte[1] += 1
  a.byte[1]++
  a.word := 1
  n := a.word
  n := @a.word
  n := a.word := 2
  a.word += 1
  a.word++
  a.word[1] := 1
  n := a.word[1]
  n := @a.word[1]
  n := a.word[1] := 2
  a.word[1] += 1
  a.word[1]++
  far.byte := 1
  n := far.byte
  n := @far.byte
  n := far.byte := 2
  far.byte += 1
  far.byte++
  far.byte[1] := 1
  n := far.byte[1]
  n := @far.byte[1]
  n := far.byte[1] := 2
  far.byte[1] += 1
  far.byte[1]++
  far.word := 1
  n := far.word
  n := @far.word
  n := far.word := 2
  far.word += 1
  far.word++
  far.word[1] := 1
  n := far.word[1]
  n := @far.word[1]
  n := far.word[1] := 2
  far.word[1] += 1
  far.word[1]++
  far := 1
  n := far
  n := @far
  n := far := 2
  far += 1
  far++
  big[39] := 1
  n := big[39]
  n := @big[39]
  n := big[39] := 2
  big[39] += 1
  big[39]++
  v := 0
  repeat 4
    case v
      2: quit
      3: next
    v++
  v := 0
  repeat 4
    case v
      1: next
      8: quit
      9: next
    v++
  big[20] := 1
  n := big[20]
  n := @big[20]
  n := big[20] := 2
  big[20] += 1
  big[20]++
  pad[10] := 1
  n := pad[10]
  n := @pad[10]
  n := pad[10] := 2
  pad[10] += 1
  pad[10]++
