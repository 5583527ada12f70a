'' Conformance probe: a PASM cog samples a pin that a Spin cog toggles (the
'' Spin interpreter writes OUTA late in the bytecode), at a moment that moves
'' by 223 cycles each pass, so it lands on every phase of the Spin loop.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long results[64]
  long stack[20], done
PUB main
  cognew(toggler, @stack)
  cognew(@sampler, @results)
  waitcnt(cnt + 400_000)
  done := 1
PRI toggler
  dira[17] := 1
  repeat until done
    !outa[17]
DAT
        org 0
sampler mov ptr, par
        mov cntr, #64
        mov wt, cnt
        add wt, #200
:loop   add wt, #223
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
