'' Waits for pin 3 (nobody drives it) to read high, then drives pin 0.
PUB main
  waitpeq(|< 3, |< 3, 0)
  dira[0]~~
