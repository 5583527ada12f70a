' Probe: PASM in DAT (conditions, effects, immediates, local labels, call/ret, $, org, res, fit)
CON
  PIN = 16
  DELAY = 80_000

VAR
  long cog

PUB start
  cog := cognew(@entry, @cog) + 1

DAT
              org       0
entry         mov       dira, mask
              mov       time, cnt
              add       time, #9
:loop         waitcnt   time, delay_
              xor       outa, mask
              call      #toggle
        if_nz jmp       #:loop
              djnz      count, #:loop   wz, wc
              test      mask, ina       wc
              muxc      outa, mask
              rdlong    value, par
              wrlong    value, par
              cmp       value, #0       wz
  if_c_and_z  add       value, #1
              sub       value, #1       nr
              jmp       #$
              jmp       #$ + 2
toggle        xor       outa, mask
toggle_ret    ret

mask          long      1 << PIN
delay_        long      DELAY
count         long      10
time          res       1
value         res       1
              fit       496

              org       $100
second        mov       second, #second
              long      @entry, @second
