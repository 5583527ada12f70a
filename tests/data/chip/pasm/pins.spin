'' PASM probe: INA and WAITPEQ/WAITPNE across cogs.  Cog 1 and cog 2 each
'' write P0/P1 at chosen cycles; the other reads INA in a tight loop and
'' waits on the pin, so both orders of cog ids are seen: a write is seen in
'' the same cycle by a cog with a higher id, one cycle step later by a lower.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@cog1, 0)
  cognew(@cog2, 0)
DAT
        org     0
cog1    mov     dira, #1
        mov     t, cnt
        add     t, delay1
        waitcnt t, #100         ' P0 high at a known cycle
        mov     outa, #1
        nop
        mov     outa, #0        ' one instruction later: low
        mov     outa, #1
        waitcnt t, #0
        mov     outa, #0
        nop
        mov     outa, #1        ' high again (cog 2 waits for it)
poll1   test    two, ina wz     ' now cog 1 polls P1, driven by cog 2
  if_z  jmp     #poll1
        waitpne two, two wz, wc ' P1 goes low again
        mov     x, cnt
        waitpeq two, two        ' and high
        mov     x, cnt
        waitpeq zero, #0        ' true at once: 4 cycles
        cogid   x
        cogstop x
t       long    0
delay1  long    3000
two     long    2
zero    long    0
x       long    0

        org     0
cog2    mov     dira, #2
low     test    one, ina wz     ' P0 is high until cog 1 drives it
  if_nz jmp     #low
poll    test    one, ina wz
  if_z  jmp     #poll
        waitpne one, one        ' low
        waitpeq one, one wz     ' high again
        mov     y, cnt
        mov     t2, cnt
        add     t2, delay2
        waitcnt t2, #12
        mov     outa, #2
        waitcnt t2, #8
        mov     outa, #0
        waitcnt t2, #0
        mov     outa, #2
        mov     t2, cnt
        add     t2, #200
        waitcnt t2, #0
        cogid   y
        cogstop y
one     long    1
y       long    0
t2      long    0
delay2  long    400
