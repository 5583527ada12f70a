'' =================================================================================================
''
''   File....... AccelStepper.spin
''   Purpose.... A stepper motor that accelerates and decelerates: the AccelStepper API in Spin
''   Updated.... spinemu project
''
'' =================================================================================================
''
'' The Arduino AccelStepper library's way of moving a motor, for the Propeller, in plain Spin
'' (no PASM): the caller's loop calls run() (or runSpeed()) as often as it can, and each call
'' makes at most one step when one is due.  Speed ramps follow D. Austin, "Generate stepper-
'' motor speed profiles in real time" (Embedded Systems Programming, Jan 2005), the method
'' AccelStepper uses: the interval before step n+1 is
''
''     c(n+1) = c(n) - 2 c(n) / (4 n + 1)          (c0 = 0.676 * sqrt(2 / acceleration) s)
''
'' where n counts steps from a standstill (n > 0 accelerating, n < 0 decelerating), never
'' shorter than cmin = 1 / maxSpeed.  Deceleration starts when the steps needed to stop,
'' speed^2 / (2 acceleration), reach the distance left.
''
'' Starting it (pins are driven by the cog that calls these methods: call start*, run and
'' the rest from one cog):
''
''   startStepDir(stepPin, dirPin)  a step/direction driver (A4988, DRV8825, TB6600...):
''                                  one high pulse on stepPin per step (8 us at 80 MHz,
''                                  never under 2 us), dirPin high = forward; DIR changes when
''                                  the direction is decided, a whole step interval before the
''                                  next pulse.
''   startCoils(firstPin)           four coil pins firstPin..firstPin+3 (an L293D or ULN2003),
''                                  full steps from the column's table %0011 %0110 %1100 %1001
''                                  (bit 0 = firstPin), forward = down the table.  The coils
''                                  are energised (holding) at once.
''   startHalfSteps(firstPin)       the same pins, half steps (%0001 %0011 %0010 %0110 %0100
''                                  %1100 %1000 %1001): one step of this object = half a step.
''
'' Units.  Positions in steps (signed longs).  Speeds in steps/s, accelerations in steps/s^2.
'' Three ways to give them:
''
''   setMaxSpeed(200)          whole numbers (the usual case);
''   setMaxSpeedF(12.5)        a Spin float literal (IEEE-754 single, e.g. 0.25 or 1.0e-2);
''   setMaxSpeedFx($0C_8000)   16.16 fixed point (value * 65536: 12.5 steps/s = $0C_8000).
''
'' The same for setAcceleration and setSpeed.  speed() reads back whole steps/s (truncated
'' toward zero, like a C cast of AccelStepper's float); speedFx() the 16.16 value.
'' Limits (at 80 MHz): the arithmetic takes speeds up to 32,767 steps/s, but a step with its
'' new interval costs run() about 0.45 ms of Spin, so steps stay on time up to about 1,500
'' steps/s (faster: FastStepper.spin, a PASM step generator); accelerations from 0.01 to 16,383
'' steps/s^2; one step every 13 s at the slowest.
''
'' Timing.  The clock is CNT.  A motor at rest that is given somewhere to go makes its first
'' step c0 after that call (AccelStepper steps at once); after that each step is due one
'' interval after the previous one was *due*, not after the loop happened to get to it, so the
'' loop's own time does not slow the motor down.  When a step is due within the "lead" (300 us
'' by default, setStepLead), run() waits for its exact clock tick with WAITCNT: steps land on
'' the tick and the step intervals in the pin trace are the intervals computed here.  The
'' price: one call of run() may block up to the lead.  The lead must exceed the time the
'' caller's loop takes to come round (a bare "repeat while motor.run" takes about 130 us at
'' 80 MHz) by about 80 us, or some steps come a few us late.  setStepLead(0) gives
'' AccelStepper's behaviour (step when the loop notices).  A loop that falls more than a whole
'' interval behind starts counting again from the late step (no burst of catch-up steps).
''
'' Example (the manual's numbers: at 1, 2, 3 s the speed is 53, 103, 153 steps/s):
''
''   OBJ  motor : "AccelStepper"
''   PUB main
''     motor.startStepDir(0, 1)
''     motor.setMaxSpeed(200)
''     motor.setAcceleration(50)
''     motor.moveTo(10_000)
''     repeat while motor.run
''
'' =================================================================================================

CON

  FIX_ONE       = 65_536                                ' 1.0 in 16.16 fixed point
  MAX_SPEED_FX  = $7FFF_0000                            ' 32,767 steps/s
  MAX_ACCEL_FX  = $3FFF_FFFF                            ' 16,383.99 steps/s^2
  MAX_TICKS     = $3FFF_FFFF                            ' longest step interval (13.4 s at 80 MHz)
  WAIT_MIN      = 2_500                                 ' ticks: a step due sooner than this is waited for in a loop (WAITCNT could miss it)
  C0_FACTOR     = round(0.676 * ^^2.0 * 65536.0)        ' 0.676 * sqrt(2) in 0.16 (Austin's first-step correction)

  MODE_NONE     = 0
  MODE_STEPDIR  = 1
  MODE_FULL     = 2
  MODE_HALF     = 3


