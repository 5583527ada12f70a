CON
  K = 5
