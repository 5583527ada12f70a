'' A local read before it is assigned: Spin does not clear locals, so sum
'' starts with whatever the stack held (here what the previous call left).
PUB main
  dira[0..7]~~
  outa[0..7] := average(10, 20, 30)
  outa[0..7] := average(1, 2, 3)

PRI average(a, b, c) | sum
  sum += a                                              ' sum := a was meant
  sum += b
  sum += c
  return sum / 3