VAR

  long  clk                                             ' clkfreq when started
  long  mode, pinA, pinB, enPin                         ' output style, step (or first coil) pin, dir pin, enable pin
  long  phase                                           ' index into the coil table
  long  curPos, targetPos                               ' steps
  long  spd, maxSpd, accel                              ' 16.16 steps/s, steps/s, steps/s^2
  long  fwd                                             ' TRUE: moving forward (DIR high)
  long  interval, lastStep, lead                        ' ticks: 0 = no stepping; when the last step was due
  long  n, c0, cn, cmin                                 ' Austin's step counter and intervals (ticks)
  long  recipA, recipShift                              ' 1 / (2 acceleration) = recipA / 2^recipShift (steps^-1 s^2)


' ------------------------------------------------------------------------------------ starting

PUB startStepDir(stepPin, dirPin)

'' Drive a step/direction driver: one pulse on stepPin per step, dirPin high = forward.

  init(MODE_STEPDIR, stepPin, dirPin)
  outa[stepPin]~
  outa[dirPin]~
  dira[stepPin]~~
  dira[dirPin]~~


PUB startCoils(firstPin)

'' Drive four coil pins firstPin..firstPin+3 in full steps (the column's table).

  init(MODE_FULL, firstPin, firstPin + 3)
  enableOutputs


PUB startHalfSteps(firstPin)

'' Drive four coil pins firstPin..firstPin+3 in half steps.

  init(MODE_HALF, firstPin, firstPin + 3)
  enableOutputs


PUB setEnablePin(pin)

'' Drive a driver's enable input (e.g. the L293D's): high now, low after disableOutputs.

  enPin := pin
  outa[pin]~~
  dira[pin]~~


PUB enableOutputs

'' Energise the coils at the current step (coil styles) and raise the enable pin if there is one.

  if mode == MODE_FULL or mode == MODE_HALF
    outa[pinB..pinA] := coils
    dira[pinB..pinA]~~
  if enPin => 0
    outa[enPin]~~


PUB disableOutputs

'' All motor pins low (coils off) and the enable pin low.  Steps made meanwhile are still counted.

  if mode == MODE_FULL or mode == MODE_HALF
    outa[pinB..pinA]~
  elseif mode == MODE_STEPDIR
    outa[pinA]~
  if enPin => 0
    outa[enPin]~


PUB setStepLead(us)

'' run()/runSpeed() wait with WAITCNT for a step due within this many microseconds (default 300).

  lead := clk / 1_000_000 * us


' ------------------------------------------------------------------------------------ setup

PUB setMaxSpeed(stepsPerSec)

'' The speed run() accelerates to, in whole steps/s (the sign is ignored).

  setMaxSpeedFx(whole(stepsPerSec))


PUB setMaxSpeedF(stepsPerSec)

