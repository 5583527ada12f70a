VAR
  long r[12]
PUB main | i, a
  repeat i from 0 to 2047
    a := word[$C000][i]
    r[0] += a
    r[1] += a * (i + 1)
    r[2] ^= a <- i
    a := word[$D000][i]
    r[3] += a
    r[4] += a * (i + 1)
    r[5] ^= a <- i
  repeat i from 0 to 2048
    a := word[$E000][i]
    r[6] += a
    r[7] += a * (i + 1)
    r[8] ^= a <- i
