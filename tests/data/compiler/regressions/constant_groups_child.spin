CON
  K = 8
PUB f
  return strsize(string("child"))
PUB g(a, b)
