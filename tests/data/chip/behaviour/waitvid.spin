'' Four WAITVIDs with VSCL's frame period at 1,000 clocks: the last three wait a frame each.
VAR
  long t0, t1
PUB main
  vscl := 1_000
  t0 := cnt
  waitvid(0, 0)
  waitvid(0, 0)
  waitvid(0, 0)
  waitvid(0, 0)
  t1 := cnt