'' setMaxSpeed with a float literal, e.g. setMaxSpeedF(12.5).

  setMaxSpeedFx(floatToFx(stepsPerSec))


PUB setMaxSpeedFx(stepsPerSec)

'' setMaxSpeed in 16.16 fixed point.

  stepsPerSec := ||stepsPerSec #> 1 <# MAX_SPEED_FX
  if stepsPerSec <> maxSpd
    maxSpd := stepsPerSec
    cmin := clkDiv(stepsPerSec) <# MAX_TICKS
    if n > 0                                            ' accelerating: resume the ramp where this speed is
      n := stopSteps
      computeNewSpeed


PUB setAcceleration(stepsPerSec2)

'' Acceleration and deceleration of run(), whole steps/s^2 (sign ignored, 0 ignored).

  setAccelerationFx(whole(stepsPerSec2))


PUB setAccelerationF(stepsPerSec2)

'' setAcceleration with a float literal, e.g. setAccelerationF(0.5).

  setAccelerationFx(floatToFx(stepsPerSec2))


PUB setAccelerationFx(stepsPerSec2)

'' setAcceleration in 16.16 fixed point.  Costs a square root and a few long divisions (ms).

  if stepsPerSec2 == 0
    return
  stepsPerSec2 := ||stepsPerSec2 <# MAX_ACCEL_FX
  if stepsPerSec2 <> accel
    if accel                                          ' keep the speed: n scales with 1/acceleration
      if n < 0
        n := -muldiv(-n, accel, stepsPerSec2)
      else
        n := muldiv(n, accel, stepsPerSec2)
    accel := stepsPerSec2
    setRecip(stepsPerSec2)
    c0 := firstInterval(stepsPerSec2)
    computeNewSpeed


PUB setSpeed(stepsPerSec)

'' Speed for runSpeed(), whole steps/s, negative = reverse; limited to +/- maxSpeed.

  setSpeedFx(whole(stepsPerSec))


PUB setSpeedF(stepsPerSec)

'' setSpeed with a float literal, e.g. setSpeedF(-0.25).

  setSpeedFx(floatToFx(stepsPerSec))


PUB setSpeedFx(stepsPerSec)

'' setSpeed in 16.16 fixed point.

  if stepsPerSec == spd
    return
  stepsPerSec := -maxSpd #> stepsPerSec <# maxSpd
  if stepsPerSec == 0
    interval := 0
  else
    if interval == 0                                ' from rest: the first step one interval from now
      lastStep := cnt
    interval := clkDiv(||stepsPerSec) <# MAX_TICKS
    setDirection(stepsPerSec > 0)
  spd := stepsPerSec


PUB moveTo(position)

'' Set the target (absolute steps).  run() goes there; a new target during a move retargets
'' (moving the other way: decelerate, stop, accelerate back).

  if targetPos <> position
    targetPos := position
    computeNewSpeed


PUB move(relative)

'' Set the target relative to the current position.

  moveTo(curPos + relative)


PUB stop | s

'' Stop as fast as the acceleration allows: the target becomes the point where the motor
'' comes to rest, a few steps further on in the direction it is going.  run() stops it.

  if spd
    s := stopSteps + 1
    if spd > 0
      move(s)
    else
      move(-s)


PUB setCurrentPosition(position)

'' Call the present position `position` (target too) and stand still: speed 0, at once.

  targetPos := curPos := position
  n := 0
  interval := 0
  spd := 0


' ------------------------------------------------------------------------------------ moving

PUB run

'' Make a step if one is due, then work out the next interval.  Returns TRUE while the motor
'' still has to move (speed not 0 or target not reached).  Call it as often as you can.

  if runSpeed
    computeNewSpeed
  return spd <> 0 or targetPos <> curPos


PUB runSpeed : stepped | due, wait

