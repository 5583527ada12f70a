'' CPU-bound benchmark loop for tests/benchmarks/bench_demo.py: no waits, and a
'' variable changes every iteration, so nothing can be fast-forwarded.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long count, acc
  byte buf[16]
PUB main | i
  repeat
    repeat i from 0 to 15
      buf[i] := i * 3 + count
      acc += buf[i] >> 1
    count++
    if acc & 1
      acc := mix(acc)
PRI mix(x)
  return x ^ (x << 3) + 7
