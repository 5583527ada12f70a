'' CPU-bound benchmark for the Spin->Python engine: arithmetic, arrays, calls, no waits.
VAR
  long total, table[16]

PUB main | i, j, x
  repeat i from 0 to 999
    x := i
    repeat j from 0 to 15
      table[j] := table[j] + x * j
      x := (x * 3 + 7) // 1000
      total += table[j] ^ x
    total := mix(total, i)

PRI mix(a, b) : r
  r := (a <- 3) ^ b
  if r < 0
    r := -r
