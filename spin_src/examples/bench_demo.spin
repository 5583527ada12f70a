'' bench_demo.spin: a button, an LED, a servo and a 2 x 16 LCD around one program.
''
'' Every press of the button on P0 toggles the LED on P16, moves the servo on
'' P17 to the next of three positions (1.0, 1.5, 2.0 ms pulses) and shows the
'' count on an HD44780 LCD in 4-bit mode (RS P8, E P9, D4..D7 on P10..P13).
'' The servo gets a pulse every 20 ms; the button is read once per pulse,
'' which also rides over its contact bounce.
''
''   spinemu run spin_src/examples/bench_demo.spin --bench spin_src/examples/bench_demo.toml --seconds 1

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

  BUTTON  = 0
  LCD_RS  = 8
  LCD_E   = 9
  LCD_D4  = 10                                          ' D4..D7 on P10..P13
  LED     = 16
  SERVO   = 17

VAR
  long presses, pulse_us

PUB main | t, was, now
  dira[LED]~~
  dira[SERVO]~~
  lcd_init
  pulse_us := 1000
  show
  was := 0
  t := cnt
  repeat
    outa[SERVO]~~                                       ' one servo pulse every 20 ms
    waitcnt(t + pulse_us * (clkfreq / 1_000_000))
    outa[SERVO]~
    now := ina[BUTTON]
    if now and not was
      presses++
      !outa[LED]
      pulse_us := 1000 + (presses // 3) * 500
      show
    was := now
    waitcnt(t += clkfreq / 50)

PRI show
  command($80)                                          ' line 1, column 0
  text(string("Presses: "))
  dec(presses)
  command($C0)                                          ' line 2, column 0
  text(string("Servo: "))
  dec(pulse_us)
  text(string(" us"))

PRI lcd_init
  dira[LCD_RS]~~
  dira[LCD_E]~~
  dira[LCD_D4 + 3..LCD_D4]~~
  pause_us(20_000)                                      ' power-up
  nibble(0, $3)                                         ' reset by instruction: 8-bit mode, three times
  pause_us(5_000)
  nibble(0, $3)
  pause_us(200)
  nibble(0, $3)
  pause_us(200)
  nibble(0, $2)                                         ' now 4-bit mode
  pause_us(100)
  command($28)                                          ' 2 lines, 5 x 8 dots
  command($0C)                                          ' display on, no cursor
  command($06)                                          ' move right after each character
  command($01)                                          ' clear
  pause_us(2_000)

PRI command(c)
  nibble(0, c >> 4)
  nibble(0, c)
  pause_us(50)

PRI char(c)
  nibble(1, c >> 4)
  nibble(1, c)
  pause_us(50)

PRI nibble(rs, n)
  outa[LCD_RS] := rs
  outa[LCD_D4 + 3..LCD_D4] := n
  outa[LCD_E]~~
  outa[LCD_E]~

PRI text(s)
  repeat strsize(s)
    char(byte[s++])

PRI dec(v) | d
  d := 1_000_000
  repeat while d > 1 and v < d
    d /= 10
  repeat while d
    char("0" + v / d // 10)
    d /= 10

PRI pause_us(us)
  waitcnt(cnt + us * (clkfreq / 1_000_000) + 400)
