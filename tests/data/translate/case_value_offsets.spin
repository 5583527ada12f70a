{{ Case values and lookups laid out where the compiler puts them: a lookup's end address is pushed
  with one byte below $100 and two from there on, so a value priced at its branch's start (or a
  selector priced before the case's own end address) could pay a different push. Each case below
  sits a few bytes further on; one of them has a lookup whose end address crosses $100. }}
VAR
  long hits

PUB main | x, k
  x := 30
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[0]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[1]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[2]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[3]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[4]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[5]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[6]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[7]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[8]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[9]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[10]~~
  case x
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, lookupz(k & 7: 40, 7..2, -6), 50..lookup(1: 60):
      hits++
  dira[11]~~