'' Make a step if one is due at the present speed (setSpeed, or the last run()).  Ignores the
'' target.  Returns TRUE if it stepped.

  if interval == 0
    return false
  due := lastStep + interval
  wait := due - cnt
  if wait > lead and wait =< interval                   ' not due yet
    return false
  if wait > interval or wait < -interval                ' a whole interval late (or 27 s): count from now
    due := cnt
  elseif due - cnt > WAIT_MIN
    waitcnt(due)                                        ' step on the tick it is due
  else
    repeat while due - cnt > 0                          ' too close for WAITCNT: a few us late at most
  lastStep := due
  if fwd
    curPos++
  else
    curPos--
  doStep
  return true


PUB runToPosition

'' run() until the target is reached and the motor stands still (blocks).

  repeat while run


PUB runToNewPosition(position)

'' moveTo(position), then runToPosition.

  moveTo(position)
  repeat while run


PUB runSpeedToPosition

'' runSpeed() towards the target at the speed setSpeed gave (no ramp); FALSE once there.

  if targetPos == curPos
    return false
  setDirection(targetPos > curPos)
  return runSpeed


' ------------------------------------------------------------------------------------ reading

PUB currentPosition

  return curPos


PUB targetPosition

  return targetPos


PUB distanceToGo

'' targetPosition - currentPosition (signed, steps).

  return targetPos - curPos


PUB speed

'' Present speed in whole steps/s, signed (truncated toward zero).

  return spd / FIX_ONE


PUB speedFx

'' Present speed in 16.16 fixed point, signed.

  return spd


PUB maxSpeedFx

  return maxSpd


PUB accelerationFx

  return accel


PUB isRunning

'' TRUE while the speed is not 0 or the target is not reached.

  return spd <> 0 or targetPos <> curPos


PUB stepInterval

'' Ticks between the last step and the next one (0: standing still).

  return interval


' ------------------------------------------------------------------------------------ inside

PRI init(m, a, b)

  clk := clkfreq
  mode := m
  pinA := a
  pinB := b
  enPin := -1
  phase := 0
  curPos := targetPos := 0
  spd := n := interval := 0
  fwd := false
  lead := clk / 1_000_000 * 300
  maxSpd := accel := 0
  setMaxSpeedFx(FIX_ONE)                                ' AccelStepper's defaults: 1 step/s, 1 step/s^2
  setAccelerationFx(FIX_ONE)


PRI computeNewSpeed | distanceTo, toStop

' The interval to the next step (Austin's recurrence), the speed, and when to start slowing down.

  distanceTo := targetPos - curPos
  toStop := stopSteps
  if distanceTo == 0 and toStop =< 1                    ' there, and slow enough to stop
    interval := spd := n := 0
    return
  if distanceTo > 0
    if n > 0                                            ' accelerating or cruising
      if toStop => distanceTo or not fwd
        n := -toStop                                    ' slow down
    elseif n < 0                                        ' decelerating
      if toStop < distanceTo and fwd
        n := -n                                         ' speed up again
  elseif distanceTo < 0
    if n > 0
      if toStop => -distanceTo or fwd
        n := -toStop
    elseif n < 0
      if toStop < -distanceTo and not fwd
        n := -n
  if n == 0                                             ' from a standstill
    cn := c0
    setDirection(distanceTo > 0)
  else
    cn := cn - (cn << 1) / ((n << 2) + 1) #> cmin <# MAX_TICKS
  n++
  if interval == 0                                  ' from rest: the first step c0 from now
    lastStep := cnt
  interval := cn
  spd := clkDiv(cn)
  if not fwd
    spd := -spd


PRI setDirection(f)

  fwd := f
  if mode == MODE_STEPDIR
    outa[pinB] := f                                     ' DIR high = forward


PRI doStep

  case mode
    MODE_STEPDIR:
      outa[pinA]~~                                      ' the step pulse
      outa[pinA]~
    MODE_FULL, MODE_HALF:
      if fwd
        phase++
      else
        phase--
      outa[pinB..pinA] := coils


PRI coils

  if mode == MODE_FULL
    return FullSteps[phase & 3]
  return HalfSteps[phase & 7]


