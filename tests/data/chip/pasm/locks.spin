'' PASM probe: LOCKNEW/LOCKRET/LOCKSET/LOCKCLR and COGID: results, flags
'' (Z and C set before each, so unchanged flags show), lock 0, all locks taken.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@entry, 0)
DAT
        org     0
entry   mov     n, #9
new     mov     x, #0 wz        ' Z = 1
        cmp     x, #1 wc        ' C = 1
        locknew x wz, wc        ' the ninth finds none free
        djnz    n, #new
        mov     x, #3
        lockret x wz, wc
        locknew x wz, wc, wr
        mov     x, #3
        lockset x wz, wc, wr
        lockset x wz, wc
        lockclr x wz, wc, wr
        lockclr x wz, wc
        mov     x, #0
        lockset x wz, wc        ' lock 0: Z = 1
        lockret x wz, wc
        mov     x, #8           ' 8 is lock 0 too
        lockclr x wz, wc
        mov     x, #2 wz
        cmp     x, #3 wc
        cogid   x wz, wc        ' flags unchanged
        cogid   x nr
        mov     x, #0 wz
        cogid   x wz, wc
        cogid   x
        cogstop x
n       long    0
x       long    0
