'' Statements with several timed events: calls whose callees write pins, register reads and
'' writes, a wait; each event must happen at its own cycle (the bytecode engine's).
VAR
  long r[8], a
PUB main | i
  dira[7..0] := $FF
  a := 2
  r[0] := pin(1) + pin(2)
  r[1] := pin(pin(3))
  outa[7..4] := pin(4)
  outa[3..0] := ina[3..0] + pin(5)
  r[2] := pin(6) + cnt - cnt
  if pin(7) + pin(8)
    outa[1] := 1
  repeat i from 0 to 2
    r[3] += pin(i) * ina[0]
  waitcnt(pin(9) * 100 + cnt)
  !outa[7..0]
  r[4] := (outa[2] := pin(10)) + pin(11)
  r[5] := pin(12) / a + (outa[6] := 1)
  r[6] := (phsa := pin(13)) + phsa
  case pin(16)
    17: r[7] := pin(17)
    pin(18), 5: r[7] := 1
  case a
    pin(19): r[7] := 2
  if pin(20) + pin(21)
    r[7]++
  repeat pin(1)
    r[7]++
  r[pin(22) & 7] := (a := 7)
  outb[a..pin(23)]--
  case 3
    (outa[7..4] := 3): r[7]++
  r[7] := lookdown(a : 1, (outa[3..0] := 5), 3)
  a := pin(24) / 3 + pin(25) // a
  longfill(@r, ~outa[2], 2)
  a := pin(26) + (outa //= 7) + spr[4]
  r[7 // 3] := pin(27)
  r[5] := pin(28) <- (pin(29) * r[(a >> 1) // 3] + pin(30)) ^ r[pin(31) // 4]
  a := cnt
  waitcnt(a += clkfreq / 1000)
  return pin(14) + pin(15)
PRI pin(v)
  outa[v & 7] := 1
  outa[v & 7] := 0
  return v + 1
