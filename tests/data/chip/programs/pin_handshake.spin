'' Cog 0 waits on pin 3, which cog 1 drives high after a delay; then cog 0
'' answers on pin 0 and waits for pin 3 to go low again (WAITPNE).
VAR
  long stack[32], t_seen, t_back
PUB main
  cognew(partner, @stack)
  waitpeq(|< 3, |< 3, 0)
  t_seen := cnt
  dira[0] := 1
  outa[0] := 1
  waitpne(|< 3, |< 3, 0)
  t_back := cnt
  cogstop(1)
PRI partner
  dira[3] := 1
  waitcnt(cnt + 50_000)
  outa[3] := 1
  waitpeq(1, 1, 0)
  waitcnt(cnt + 7_777)
  outa[3] := 0
  repeat