PRI stopSteps : s | v2, hi, lo

' Steps needed to stop from the present speed: speed^2 / (2 acceleration), truncated.

  v2 := spd ** spd                              ' speed^2, whole steps^2/s^2
  hi := v2 ** recipA
  lo := v2 * recipA
  if recipShift > 32
    s := hi >> (recipShift - 32)
  elseif recipShift == 32
    s := hi
  else
    s := hi << (32 - recipShift) | lo >> recipShift


PRI setRecip(a) | b

' 1 / (2 a) for 16.16 a, as recipA / 2^recipShift with 2^30 =< recipA =< 2^31 - 1:
' 1 / (2 a) = 2^15 / a_fx = 2^15 * ceil(2^P / a_fx) / 2^P.  Rounded up, so that a whole
' number of steps to stop (200^2 / (2 * 50) = 400) does not come out one short.

  b := >|a                                              ' 2^(b-1) =< a < 2^b
  if a & (a - 1)
    recipA := muldiv(|<30, |<b, a) + 1                  ' 2^(30+b) / a, in (2^30, 2^31), never a whole number
    recipShift := 30 + b - 15
  else
    recipA := |<30                                      ' a power of two: exactly 2^30
    recipShift := 29 + b - 15


PRI firstInterval(a) : c | x, j

' c0 = 0.676 * sqrt(2 / a) seconds, in ticks, for 16.16 a: 0.956 clkfreq / sqrt(a).

  x := a
  j := 0
  repeat while x < $1000_0000                           ' normalise to 2^28..2^30 by factors of 4
    x <<= 2
    j++
  repeat while x => $4000_0000
    x >>= 2
    j--
  ' sqrt(a_fx) = ^^x / 2^j, so sqrt(a) = ^^x / 2^(j+8)
  c := muldiv(muldiv(clk, C0_FACTOR, FIX_ONE), |<(j + 8), ^^x) <# MAX_TICKS


PRI clkDiv(x) : y | q, r, s

' clkfreq * 65536 / x for x > 0: ticks from a 16.16 speed, or a 16.16 speed from ticks.
' Exact whole part; the fraction from the remainder with at least 15 bits of x.

  q := clk / x
  if q > $7FFF
    return POSX
  r := clk // x
  s := (>|x) - 15 #> 0
  y := q << 16 + (r >> s) << 16 / (x >> s)


PRI muldiv(a, b, c) : q | hi, lo, carry

' a * b / c (truncated) with a 64-bit product, for a, b => 0 and c > 0; POSX if too big.

  hi := a ** b
  lo := a * b
  if (hi ^ NEGX) => (c ^ NEGX)                          ' unsigned hi => c: over 32 bits
    return POSX
  repeat 32                                             ' restoring division, one bit a turn
    carry := hi < 0
    hi := hi << 1 | lo >> 31
    lo <<= 1
    q <<= 1
    if carry or (hi ^ NEGX) => (c ^ NEGX)
      hi -= c
      q |= 1
  if q < 0
    q := POSX


PRI whole(x)

' Whole steps/s (or steps/s^2) to 16.16, clamped to +/- 32,767.

  return (-32_767 #> x <# 32_767) << 16


PRI floatToFx(f) : x | e

' An IEEE-754 single (a Spin float literal) to 16.16: value = 1.m * 2^(e-127).

  e := f >> 23 & $FF
  if e == 0                                             ' zero (and denormals, far below 1/65536)
    return 0
  x := f & $7F_FFFF | $80_0000                          ' 24-bit mantissa
  e -= 134                                              ' value * 2^16 = mantissa * 2^(e - 134)
  if e > 7
    x := POSX
  elseif e => 0
    x <<= e
  elseif e > -24
    x >>= -e
  else
    x := 0
  if f < 0
    x := -x


DAT

FullSteps     byte      %0011, %0110, %1100, %1001      ' the column's full-step table (bit 0 = first pin)
HalfSteps     byte      %0001, %0011, %0010, %0110, %0100, %1100, %1000, %1001
