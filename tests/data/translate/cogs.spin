'' Two cogs sharing hub variables: a flag handshake, a pin wait, a cog stopped from outside.
VAR
  long flag, count, stack[32], stack2[32]

PUB main | cog2
  dira[0] := 1
  cognew(worker, @stack)
  cog2 := cognew(blinker, @stack2)
  repeat 5
    flag := 1
    repeat while flag
    outa[0] := !outa[0]
  waitpeq(|< 8, |< 8, 0)
  cogstop(cog2)
  count += 100

PRI worker
  repeat
    repeat until flag
    count++
    flag := 0

PRI blinker
  dira[8] := 1
  repeat
    outa[8] := !outa[8]
    waitcnt(cnt + 5000)
