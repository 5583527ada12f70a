'' LOCKNEW order: the chip hands out lock 0 first, spinsim lock 1.
VAR
  long got[9]
PUB main | i
  repeat i from 0 to 8
    got[i] := locknew
