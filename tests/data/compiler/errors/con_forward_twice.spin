' OpenSpin reads CON in two passes: A needs B, which needs C further down
CON
  A = B
  B = C
  C = 1
PUB main
