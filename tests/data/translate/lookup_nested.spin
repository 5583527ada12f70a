'' Lookups whose items are paid one by one at run time (an item that reads a register or
'' assigns), nested as another such lookup's value or item: each keeps its LOOK_DONE in the
'' statement's price, which a match gives back.
VAR
  long r[6]
PUB main | a
  a := 5
  r[0] := lookupz(lookdownz(7: 4, outa, 7): a--, 29894)
  dira[0]~~
  r[1] := lookupz(lookdownz(9: 4, outa, 7): a--, 29894)
  dira[1]~~
  r[2] := lookup(lookdown(7: 4, ina, 7): 3, a++, lookdown(a: 1, outa, 6))
  dira[2]~~
  r[3] := lookdown(lookup(3: 1, a--, 7, outa): 7, a++, 9)
  dira[3]~~
  r[4] := lookdownz(a: 1, lookupz(a & 1: a++, ina), 6..9, a--)
  dira[4]~~
  r[5] := a
