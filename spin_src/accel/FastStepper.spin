'' =================================================================================================
''
''   File....... FastStepper.spin
''   Purpose.... Fast step/direction stepper driver: a PASM step generator fed by a Spin ramp planner
''   Updated.... spinemu project
''
'' =================================================================================================
''
'' FastAccelStepper's design on a Propeller: two cogs and a queue between them.
''
''   * The step generator (PASM, one cog) takes commands from a queue in hub RAM: "n steps,
''     t clock ticks apart, this direction".  It makes every step with WAITCNT on the exact
''     tick (each step is due t after the one before, across commands), a STEP pulse of
''     2.5 us, DIR set at least 5 us before a step in the new direction, and keeps the
''     position in hub RAM.  It enables the driver itself (auto-enable): before the first step
''     after a standstill it raises the enable pin and waits the on-delay; when the queue has
''     been empty for the off-delay after the last step, it drops the enable pin again.
''   * The ramp planner (Spin, one cog) keeps the queue filled about 6 ms ahead.  Its state is
''     the ramp position s, the steps it takes to stop from the present speed: s = v^2 / (2 a).
''     Accelerating from s to s + n takes (v(s+n) - v(s)) / a seconds, so every step of that
''     command is t = K / (sqrt(s) + sqrt(s + n)) ticks apart, K = clkfreq * sqrt(2 / a); it
''     decelerates the same way from s to s - n once the distance left is s, and cruises at
''     clkfreq / maxSpeed in between.  A command covers about 2 ms of motion.
''
'' The queue (QUEUE_LEN entries of two longs) can also be filled by hand with queueEntry:
''   long 0: steps (1..65,535) | FORWARD (bit 31) | LAST (bit 30: the move ends after it)
''   long 1: ticks from one step to the next (also from the last step of the entry before)
'' When the queue runs dry in the middle of a move (the last entry was not LAST and the next
'' step is overdue) the generator counts an underrun and the motor stops where it is; a step
'' that comes too late for WAITCNT is made at once and counted in lateSteps.
''
'' Speeds: the PASM loop needs about 1 us per step besides the 2.5 us pulse, so 50,000 steps/s
'' (1,600 ticks at 80 MHz) leaves the cog idle most of the time; the Spin planner, one command
'' per 2 ms, keeps up.  The ramp planner keeps s below 32,768 (50,000 steps/s
'' needs an acceleration of at least 38,147 steps/s^2).  Units are whole steps/s and steps/s^2.
''
''   OBJ  fast : "FastStepper"
''   PUB main
''     fast.start(0, 1, 2, true)                    ' STEP P0, DIR P1, ~ENABLE P2 (active low)
''     fast.setSpeedInHz(50_000)
''     fast.setAcceleration(200_000)
''     fast.moveTo(20_000)
''     repeat while fast.isRunning
''
'' =================================================================================================

CON

  QUEUE_LEN     = 16                                    ' entries, a power of two
  FORWARD       = $8000_0000                            ' entry flags
  LAST          = $4000_0000
  STEPS_MASK    = $FFFF
  MAX_S         = 32_767                                ' longest ramp (steps from standstill)
  CHUNK_US      = 2_000                                 ' motion per planned command
  AHEAD_US      = 6_000                                 ' how far ahead the planner fills the queue
  SQRT2_16      = round(^^2.0 * 65536.0)                ' sqrt(2) in 16.16


VAR

  long  cog, plannerCog                                 ' cog numbers + 1 (0: not running)

  ' shared with the step generator, in this order (it reads them from PAR)
  long  head, tail, position, underrunCount, lateCount
  long  stepMask, dirMask, enMask, enOn                 ' pins, and the OUTA bits that enable the driver
  long  pulseTicks, dirSetupTicks, onTicks, offTicks
  long  queue[QUEUE_LEN * 2]

  ' the planner's
  long  target, planned, s, sMax, goingFwd, stopReq
  long  accel, maxSpeed, k, cruiseTicks, chunkTicks, aheadTicks, aheadUntil
  long  qhead, hold, ended                              ' next free entry; entries to collect before handing over; the last entry ended a move
  long  rawFlags, rawTicks                              ' a queueEntry waiting for the planner
  long  stack[48]


' ------------------------------------------------------------------------------------ starting

PUB start(stepPin, dirPin, enablePin, enableActiveLow) : okay

