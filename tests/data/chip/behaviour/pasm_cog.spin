'' Starts a PASM cog that makes P0 an output for 100_000 cycles, then stops.
VAR
  long id
PUB main
  id := cognew(@entry, 0)
DAT
        org 0
entry   mov     dira, #1
        mov     t, cnt
        add     t, delay
        waitcnt t, #0
        cogid   t
        cogstop t
delay   long    100_000
t       long    0
