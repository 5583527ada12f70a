'' PASM probe: the special registers $1F0-$1FF as source and destination.
'' PAR, CNT, INA, INB as destination read their shadow RAM; writes to them land
'' there; OUTA/DIRA/CTR/FRQ/PHS/VCFG/VSCL read back; PHS without a counter.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long buf[4]
PUB main
  cognew(@entry, @buf)
DAT
        org     0
entry   mov     y, par
        mov     y, cnt
        mov     y, ina
        mov     y, inb
        cmp     cnt, #0 wz      ' shadow: 0
        mov     cnt, #9
        add     cnt, #1
        mov     y, cnt
        mov     y, #3
        add     ina, y
        mov     y, ina
        mov     ina, #5
        cmp     ina, #5 wz
        mov     inb, #7
        add     inb, #1
        mov     dira, #$F0
        or      outa, #$30
        xor     outa, #$C0
        mov     y, outa
        mov     y, ina
        andn    dira, #$10
        mov     y, ina
        mov     y, dira
        mov     ctra, #3
        mov     y, ctra
        mov     frqb, #7
        add     frqb, frqb
        mov     y, frqb
        mov     phsa, #11
        add     phsa, #1
        mov     y, phsa
        add     y, phsb
        mov     vcfg, #3
        mov     y, vcfg
        mov     vscl, #5
        mov     y, vscl
        mov     outb, #9
        mov     y, outb
        mov     dirb, #1
        mov     y, dirb
        mov     dira, #0
        cogid   y
        cogstop y
y       long    0
