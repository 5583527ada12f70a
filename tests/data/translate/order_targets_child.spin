'' A child object for order_targets.spin.
VAR
  long v
PUB put(x)
  v := x
  return v * 2
PUB get
  return v
