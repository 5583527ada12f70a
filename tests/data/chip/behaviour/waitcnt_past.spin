'' WAITCNT on a target that has already passed waits until CNT comes round (2**32 cycles).
PUB main | t
  dira[0]~~
  t := cnt
  waitcnt(t)
  outa[0]~~
