'' PASM probe: a PASM cog starts the Spin interpreter.  The first run of main
'' starts the PASM cog and stops its own cog; the PASM cog starts a new Spin
'' cog on the boot frame at $0004, which runs main again (now flag is set).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long flag
PUB main
  if flag == 0
    flag := 1
    cognew(@entry, 0)
    cogstop(cogid)
  dira[4] := 1
  outa[4] := 1
  waitcnt(cnt + 2000)
DAT
        org     0
entry   mov     t, cnt
        add     t, #500
        waitcnt t, #0
        mov     x, spin
        coginit x wc, wr        ' NEW: the first free cog
        cogid   t
        cogstop t
spin    long    ($0004 >> 2) << 18 | ($F004 >> 2) << 4 | %1000
t       long    0
x       long    0
