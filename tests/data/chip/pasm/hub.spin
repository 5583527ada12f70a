'' PASM probe: hub instructions and their windows.  The same loop runs in
'' cogs 1..7 (back-to-back reads, reads after 1..3 plain instructions,
'' writes, every size, misaligned addresses, ROM reads).
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long buf[8]
PUB main | i
  repeat i from 1 to 7
    coginit(i, @entry, @buf)
    waitcnt(cnt + 2000)
DAT
        org     0
entry   mov     p, par
        rdlong  x, p
        rdlong  x, p
        nop
        rdlong  x, p
        nop
        nop
        rdlong  x, p wz, wc
        nop
        nop
        nop
        rdlong  x, p
        cogid   x
        wrlong  x, p
        wrword  x, p
        add     p, #5
        wrbyte  minus, p
        rdbyte  y, p
        rdword  y, p
        rdlong  y, p wz
        sub     p, #1
        wrword  minus, p
        rdlong  y, p
        rdbyte  y, #0 wz
        rdword  y, #4 wc
        rdlong  y, rom          ' the ROM's sine table
        rdword  y, rom
        rdbyte  y, rom
        if_never rdlong y, p
        cogid   x
        cogstop x
p       long    0
x       long    0
y       long    0
minus   long    -1
rom     long    $E802
