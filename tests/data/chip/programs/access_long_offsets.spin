VAR
  long v0, v1, v2, v3, v4, v5, v6, v7, v8, v9, v10
PUB main | a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, n
  v10 := 1
  n := v10
  n := @v10
  n := v10 := 2
  v10 += 1
  v10++
  n := v10--
  a9 := 1
  n := a9
  n := @a9
  n := a9 := 2
  a9 += 1
  a9++
  n := a9--
