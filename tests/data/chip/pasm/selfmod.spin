'' PASM probe: the pipeline. The instruction after one that writes cog RAM was
'' fetched before the write; a jump's target likewise (jmpret to itself, djnz).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@entry, 0)
DAT
        org     0
entry   movs    n1, #7          ' changes the next instruction: it runs unchanged
n1      mov     y, #0
        movs    n2, #7          ' one instruction between: the change is seen
        nop
n2      mov     y, #0
        jmpret  n3, #n3         ' writes its own target (the next long)
n3      mov     y, #1
        jmpret  n4, #n4         ' writes a target two longs on
        nop
n4      mov     y, #1
        movs    n5, #5
        jmp     #n5
n5      mov     y, #1
        mov     x, #2
        movs    n6, #5
        djnz    x, #n6
n6      mov     y, #1
        movs    n7, #9          ' changes the next (a djnz): old target used
n7      djnz    x, #n9
        mov     y, #3
n9      mov     y, #4
        mov     x, #n10
        jmpret  n10, x          ' indirect jump to the long it writes
        nop
n10     mov     y, #5
        mov     z, #n11
        movd    n11, #y
n11     add     z, #1           ' its destination changed one instruction earlier: runs unchanged
        movi    n12, #%101000_001    ' mov
n12     add     y, #7
        mov     x, #3
loop    add     y, #1
        djnz    x, #loop        ' taken twice (4 cycles), then falls through (8)
        cogid   x
        cogstop x
x       long    0
y       long    0
z       long    0
