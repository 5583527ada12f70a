'' =================================================================================================
''
''   File....... accel_demo.spin
''   Purpose.... AccelStepper.spin on a step/direction driver: the manual's ramp, stop, retarget
''   Updated.... spinemu project
''
'' =================================================================================================
''
'' The example of "AccelStepper: the missing manual": maximum speed 200 steps/s, acceleration
'' 50 steps/s^2, run() called continually towards a far target.  At 1, 2, 3 s the motor runs
'' at 53, 103, 153 steps/s and has made 28, 106, 235 steps; from 4 s on it cruises at 200.
'' At 7 s stop() brings it to rest (200^2 / (2 * 50) = 400 more steps); then it heads back to
'' 0 and, halfway through, is sent to 1,500 instead: it slows down, turns and goes there.
''
'' Pins: P0 step, P1 direction (high = forward), P16 goes high when the first move starts
'' (a trigger for a scope, and time zero for the manual's table).
''
''   spinemu run spin_src/accel/accel_demo.spin --trace accel.log
''   spinemu trace steps accel.log --step-dir 0,1
''
'' =================================================================================================

CON

  _clkmode      = xtal1 + pll16x
  _xinfreq      = 5_000_000

  STEP_PIN      = 0
  DIR_PIN       = 1
  TRIGGER       = 16

  FAR_AWAY      = 1_000_000


OBJ

  motor : "AccelStepper"


PUB main | t0

  motor.startStepDir(STEP_PIN, DIR_PIN)
  motor.setMaxSpeed(200)
  motor.setAcceleration(50)
  dira[TRIGGER]~~

  outa[TRIGGER]~~                                       ' time zero
  motor.moveTo(FAR_AWAY)
  t0 := cnt
  repeat while cnt - t0 < clkfreq * 7                   ' run() continually for 7 s
    motor.run

  motor.stop                                            ' decelerate to a standstill
  motor.runToPosition

  motor.moveTo(0)                                       ' back towards 0 ...
  repeat while motor.currentPosition > 600
    motor.run
  motor.moveTo(1_500)                                   ' ... no, to 1,500: turn round
  motor.runToPosition

  outa[TRIGGER]~