'' Start the step generator and the ramp planner (two cogs).  enablePin -1: no enable pin.
'' The defaults: 1,000 steps/s, 10,000 steps/s^2, enable 100 us before the first step and
'' 10 ms after the last.  Returns TRUE if both cogs started.

  stop
  head := tail := position := underrunCount := lateCount := 0
  stepMask := |< stepPin
  dirMask := |< dirPin
  enMask := enOn := 0
  if enablePin => 0
    enMask := |< enablePin
    if not enableActiveLow
      enOn := enMask
  pulseTicks := clkfreq / 400_000 #> 64                 ' 2.5 us
  dirSetupTicks := clkfreq / 200_000 #> 64              ' 5 us
  setEnableDelays(100, 10_000)
  chunkTicks := clkfreq / 1_000_000 * CHUNK_US
  aheadTicks := clkfreq / 1_000_000 * AHEAD_US
  target := planned := s := stopReq := rawFlags := qhead := hold := 0
  ended := true
  aheadUntil := cnt
  setSpeedInHz(1_000)
  setAcceleration(10_000)
  okay := (cog := cognew(@generator, @head) + 1) > 0
  if okay
    okay := (plannerCog := cognew(planner, @stack) + 1) > 0
  if not okay
    stop


PUB stop

'' Stop both cogs (the pins float).

  if plannerCog
    cogstop(plannerCog~ - 1)
  if cog
    cogstop(cog~ - 1)


PUB setEnableDelays(onUs, offUs)

'' Auto-enable: raise the enable pin onUs before the first step after a standstill, drop it
'' offUs after the last step (0: never).  Takes effect from the next standstill.

  onTicks := clkfreq / 1_000_000 * onUs #> 64
  offTicks := clkfreq / 1_000_000 * offUs
  if offUs == 0
    offTicks := POSX


' ------------------------------------------------------------------------------------ moving

PUB setSpeedInHz(stepsPerSec)

'' The top speed, whole steps/s.

  maxSpeed := stepsPerSec #> 1
  cruiseTicks := clkfreq / maxSpeed
  setRamp


PUB setAcceleration(stepsPerSec2)

'' Acceleration and deceleration, whole steps/s^2.

  accel := stepsPerSec2 #> 1 <# $3FFF_FFFF
  k := rampConstant(accel)
  setRamp


PUB moveTo(position_)

'' Go to an absolute position (steps); returns at once.  A new target while moving: the
'' planner slows down first if it has to (past the target: stop, then come back).

  target := position_


PUB move(relative)

'' Go relative to the target of the last move.

  target += relative


PUB stopMove

'' Decelerate to a standstill (the target becomes where the ramp ends).

  stopReq := true


PUB queueEntry(count, interval, fwd)

'' A raw command for the step generator: count steps (1..65,535), interval ticks apart,
'' forward if fwd is TRUE.
'' Passed through the planner, so use it while no move is planned.  The last one of a series
'' should be ended with queueLast (or the generator counts an underrun when it runs dry).

  repeat while rawFlags
  rawTicks := interval
  rawFlags := count & STEPS_MASK | (fwd & FORWARD)


PUB queueLast(count, interval, fwd)

'' queueEntry for the last command of a series: the motor stops after it.

  repeat while rawFlags
  rawTicks := interval
  rawFlags := count & STEPS_MASK | (fwd & FORWARD) | LAST


' ------------------------------------------------------------------------------------ reading

PUB getCurrentPosition

'' Where the step generator is (steps).

  return position


PUB targetPosition

  return target


PUB isRunning

'' TRUE while steps are queued, planned or still to be planned.

  return head <> tail or s or planned <> target or rawFlags


PUB underruns

'' How often the queue ran dry in the middle of a move.

  return underrunCount


PUB lateSteps

'' Steps made late because their tick had passed before the generator got to them.

  return lateCount


' ------------------------------------------------------------------------------------ the planner

PRI setRamp

  sMax := muldiv(maxSpeed, maxSpeed, accel << 1) <# MAX_S


PRI planner

' The ramp planner's cog: keep the queue about AHEAD_US ahead of the motor.

  repeat
    if qhead - tail < QUEUE_LEN and (hold or aheadUntil - cnt < aheadTicks)
      if rawFlags
        enqueue(rawFlags, rawTicks, rawFlags & STEPS_MASK)
        if rawFlags & FORWARD
          planned += rawFlags & STEPS_MASK
        else
          planned -= rawFlags & STEPS_MASK
        target := planned
        rawFlags := 0
      elseif s or planned <> target or stopReq
        planOne


