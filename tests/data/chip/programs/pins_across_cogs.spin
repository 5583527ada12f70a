'' Conformance probe: one Spin cog reads pins that other Spin cogs write.
'' Writers toggle, assign bits, ranges and whole registers (REG bytecodes
'' $3D/$3E/$3F, each writing its register late in its path); the reader samples
'' INA (bit, range, whole) at a cycle that moves by one each pass, so it lands
'' on every phase of the writers' loops, and waits on them with WAITPEQ/WAITPNE.
'' The writers end when told (a cog stopped by another inside a bytecode keeps
'' that bytecode's stack writes on spinemu: docs/chip.md).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long bits[40], ranges[40], whole[40], waits[8]
  long stack1[24], stack2[24], stack3[24], done
PUB main | k, t, w1, w2, w3
  w1 := cognew(toggler, @stack1)
  w2 := cognew(ranger, @stack2)
  w3 := cognew(wholer, @stack3)
  waitcnt(cnt + 20_000)
  repeat k from 0 to 39
    t := cnt + 3_000 + k * 7
    waitcnt(t)
    bits[k] := ina[17] | ina[18] << 1 | (cnt - t) << 8
    t := cnt + 3_000 + k * 5
    waitcnt(t)
    ranges[k] := ina[23..20]
    whole[k] := ina & $0F0F_0000
  repeat k from 0 to 3
    waitpeq(|< 17, |< 17, 0)
    waits[2 * k] := cnt
    waitpne(|< 18, |< 18, 0)
    waits[2 * k + 1] := cnt
  done := 1
PRI toggler
  dira[17] := 1
  repeat until done
    !outa[17]
PRI ranger | n
  dira[23..18] := %111111
  repeat until done
    outa[18] := n >> 2
    outa[23..20] := n++
PRI wholer | n
  dira := $0F00_0000
  repeat until done
    outa := n += $0100_0000
