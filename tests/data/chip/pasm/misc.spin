'' PASM probe: odd corners.  Opcodes $04-$07 (no instruction: a hub slot,
'' D := 0), HUBOP with the operation in a register, CLKSET to the same mode,
'' WAITVID without video (4 cycles in spinsim), every condition code against
'' all four flag states, and effects on instructions that do not write.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  cognew(@entry, 0)
DAT
        org     0
entry   mov     x, #0 wz
        cmp     x, #1 wc
        long    %000100_1110_1111_000000000 << 9 | (x - 0) << 9 | (y - 0)    ' opcode $04 wz wc wr
        long    %000111_0010_1111_000000000 << 9 | (x - 0) << 9 | (y - 0)    ' opcode $07 wr
        mov     y, #1
        hubop   x, y wr         ' operation 1: cogid
        mov     y, #0
        rdbyte  x, #4
        clkset  x               ' the mode the program runs in: nothing changes
        clkset  x wr            ' wr writes D back
        hubop   x, y wr         ' y = 0: CLKSET through a register
        waitvid x, #0
        waitvid x, #0 wz, wc
        mov     f, #0
flags   shr     f, #1 wc, nr    ' C = bit 0 of f
        test    f, #2 wz        ' Z = bit 1 of f clear
        mov     y, #0
  if_never      add y, #1
  if_nc_and_nz  add y, #2
  if_nc_and_z   add y, #4
  if_nc         add y, #8
  if_c_and_nz   add y, #16
  if_nz         add y, #32
  if_c_ne_z     add y, #64
  if_nc_or_nz   add y, #128
  if_c_and_z    add y, #256
  if_c_eq_z     add y, #1
  if_z          add y, #2
  if_nc_or_z    add y, #4
  if_c          add y, #8
  if_c_or_nz    add y, #16
  if_c_or_z     add y, #32
  if_always     add y, #64
        add     f, #1
        cmp     f, #4 wz
  if_nz jmp     #flags
        cmp     x, y wz, wc, wr
        test    x, y wc, wr
        mov     x, #5 nr
        cogid   x
        cogstop x
x       long    0
y       long    0
f       long    0