PRI planOne | d, dist, n, t

' One command of the ramp: decelerate, accelerate or cruise.

  if stopReq~
    if goingFwd
      target := planned + s
    else
      target := planned - s
  d := target - planned
  if s == 0
    if d == 0
      return
    goingFwd := d > 0
    if ended                                            ' from a standstill: hand over the first
      hold := 3                                         ' three commands together
  dist := d
  if not goingFwd
    dist := -d                                          ' left to go in the direction of travel
  n := chunkTicks / stepTicks(s, s + 1) #> 1
  if dist =< s                                          ' stop within the distance left (or past it)
    n <#= s
    t := stepTicks(s, s - n)
    s -= n
  elseif s < sMax and dist - s => 2
    n := n <# (sMax - s) <# ((dist - s) >> 1)
    t := stepTicks(s, s + n)
    s += n
  else
    n := n <# (dist - s) <# STEPS_MASK
    if s == sMax
      t := cruiseTicks
    elseif s == 0                                       ' a single step from a standstill
      t := k
    else
      t := stepTicks(s, s)
  if goingFwd
    planned += n
    d := n | FORWARD
  else
    planned -= n
    d := n
  if s == 0 and planned == target
    d |= LAST
  enqueue(d, t, n)


PRI enqueue(flags, t, n) | i

  i := (qhead & (QUEUE_LEN - 1)) << 1
  queue[i] := flags
  queue[i + 1] := t
  qhead++
  if aheadUntil - cnt < 0
    aheadUntil := cnt
  aheadUntil += n * t
  ended := flags & LAST
  if hold
    hold--
  if hold == 0 or ended
    hold := 0
    head := qhead                                       ' the entries are there: hand them over


PRI stepTicks(s0, s1) : t | d, q

