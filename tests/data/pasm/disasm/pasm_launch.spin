'' pasm_launch.spin: launch forms and data that spinemu disasm must not take for code
PUB main
  cognew(@code[0], 0)
  coginit(cogid, @bitmap, @glyphs)        ' no code there: launched, but shown as such

DAT
glyphs        byte    $FC, $FC, $FC, $03, $FC, $FC, $FC, $FC, $E0, $FC, $FC, $FC
              byte    $E0, $E0, $E0, $E0, $E0, $E0, $E0, $E0, $E0, $FC, $FC, $FC
              byte    $FC, $FC, $FC, $FC, $FC, $FC, $FC, $03
              long    $FFFFFFFF[8]

              org     0
code          long    1 << 9                  ' d0 trick: runs as a no-op at cog $000
              mov     dira, #1
:loop         xor     outa, #1
              jmp     #:loop

bitmap        long    0
