'' pasm_blinker.spin: a PASM pin toggler started with cognew (spinemu disasm test object)
CON
  DEFAULT_TICKS = 40_000

VAR
  long cog
  long pinmask, ticks                 ' handed to the cog through PAR

PUB start(pin, period) : ok
  stop
  pinmask := |< pin
  ticks := period #> 400
  ok := cog := cognew(@entry, @pinmask) + 1

PUB stop
  if cog
    cogstop(cog~ - 1)

PUB running
  return cog <> 0

DAT
              org     0
entry         mov     t1, par
              rdlong  mask, t1
              add     t1, #4
              rdlong  delay, t1
              or      dira, mask
              mov     time, cnt
              add     time, delay
:loop         call    #toggle
              waitcnt time, delay
              djnz    count, #:loop   wz
              mov     count, #100
        if_z  jmp     #:loop
              jmp     #:loop
toggle        xor     outa, mask
              test    mask, ina       wc
              muxc    flags, #1
toggle_ret    ret
count         long    100
flags         long    0
mask          res     1
delay         res     1
time          res     1
t1            res     1
              fit
