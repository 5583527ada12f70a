VAR
  long n, v, w
PUB main | i
  n := 1
  outa++
  n := outa++
  outa := 3
  outa--
  n := outa--
  outa := 3
  ++outa
  n := ++outa
  outa := 3
  --outa
  outa := 3
  outa~
  n := outa~
  outa := 3
  outa~~
  n := outa~~
  outa := 3
  ~outa
  n := ~outa
  outa := 3
  ~~outa
  n := ~~outa
  outa := 3
  ?outa
  n := ?outa
  outa := 3
  outa?
  n := outa?
  outa := 3
  -outa
  outa := 3
  !outa
  outa := 3
  ||outa
  outa := 3
  |<outa
  outa := 3
  >|outa
  outa := 3
  ^^outa
  outa := 3
  outa ->= 3
  n := (outa ->= 5)
  outa := 7
  outa <-= 3
  n := (outa <-= 5)
  outa := 7
  outa >>= 3
  n := (outa >>= 5)
  outa := 7
  outa <<= 3
  n := (outa <<= 5)
  outa := 7
  outa #>= 3
  n := (outa #>= 5)
  outa := 7
  outa <#= 3
  n := (outa <#= 5)
  outa := 7
  outa &= 3
  n := (outa &= 5)
  outa := 7
  outa |= 3
  n := (outa |= 5)
  outa := 7
  outa ^= 3
  n := (outa ^= 5)
  outa := 7
  outa += 3
  n := (outa += 5)
  outa := 7
  outa -= 3
  n := (outa -= 5)
  outa := 7
  outa ~>= 3
  n := (outa ~>= 5)
  outa := 7
  outa ><= 3
  n := (outa ><= 5)
  outa := 7
  outa AND= 3
  n := (outa AND= 5)
  outa := 7
  outa OR= 3
  n := (outa OR= 5)
  outa := 7
  outa *= 3
  n := (outa *= 5)
  outa := 7
  outa **= 3
  n := (outa **= 5)
  outa := 7
  outa /= 3
  n := (outa /= 5)
  outa := 7
  outa //= 3
  n := (outa //= 5)
  outa := 7
  outa <= 3
  n := (outa <= 5)
  outa := 7
  outa >= 3
  n := (outa >= 5)
  outa := 7
  outa <>= 3
  n := (outa <>= 5)
  outa := 7
  outa === 3
  n := (outa === 5)
  outa := 7
  outa =<= 3
  n := (outa =<= 5)
  outa := 7
  outa =>= 3
  n := (outa =>= 5)
  outa := 7
  n := outa := 2
  v++
  n := v++
  v := 3
  v--
  n := v--
  v := 3
  ++v
  n := ++v
  v := 3
  --v
  v := 3
  v~
  n := v~
  v := 3
  v~~
  n := v~~
  v := 3
  ~v
  n := ~v
  v := 3
  ~~v
  n := ~~v
  v := 3
  ?v
  n := ?v
  v := 3
  v?
  n := v?
  v := 3
  -v
  v := 3
  !v
  v := 3
  ||v
  v := 3
  |<v
  v := 3
  >|v
  v := 3
  ^^v
  v := 3
  v ->= 3
  n := (v ->= 5)
  v := 7
  v <-= 3
  n := (v <-= 5)
  v := 7
  v >>= 3
  n := (v >>= 5)
  v := 7
  v <<= 3
  n := (v <<= 5)
  v := 7
  v #>= 3
  n := (v #>= 5)
  v := 7
  v <#= 3
  n := (v <#= 5)
  v := 7
  v &= 3
  n := (v &= 5)
  v := 7
  v |= 3
  n := (v |= 5)
  v := 7
  v ^= 3
  n := (v ^= 5)
  v := 7
  v += 3
  n := (v += 5)
  v := 7
  v -= 3
  n := (v -= 5)
  v := 7
  v ~>= 3
  n := (v ~>= 5)
  v := 7
  v ><= 3
  n := (v ><= 5)
  v := 7
  v AND= 3
  n := (v AND= 5)
  v := 7
  v OR= 3
  n := (v OR= 5)
  v := 7
  v *= 3
  n := (v *= 5)
  v := 7
  v **= 3
  n := (v **= 5)
  v := 7
  v /= 3
  n := (v /= 5)
  v := 7
  v //= 3
  n := (v //= 5)
  v := 7
  v <= 3
  n := (v <= 5)
  v := 7
  v >= 3
  n := (v >= 5)
  v := 7
  v <>= 3
  n := (v <>= 5)
  v := 7
  v === 3
  n := (v === 5)
  v := 7
  v =<= 3
  n := (v =<= 5)
  v := 7
  v =>= 3
  n := (v =>= 5)
  v := 7
  n := v := 2
  spr[5]++
  n := spr[5]++
  spr[5] := 3
  spr[5]--
  n := spr[5]--
  spr[5] := 3
  ++spr[5]
  n := ++spr[5]
  spr[5] := 3
  --spr[5]
  spr[5] := 3
  spr[5]~
  n := spr[5]~
  spr[5] := 3
  spr[5]~~
  n := spr[5]~~
  spr[5] := 3
  ~spr[5]
  n := ~spr[5]
  spr[5] := 3
  ~~spr[5]
  n := ~~spr[5]
  spr[5] := 3
  ?spr[5]
  n := ?spr[5]
  spr[5] := 3
  spr[5]?
  n := spr[5]?
  spr[5] := 3
  -spr[5]
  spr[5] := 3
  !spr[5]
  spr[5] := 3
  ||spr[5]
  spr[5] := 3
  |<spr[5]
  spr[5] := 3
  >|spr[5]
  spr[5] := 3
  ^^spr[5]
  spr[5] := 3
  spr[5] ->= 3
  n := (spr[5] ->= 5)
  spr[5] := 7
  spr[5] <-= 3
  n := (spr[5] <-= 5)
  spr[5] := 7
  spr[5] >>= 3
  n := (spr[5] >>= 5)
  spr[5] := 7
  spr[5] <<= 3
  n := (spr[5] <<= 5)
  spr[5] := 7
  spr[5] #>= 3
  n := (spr[5] #>= 5)
  spr[5] := 7
  spr[5] <#= 3
  n := (spr[5] <#= 5)
  spr[5] := 7
  spr[5] &= 3
  n := (spr[5] &= 5)
  spr[5] := 7
  spr[5] |= 3
  n := (spr[5] |= 5)
  spr[5] := 7
  spr[5] ^= 3
  n := (spr[5] ^= 5)
  spr[5] := 7
  spr[5] += 3
  n := (spr[5] += 5)
  spr[5] := 7
  spr[5] -= 3
  n := (spr[5] -= 5)
  spr[5] := 7
  spr[5] ~>= 3
  n := (spr[5] ~>= 5)
  spr[5] := 7
  spr[5] ><= 3
  n := (spr[5] ><= 5)
  spr[5] := 7
  spr[5] AND= 3
  n := (spr[5] AND= 5)
  spr[5] := 7
  spr[5] OR= 3
  n := (spr[5] OR= 5)
  spr[5] := 7
  spr[5] *= 3
  n := (spr[5] *= 5)
  spr[5] := 7
  spr[5] **= 3
  n := (spr[5] **= 5)
  spr[5] := 7
  spr[5] /= 3
  n := (spr[5] /= 5)
  spr[5] := 7
  spr[5] //= 3
  n := (spr[5] //= 5)
  spr[5] := 7
  spr[5] <= 3
  n := (spr[5] <= 5)
  spr[5] := 7
  spr[5] >= 3
  n := (spr[5] >= 5)
  spr[5] := 7
  spr[5] <>= 3
  n := (spr[5] <>= 5)
  spr[5] := 7
  spr[5] === 3
  n := (spr[5] === 5)
  spr[5] := 7
  spr[5] =<= 3
  n := (spr[5] =<= 5)
  spr[5] := 7
  spr[5] =>= 3
  n := (spr[5] =>= 5)
  spr[5] := 7
  n := spr[5] := 2
  outa[3]++
  n := outa[3]++
  outa[3] := 3
  outa[3]--
  n := outa[3]--
  outa[3] := 3
  ++outa[3]
  n := ++outa[3]
  outa[3] := 3
  --outa[3]
  outa[3] := 3
  outa[3]~
  n := outa[3]~
  outa[3] := 3
  outa[3]~~
  n := outa[3]~~
  outa[3] := 3
  ~outa[3]
  n := ~outa[3]
  outa[3] := 3
  ~~outa[3]
  n := ~~outa[3]
  outa[3] := 3
  ?outa[3]
  n := ?outa[3]
  outa[3] := 3
  outa[3]?
  n := outa[3]?
  outa[3] := 3
  -outa[3]
  outa[3] := 3
  !outa[3]
  outa[3] := 3
  ||outa[3]
  outa[3] := 3
  |<outa[3]
  outa[3] := 3
  >|outa[3]
  outa[3] := 3
  ^^outa[3]
  outa[3] := 3
  outa[3] ->= 3
  n := (outa[3] ->= 5)
  outa[3] := 7
  outa[3] <-= 3
  n := (outa[3] <-= 5)
  outa[3] := 7
  outa[3] >>= 3
  n := (outa[3] >>= 5)
  outa[3] := 7
  outa[3] <<= 3
  n := (outa[3] <<= 5)
  outa[3] := 7
  outa[3] #>= 3
  n := (outa[3] #>= 5)
  outa[3] := 7
  outa[3] <#= 3
  n := (outa[3] <#= 5)
  outa[3] := 7
  outa[3] &= 3
  n := (outa[3] &= 5)
  outa[3] := 7
  outa[3] |= 3
  n := (outa[3] |= 5)
  outa[3] := 7
  outa[3] ^= 3
  n := (outa[3] ^= 5)
  outa[3] := 7
  outa[3] += 3
  n := (outa[3] += 5)
  outa[3] := 7
  outa[3] -= 3
  n := (outa[3] -= 5)
  outa[3] := 7
  outa[3] ~>= 3
  n := (outa[3] ~>= 5)
  outa[3] := 7
  outa[3] ><= 3
  n := (outa[3] ><= 5)
  outa[3] := 7
  outa[3] AND= 3
  n := (outa[3] AND= 5)
  outa[3] := 7
  outa[3] OR= 3
  n := (outa[3] OR= 5)
  outa[3] := 7
  outa[3] *= 3
  n := (outa[3] *= 5)
  outa[3] := 7
  outa[3] **= 3
  n := (outa[3] **= 5)
  outa[3] := 7
  outa[3] /= 3
  n := (outa[3] /= 5)
  outa[3] := 7
  outa[3] //= 3
  n := (outa[3] //= 5)
  outa[3] := 7
  outa[3] <= 3
  n := (outa[3] <= 5)
  outa[3] := 7
  outa[3] >= 3
  n := (outa[3] >= 5)
  outa[3] := 7
  outa[3] <>= 3
  n := (outa[3] <>= 5)
  outa[3] := 7
  outa[3] === 3
  n := (outa[3] === 5)
  outa[3] := 7
  outa[3] =<= 3
  n := (outa[3] =<= 5)
  outa[3] := 7
  outa[3] =>= 3
  n := (outa[3] =>= 5)
  outa[3] := 7
  n := outa[3] := 2
  outa[7..4]++
  n := outa[7..4]++
  outa[7..4] := 3
  outa[7..4]--
  n := outa[7..4]--
  outa[7..4] := 3
  ++outa[7..4]
  n := ++outa[7..4]
  outa[7..4] := 3
  --outa[7..4]
  outa[7..4] := 3
  outa[7..4]~
  n := outa[7..4]~
  outa[7..4] := 3
  outa[7..4]~~
  n := outa[7..4]~~
  outa[7..4] := 3
  ~outa[7..4]
  n := ~outa[7..4]
  outa[7..4] := 3
  ~~outa[7..4]
  n := ~~outa[7..4]
  outa[7..4] := 3
  ?outa[7..4]
  n := ?outa[7..4]
  outa[7..4] := 3
  outa[7..4]?
  n := outa[7..4]?
  outa[7..4] := 3
  -outa[7..4]
  outa[7..4] := 3
  !outa[7..4]
  outa[7..4] := 3
  ||outa[7..4]
  outa[7..4] := 3
  |<outa[7..4]
  outa[7..4] := 3
  >|outa[7..4]
  outa[7..4] := 3
  ^^outa[7..4]
  outa[7..4] := 3
  outa[7..4] ->= 3
  n := (outa[7..4] ->= 5)
  outa[7..4] := 7
  outa[7..4] <-= 3
  n := (outa[7..4] <-= 5)
  outa[7..4] := 7
  outa[7..4] >>= 3
  n := (outa[7..4] >>= 5)
  outa[7..4] := 7
  outa[7..4] <<= 3
  n := (outa[7..4] <<= 5)
  outa[7..4] := 7
  outa[7..4] #>= 3
  n := (outa[7..4] #>= 5)
  outa[7..4] := 7
  outa[7..4] <#= 3
  n := (outa[7..4] <#= 5)
  outa[7..4] := 7
  outa[7..4] &= 3
  n := (outa[7..4] &= 5)
  outa[7..4] := 7
  outa[7..4] |= 3
  n := (outa[7..4] |= 5)
  outa[7..4] := 7
  outa[7..4] ^= 3
  n := (outa[7..4] ^= 5)
  outa[7..4] := 7
  outa[7..4] += 3
  n := (outa[7..4] += 5)
  outa[7..4] := 7
  outa[7..4] -= 3
  n := (outa[7..4] -= 5)
  outa[7..4] := 7
  outa[7..4] ~>= 3
  n := (outa[7..4] ~>= 5)
  outa[7..4] := 7
  outa[7..4] ><= 3
  n := (outa[7..4] ><= 5)
  outa[7..4] := 7
  outa[7..4] AND= 3
  n := (outa[7..4] AND= 5)
  outa[7..4] := 7
  outa[7..4] OR= 3
  n := (outa[7..4] OR= 5)
  outa[7..4] := 7
  outa[7..4] *= 3
  n := (outa[7..4] *= 5)
  outa[7..4] := 7
  outa[7..4] **= 3
  n := (outa[7..4] **= 5)
  outa[7..4] := 7
  outa[7..4] /= 3
  n := (outa[7..4] /= 5)
  outa[7..4] := 7
  outa[7..4] //= 3
  n := (outa[7..4] //= 5)
  outa[7..4] := 7
  outa[7..4] <= 3
  n := (outa[7..4] <= 5)
  outa[7..4] := 7
  outa[7..4] >= 3
  n := (outa[7..4] >= 5)
  outa[7..4] := 7
  outa[7..4] <>= 3
  n := (outa[7..4] <>= 5)
  outa[7..4] := 7
  outa[7..4] === 3
  n := (outa[7..4] === 5)
  outa[7..4] := 7
  outa[7..4] =<= 3
  n := (outa[7..4] =<= 5)
  outa[7..4] := 7
  outa[7..4] =>= 3
  n := (outa[7..4] =>= 5)
  outa[7..4] := 7
  n := outa[7..4] := 2
  outa := 0
  n := strcomp(string("ab"), string("ac"))
  sl := 1
  n := sl
  n := @sl
  n := sl := 3
  sl -= 1
  sw := 1
  n := sw
  n := @sw
  n := sw := 3
  sw -= 1
  sb := 1
  n := sb
  n := @sb
  n := sb := 3
  sb -= 1
  sl[1] := 1
  n := sl[1]
  n := @sl[1]
  n := sl[1] := 3
  sl[1] -= 1
  sw[1] := 1
  n := sw[1]
  n := @sw[1]
  n := sw[1] := 3
  sw[1] -= 1
  sb[1] := 1
  n := sb[1]
  n := @sb[1]
  n := sb[1] := 3
  sb[1] -= 1
  v := 1
  repeat
    v++
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
  while v < 3
  v := 0
  repeat v
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
    v := w + n * v - i
  v := 99
  case v
    1..5:
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
      v := w + n * v - i
    7: n := 1
DAT
sl long 1, 2
sw word 1, 2
sb byte 1, 2
