OBJ
  s : "child_a"

VAR
  byte w[3]

PUB work
  s.start(w[0])

PUB value
  return s.value + w[1]
