VAR
  long stack[16], id, marker
PUB main
  marker := $AAAAAAAA
  longfill(@stack, $66666666, 16)
  fill
  start
  waitcnt(cnt + 100000)
  cogstop(id)
PRI fill | l[60]
  longfill(@l, $55555555, 60)
PRI start | pad[4]
  id := cognew(child(11, 22, 33), @stack[1])
PRI child(a, b, c) | l1, l2, l3
  repeat
