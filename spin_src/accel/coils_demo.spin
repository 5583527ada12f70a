'' =================================================================================================
''
''   File....... coils_demo.spin
''   Purpose.... The column's stepper demo with AccelStepper.spin: ramps instead of a fixed speed
''   Updated.... spinemu project
''
'' =================================================================================================
''
'' The wiring of "Stepping Out with Spin" (an L293D: enable on P0, coils on P1..P4, a 48-step
'' motor) and the same program: five times one revolution forward and one back, then free-
'' running 5 s each way.  The column steps at a fixed 5 ms from a standstill; here each move
'' ramps up to that speed (200 steps/s) at 1,600 steps/s^2 and back down, and the free run
'' is runSpeed() at 96 steps/s, the half second per revolution the column meant (its 500 / 48
'' ms rounds to 10 ms, 100 steps/s).
''
''   spinemu run spin_src/accel/coils_demo.spin --trace coils.log
''   spinemu trace steps coils.log --pins 1..4
''
'' =================================================================================================

CON

  _clkmode      = xtal1 + pll16x
  _xinfreq      = 5_000_000

  EN            = 0                                     ' L293 enable inputs (both)
  M1            = EN + 1                                ' first coil pin (P1..P4)

  STEPS_PER_REV = 48


OBJ

  motor : "AccelStepper"


PUB main | idx

  motor.startCoils(M1)                                  ' energise the coils (holding)
  motor.setEnablePin(EN)                                ' enable the L293D
  motor.setMaxSpeed(200)                                ' the column's 5 ms per step
  motor.setAcceleration(1_600)

  repeat idx from 1 to 5
    motor.runToNewPosition(STEPS_PER_REV)               ' one revolution forward
    pause(200)
    motor.runToNewPosition(0)                           ' and back
    pause(200)

  motor.setSpeed(STEPS_PER_REV * 2)                     ' free run: 1/2 s per revolution
  runFor(5_000)
  motor.setSpeed(-STEPS_PER_REV * 2)
  runFor(5_000)

  motor.disableOutputs                                  ' coils off, driver disabled


PRI runFor(ms) | t0

  t0 := cnt
  repeat while cnt - t0 < clkfreq / 1000 * ms
    motor.runSpeed


PRI pause(ms)

  waitcnt(clkfreq / 1000 * ms + cnt)
