'' The local is assigned first.
PUB main
  dira[0..7]~~
  outa[0..7] := average(10, 20, 30)
  outa[0..7] := average(1, 2, 3)

PRI average(a, b, c) | sum
  sum := a
  sum += b
  sum += c
  return sum / 3
