'' PASM probe: COGINIT and COGSTOP from PASM.  Cog 3 starts cog 5 (a higher
'' id) and cog 1 (a lower id): when the new cog's first
'' instruction runs, when a stopped cog's last one ran, NEW with no cog free,
'' the flags and results, and a cog restarting itself.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long flag
PUB main
  code := @counter << 2         ' ADDR field (bits 17..4) of a COGINIT long
  self := @starter << 2
  coginit(3, @starter, @flag)
  waitcnt(cnt + 40_000)
DAT
        org     0
starter rdlong  again, par wz    ' 0 the first time; after the restart PAR is 0: hub long 0
  if_nz cogid   x
  if_nz cogstop x
        mov     x, code         ' cog 5 (higher id) runs the counter
        or      x, #5
        coginit x wz, wc, wr
        mov     x, code         ' cog 1 (lower id) too
        or      x, #1
        coginit x wz, wc, wr
        mov     t, cnt
        add     t, #100
        waitcnt t, #0
        mov     x, #5
        cogstop x wz, wc, wr    ' stop the higher-id cog
        mov     x, #1
        cogstop x wz, wc, wr    ' stop the lower-id cog
        mov     n, #6           ' fill every cog with NEW (the last one finds none free)
fill    mov     x, code
        or      x, #8
        coginit x wz, wc, wr
        djnz    n, #fill
        mov     n, #8
stop    sub     n, #1
        cmp     n, #3 wz
  if_nz cogstop n wz, wc
        tjnz    n, #stop
        mov     x, #2
        cogstop x wz, wc, wr    ' already stopped
        mov     x, self         ' restart this very cog on this code
        cogid   y
        or      x, y
        coginit x
x       long    0
y       long    0
t       long    0
n       long    0
again   long    0
code    long    0               ' set by main before the cog starts
self    long    0

        org     0
counter add     count, #1
        jmp     #counter
count   long    0
