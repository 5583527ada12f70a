'' Conformance probe: a cog restarts itself with COGINIT (a common start-up idiom:
'' "coginit(0, main2, @stack)" to run on a known stack, or to turn cog 0 into a
'' PASM driver).  The new program's first instruction runs as soon as the
'' COGINIT's hub access ends, not after the rest of the COGINIT bytecode.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long stk[32], stk2[32], t[4]
PUB main
  t[0] := cnt
  coginit(cogid, second, @stk)
PRI second
  t[1] := cnt
  dira[1] := 1
  outa[1] := 1
  coginit(cogid, third(5), @stk2)
PRI third(n)
  t[2] := cnt
  dira[2] := 1
  outa[2] := n
  coginit(cogid, @entry, @t[3])
DAT
        org 0
entry   mov x, cnt
        wrlong x, par
        or dira, mask
        or outa, mask
        cogid x
        cogstop x
mask    long |< 3
x       long 0
