'' button_count.spin: counts the presses of a button on P0 (high while pressed) twice: every rising
'' edge seen by a tight loop (bounce included) in raw, and presses debounced (5 ms steady) in clean.

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000

VAR
  long raw, clean

PUB main | was, now, t, stable
  t := cnt
  was := 0
  stable := 0
  repeat while cnt - t < clkfreq                        ' one second
    now := ina[0]
    if now and not was
      raw++
    if now <> was
      stable := cnt
    elseif now and stable and cnt - stable > clkfreq / 200
      clean++
      stable := 0
    was := now
