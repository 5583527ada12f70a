'' PASM probe: a Spin cog and a PASM cog share hub RAM and pins.  Spin
'' writes a number, PASM echoes it and mirrors P1 (driven by Spin) onto P2,
'' Spin waits for P2, and finally stops the PASM cog.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long flag, echo
PUB main | i
  cognew(@pasm, @flag)
  dira[1] := 1
  repeat i from 1 to 12
    flag := i
    repeat until echo == i
    outa[1] := i & 1
    waitpeq((i & 1) << 2, 4, 0)
  cogstop(1)
  dira[1] := 0
DAT
        org     0
pasm    mov     p, par
        mov     e, par
        add     e, #4
        or      dira, #4
loop    rdlong  v, p
        cmp     v, last wz
  if_z  jmp     #loop
        mov     last, v
        wrlong  v, e
        test    v, #1 wz
  if_nz waitpne zero, #2        ' odd: wait for P1 high
  if_z  waitpeq zero, #2        ' even: wait for P1 low
        test    two, ina wz
        muxnz   outa, #4
        jmp     #loop
p       long    0
e       long    0
v       long    0
last    long    0
two     long    2
zero    long    0
