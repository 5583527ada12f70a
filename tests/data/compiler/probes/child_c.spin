VAR
  word z

PUB value(p, q) | t
  t := p + q
  z := t
  return t

PRI helper
  return z
