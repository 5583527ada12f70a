'' Conformance probe: a PASM cog toggles a pin on a 16-cycle loop; a PASM cog
'' samples it every 61 cycles (every phase of the loop) and the Spin cog reads
'' it with INA bit, range and whole-register reads at moving moments.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long pasm_seen[64], spin_seen[48]
PUB main | k, t, w
  w := cognew(@toggler, 0)
  cognew(@sampler, @pasm_seen)
  waitcnt(cnt + 20_000)
  repeat k from 0 to 15
    t := cnt + 3000 + k
    waitcnt(t)
    spin_seen[3 * k] := ina[17]
    t := cnt + 3000 + k
    waitcnt(t)
    spin_seen[3 * k + 1] := ina[18..16]
    t := cnt + 3000 + k
    waitcnt(t)
    spin_seen[3 * k + 2] := ina & $0002_0000
  waitcnt(cnt + 100_000)
  cogstop(w)
DAT
        org 0
toggler mov dira, tmask
:loop   xor outa, tmask
        nop
        xor outa, tmask
        jmp #:loop
tmask   long 1 << 17

        org 0
sampler mov ptr, par
        mov cntr, #64
        mov wt, cnt
        add wt, #200
:loop   add wt, #61
        waitcnt wt, #0
        mov x, ina
        shr x, #17
        and x, #1
        wrlong x, ptr
        add ptr, #4
        djnz cntr, #:loop
        cogid x
        cogstop x
ptr     res 1
cntr    res 1
wt      res 1
x       res 1