' Ticks between steps from ramp position s0 to s1: K / (sqrt(s0) + sqrt(s1)), the square
' roots in 8.8 fixed point.

  d := ^^(s0 << 16) + ^^(s1 << 16) #> 1
  q := k / d
  if q > $7F_FFFF
    return POSX
  t := q << 8 + (k // d) << 8 / d


PRI rampConstant(a) : c | x, j

' K = clkfreq * sqrt(2 / a) ticks: the time of the first step from a standstill.

  x := a
  j := 0
  repeat while x < $1000_0000                           ' normalise to 2^28..2^30 by factors of 4
    x <<= 2
    j++
  ' sqrt(a) = ^^x / 2^j
  c := muldiv(muldiv(clkfreq, SQRT2_16, 65_536), |< j, ^^x)


PRI muldiv(a, b, c) : q | hi, lo, carry

' a * b / c (truncated) with a 64-bit product, for a, b => 0 and c > 0; POSX if too big.

  hi := a ** b
  lo := a * b
  if (hi ^ NEGX) => (c ^ NEGX)
    return POSX
  repeat 32
    carry := hi < 0
    hi := hi << 1 | lo >> 31
    lo <<= 1
    q <<= 1
    if carry or (hi ^ NEGX) => (c ^ NEGX)
      hi -= c
      q |= 1
  if q < 0
    q := POSX


DAT

' ------------------------------------------------------------------------------------ step generator
' PAR = @head.  The registers after the code hold addresses, configuration and state.

                        org     0
generator               mov     p, par
                        mov     headAddr, p
                        add     p, #4
                        mov     tailAddr, p
                        add     p, #4
                        mov     posAddr, p
                        add     p, #4
                        mov     underAddr, p
                        add     p, #4
                        mov     lateAddr, p
                        add     p, #4
                        rdlong  stepBit, p
                        add     p, #4
                        rdlong  dirBit, p
                        add     p, #4
                        rdlong  enBit, p
                        add     p, #4
                        rdlong  enOnBits, p
                        add     p, #4
                        rdlong  pulse, p
                        add     p, #4
                        rdlong  dirSetup, p
                        add     p, #4
                        mov     onAddr, p               ' the delays are read when they are needed
                        add     p, #4
                        mov     offAddr, p
                        add     p, #4
                        mov     queueAddr, p
                        mov     enOffBits, enBit        ' the enable pin's off level
                        xor     enOffBits, enOnBits
                        mov     outa, enOffBits         ' STEP and DIR low, the driver disabled
                        or      dira, stepBit
                        or      dira, dirBit
                        or      dira, enBit
                        cmp     enBit, #0       wz      ' no enable pin: always enabled
                        muxz    enabled, #1
                        mov     lastStep, cnt

' waiting for an entry
idle                    rdlong  h, headAddr
                        cmp     h, tailCount    wz
        if_nz           jmp     #fetch
                        tjz     moving, #checkOff
                        mov     p, cnt                  ' in a move and nothing queued: is the next step overdue?
                        sub     p, lastStep
                        cmp     p, ticks        wc
        if_c            jmp     #idle
                        add     underrunN, #1           ' an underrun: the motor stops here
                        wrlong  underrunN, underAddr
                        mov     moving, #0
checkOff                tjz     enBit, #idle
                        tjz     enabled, #idle
                        rdlong  offDelay, offAddr
                        mov     p, cnt
                        sub     p, lastStep
                        cmp     p, offDelay     wc
        if_c            jmp     #idle
                        andn    outa, enBit             ' auto-disable
                        or      outa, enOffBits
                        mov     enabled, #0
                        jmp     #idle

' the next entry
fetch                   mov     p, tailCount
                        and     p, #QUEUE_LEN - 1
                        shl     p, #3
                        add     p, queueAddr
                        rdlong  cmd, p
                        add     p, #4
                        mov     oldTicks, ticks
                        rdlong  ticks, p
                        mov     steps, cmd
                        and     steps, stepsMask
                        tjnz    moving, #keepTime
                        mov     nextStep, cnt           ' from a standstill: the first step soon
                        add     nextStep, #160
                        tjnz    enabled, #direction
                        rdlong  p, onAddr               ' auto-enable, then wait the on-delay
                        andn    outa, enBit
                        or      outa, enOnBits
                        mov     enabled, #1
                        mov     nextStep, cnt
                        add     nextStep, p
                        jmp     #direction
keepTime                sub     nextStep, oldTicks      ' the last step + the new interval
                        add     nextStep, ticks
direction               test    cmd, forwardBit wc      ' C: forward
                        mov     stepDelta, #1
        if_nc           neg     stepDelta, #1
                        test    dirBit, outa    wz      ' Z: DIR low now
        if_c_and_nz     jmp     #steploop               ' forward, DIR already high
        if_nc_and_z     jmp     #steploop               ' backward, DIR already low
                        muxc    outa, dirBit            ' turn DIR, then keep the setup time
                        mov     p, cnt
                        add     p, dirSetup
                        sub     p, nextStep
                        cmps    p, #0           wc
        if_nc           add     nextStep, p

' one step a turn
steploop                mov     p, nextStep
                        sub     p, cnt
                        cmps    p, #40          wc      ' too late for WAITCNT: step now
        if_c            add     lateN, #1
        if_c            wrlong  lateN, lateAddr
        if_c            mov     nextStep, cnt
        if_c            add     nextStep, #16
                        waitcnt nextStep, ticks         ' the step's tick; next += ticks
                        or      outa, stepBit
                        mov     p, cnt
                        add     p, pulse
                        adds    pos, stepDelta
                        wrlong  pos, posAddr
                        waitcnt p, #0                   ' the pulse
                        andn    outa, stepBit
                        djnz    steps, #steploop

                        mov     lastStep, nextStep      ' the last step was at next - ticks
                        sub     lastStep, ticks
                        add     tailCount, #1
                        wrlong  tailCount, tailAddr
                        test    cmd, lastBit    wz
                        muxz    moving, #1              ' LAST: a standstill now
                        jmp     #idle

stepsMask               long    STEPS_MASK
forwardBit              long    FORWARD
lastBit                 long    LAST
tailCount                    long    0
pos                     long    0
underrunN               long    0
lateN                   long    0
moving                  long    0
enabled                 long    0
ticks                   long    0

p                       res     1
h                       res     1
headAddr                res     1
tailAddr                res     1
posAddr                 res     1
underAddr               res     1
lateAddr                res     1
onAddr                  res     1
offAddr                 res     1
queueAddr               res     1
stepBit                 res     1
dirBit                  res     1
enBit                   res     1
enOnBits                res     1
enOffBits               res     1
pulse                   res     1
dirSetup                res     1
offDelay                res     1
cmd                     res     1
steps                   res     1
oldTicks                res     1
nextStep                res     1
lastStep                res     1
stepDelta               res     1
                        fit
