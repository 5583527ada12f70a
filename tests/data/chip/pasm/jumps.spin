'' PASM probe: jmp/jmpret/call/ret, djnz/tjz/tjnz taken and not, their flags,
'' conditions on jumps, jumps through registers, and pc wrapping past $1FF.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@entry, 0)
DAT
        org     0
entry   call    #subr
        call    #subr
        mov     x, #$10
        jmpret  x, #l1 wz, wc, nr
l1      mov     x, minus
        jmpret  x, #l2 wz, wc
l2      mov     x, #0
        jmp     #l3 wz, wc
l3      mov     x, #1
        djnz    x, #l4 wz, wc
l4      mov     x, #0
        djnz    x, #l5 wz, wc
l5      mov     x, #2
        djnz    x, #l6 wz, wc
l6      mov     x, #0
        tjz     x, #l7 wz, wc
l7      tjnz    x, #l8 wz, wc
l8      mov     x, minus
        tjz     x, #l9 wz, wc
l9      tjnz    x, #l10 wz, wc
l10     mov     x, #0 wz
  if_nz jmp     #l10
  if_z  djnz    x, #l11
l11     mov     x, #l12
        jmp     x
        nop
l12     mov     x, #0 wc
  if_c  tjz     x, #l13
  if_nc tjz     x, #l13
        nop
l13     tjnz    minus, #l14 wr
l14     djnz    x, #l15 nr
l15     mov     cnt2, #3
l16     djnz    cnt2, #l16
        jmp     #wrap
subr    add     x, #1
subr_ret ret
wrap    mov     entry, jmpdone  ' after the wrap, $000 ends the probe
        mov     $1fe, #0        ' VCFG: a harmless long at $1FE
        movi    $1ff, #%101000_001
        movd    $1ff, #x
        movs    $1ff, #7        ' VSCL ($1FF): mov x, #7; then the pc wraps to $000
        jmp     #$1fe
done    cogid   x
        cogstop x
jmpdone jmp     #done
x       long    0
cnt2    long    0
minus   long    -1
        fit     $1f0
