'' PASM probe: WAITCNT targets 0..33 cycles after CNT (a target up to 3
'' cycles back still counts), its flags, and CNT as a shadow destination.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@entry, 0)
DAT
        org     0
entry   mov     d, #5
loop    mov     t, cnt
        add     t, d
        waitcnt t, #0
        add     d, #1
        cmp     d, #34 wz
  if_nz jmp     #loop
        mov     t, cnt
        add     t, #40
        waitcnt t, minus wz, wc
        mov     cnt, #9         ' CNT as destination: shadow RAM
        add     cnt, cnt
        waitcnt cnt, #16
        waitcnt cnt, #0 wz, wc
        mov     t, cnt
        if_never waitcnt t, #0
        cogid   t
        cogstop t
d       long    0
t       long    0
minus   long    -1
