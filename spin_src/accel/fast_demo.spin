'' =================================================================================================
''
''   File....... fast_demo.spin
''   Purpose.... FastStepper.spin: a ramp to 50,000 steps/s, auto-enable, and a starved queue
''   Updated.... spinemu project
''
'' =================================================================================================
''
'' A step/direction driver (an A4988: STEP P0, DIR P1, ~ENABLE P2, active low).
''
''   1. 10,000 steps forward: up to 50,000 steps/s at 500,000 steps/s^2 (2,500 steps and
''      0.1 s each way) and 5,000 steps at full speed.  The driver is enabled 100 us before
''      the first step and disabled 10 ms after the last.
''   2. 500 steps back at 25,000 steps/s, queued by hand with nothing after them: the queue
''      runs dry in the middle of a move, an underrun.
''   3. P16..P19 show the underruns (1), P20..P23 the late steps (0).
''
'' The step generator is PASM: the run needs an emulator with PASM cogs.
''
'' =================================================================================================

CON

  _clkmode      = xtal1 + pll16x
  _xinfreq      = 5_000_000

  STEP_PIN      = 0
  DIR_PIN       = 1
  ENABLE_PIN    = 2                                     ' ~ENABLE of an A4988
  LEDS          = 16                                    ' P16..P23


OBJ

  fast : "FastStepper"


PUB main

  if not fast.start(STEP_PIN, DIR_PIN, ENABLE_PIN, true)
    return
  fast.setSpeedInHz(50_000)
  fast.setAcceleration(500_000)

  fast.moveTo(10_000)                                   ' 1. the ramp
  repeat while fast.isRunning
  waitcnt(clkfreq / 50 + cnt)                           ' 20 ms: auto-disable after 10

  fast.queueEntry(500, clkfreq / 25_000, false)         ' 2. a move that nobody finishes
  waitcnt(clkfreq / 25 + cnt)                           ' 40 ms: 20 of steps, then dry

  dira[LEDS + 7..LEDS]~~                                ' 3. the counters
  outa[LEDS + 3..LEDS] := fast.underruns <# 15
  outa[LEDS + 7..LEDS + 4] := fast.lateSteps <# 15
  repeat                                                ' keep the cogs running
