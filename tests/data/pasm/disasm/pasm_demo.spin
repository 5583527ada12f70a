'' pasm_demo.spin: exercises what spinemu disasm shows (objects, strings, case, PASM in DAT)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

VAR
  long  counter
  word  small[3]
  byte  flag

OBJ
  blink[2] : "pasm_blinker"

PUB main | i, r
  blink[0].start(16, 80_000)
  blink[1].start(17, 160_000)
  repeat i from 0 to 9 step 3
    counter += lookup(i: 10, 20, 30..33)
    small[i // 3] := lookdown(i: 0, 3, 6..9)
  r := classify(counter)
  flag := strsize(name(r))
  coginit(cogid + 1, @counter_loop, @counter)
  repeat while blink[0].running
    waitcnt(cnt + clkfreq / 10)
    !outa[5..4]

PRI classify(x) : kind
  case x
    0: kind := 0
    1..9: kind := 1
    10, 20, 30: kind := 2
    other: kind := 3

PRI name(k)
  return lookupz(k: string("zero"), string("small"), string("round"), string("big"))

DAT
table         byte    1, 2, 3, 4, "text", 0
              word    $1234, $5678
              long    $DEADBEEF, -1

              org     0
counter_loop  rdlong  value, par
              add     value, #1
              wrlong  value, par
              jmp     #counter_loop
value         long    0

              org     0
spare         mov     dira, #$FF                ' never launched: found by the plausibility scan
              mov     outa, #0
:next         add     outa, #1
              cmp     outa, #$FF      wz
        if_ne jmp     #:next
              cogid   value
              cogstop value
