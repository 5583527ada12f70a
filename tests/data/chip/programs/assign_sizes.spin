VAR
  long r[100]
  long n, l
  word w
  byte b
PUB main | i
  b := 255
  r[n++] := ++b
  r[n++] := b
  b := 0
  r[n++] := --b
  r[n++] := b
  b := 255
  r[n++] := b++
  r[n++] := b
  w := $FFFF
  r[n++] := ++w
  r[n++] := w--
  r[n++] := w
  b := $80
  r[n++] := ~b
  r[n++] := b
  w := $8000
  r[n++] := ~~w
  r[n++] := w
  l := $80
  r[n++] := ~l
  r[n++] := l
  l := $1234
  r[n++] := l~
  r[n++] := l
  r[n++] := l~~
  r[n++] := l
  b := 5
  r[n++] := b~~
  r[n++] := b
  r[n++] := b := 300
  r[n++] := b
  b := 200
  r[n++] := b += 100
  r[n++] := b
  w := 1
  r[n++] := w -= 2
  r[n++] := w
  l := 12345
  r[n++] := ?l
  r[n++] := ?l
  r[n++] := l?
  r[n++] := l?
  l := 0
  r[n++] := ?l
  l := 0
  r[n++] := l?
  l := -1
  r[n++] := ?l
  l := 1
  r[n++] := ?l
  r[n++] := ?l
  l := 1
  r[n++] := l?
  r[n++] := l?
  b := 7
  r[n++] := ?b
  r[n++] := b
  r[n++] := -l
  l := 5
  r[n++] := -l
  r[n++] := l
  r[n++] := !l
  r[n++] := ||l
  r[n++] := l
  l := 100
  r[n++] := l *= 3
  r[n++] := l /= 7
  r[n++] := l //= 5
  r[n++] := l
  outa := $F0
  r[n++] := outa[7..4]
  r[n++] := outa[4..7]
  outa[3..0] := %1011
  r[n++] := outa
  outa[0..3] := %1011
  r[n++] := outa
  r[n++] := outa[5]++
  r[n++] := outa
  r[n++] := ++outa[7..4]
  r[n++] := outa
  r[n++] := outa[7..4] += 3
  r[n++] := outa
  r[n++] := outa[3..0]~~
  r[n++] := outa
  r[n++] := outa[0]~
  r[n++] := outa
  r[n++] := -outa[7..4]
  r[n++] := outa
  r[n++] := !outa[1]
  r[n++] := outa
  r[n++] := outa[31..0]
  r[n++] := outa[0..31]
  r[n++] := spr[4]
  r[n++] := spr[20]
  spr[21] := 3
  r[n++] := outa
  r[n++] := n
